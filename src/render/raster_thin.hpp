// Part of the rasteriser (raster.cpp, which alone includes it): thin aliased lines, one pixel
// per column along the major axis (Bresenham with sub-pixel end points): thin() in 64 bits for
// any line, thin32() in 32 bits for the common case, thin_inside() for a line whose ends are
// both on the canvas.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "render/raster.hpp"
#include "render/raster_plot.hpp"

namespace noneuclid::render {
namespace {

template <class P>
void thin(P& p, int64_t u0, int64_t v0, int64_t u1, int64_t v1, bool cut) {
    const int64_t du = u1 - u0, dv = v1 - v0;
    Columns col = columns<int64_t>(u0, u1);
    // Only the columns on the canvas (and in the row band, when the major axis is y): along the
    // major axis the range is cut once, here; across it each pixel is checked (a single
    // unsigned compare).
    const int64_t umin = p.swap ? p.row0 : 0, umax = p.swap ? p.row1 : p.sink.width();
    const int64_t vmax = p.swap ? p.sink.width() : p.sink.height();
    if (!cut_columns<int64_t>(col, umin, umax)) return;
    // v at a column centre uc, in px: (v0 du + (uc - u0) dv) / (256 du) = N / A, A > 0; at the
    // k-th column from the first, (N + k step) / A.
    const int64_t sgn = du > 0 ? 1 : -1;
    const int64_t A = kSub * du * sgn;
    const int64_t uc = col.first * kSub + kSub / 2;
    int64_t N = sgn * (v0 * du + (uc - u0) * dv);
    const int64_t step = kSub * dv * col.step * sgn;  // |step| <= A
    if (cut && !p.swap) {
        // x major, rows [row0, row1): the columns k with row0 A <= N + k step < row1 A, solved
        // exactly in integers (the row is monotonic along the line), then the line is entered
        // at the first of them with the same row and remainder the full walk would have there.
        const int64_t lo = p.row0 * A, hi = p.row1 * A;
        int64_t kmin = 0, kmax = col.count - 1;
        if (step > 0) {
            kmin = ceil_div(lo - N, step), kmax = ceil_div(hi - N, step) - 1;
        } else if (step < 0) {
            kmin = floor_div(N - hi, -step) + 1, kmax = floor_div(N - lo, -step);
        } else if (N < lo || N >= hi) {
            return;
        }
        if (kmin < 0) kmin = 0;
        if (kmax > col.count - 1) kmax = col.count - 1;
        if (kmin > kmax) return;
        col.first += kmin * col.step;
        col.count = kmax - kmin + 1;
        N += kmin * step;
    }
    int64_t row = floor_div(N, A), rem = N - row * A;  // 0 <= rem < A
    int64_t u = col.first;
    p.opaque(u, row);  // the first pixel goes through the shared-point check
    if constexpr (requires { p.sink.base; }) {
        // Into a canvas: step a byte offset along the major axis and, on a carry, across it.
        using Sink = std::remove_cvref_t<decltype(p.sink)>;
        constexpr int bpp = Sink::bytes;
        const std::ptrdiff_t major = (p.swap ? p.sink.stride : bpp) * col.step;
        const std::ptrdiff_t minor = p.swap ? bpp : p.sink.stride;
        std::ptrdiff_t off = p.swap ? u * p.sink.stride + row * bpp : row * p.sink.stride + u * bpp;
        // Branch-free carry: the minor axis moves one way only along a line.
        if (step >= 0) {
            for (int64_t k = 1; k < col.count; ++k) {
                off += major;
                rem += step;
                const int64_t carry = rem >= A;
                rem -= A & -carry;
                row += carry;
                off += minor & -carry;
                if (static_cast<uint64_t>(row) < static_cast<uint64_t>(vmax)) p.sink.store(off);
            }
        } else {
            for (int64_t k = 1; k < col.count; ++k) {
                off += major;
                rem += step;
                const int64_t borrow = rem < 0;
                rem += A & -borrow;
                row -= borrow;
                off -= minor & -borrow;
                if (static_cast<uint64_t>(row) < static_cast<uint64_t>(vmax)) p.sink.store(off);
            }
        }
        u += (col.count - 1) * col.step;
    } else {
        for (int64_t k = 1; k < col.count; ++k) {
            u += col.step;
            rem += step;
            if (rem >= A) rem -= A, ++row;
            else if (rem < 0) rem += A, --row;
            if (static_cast<uint64_t>(row) < static_cast<uint64_t>(vmax)) p.raw(u, row);
        }
    }
    p.note_last(u, row);
}

// thin() into a canvas in 32-bit arithmetic: the same pixels, without 64-bit error terms, a
// 64-bit division per line or 64-bit compares (each a pair of instructions or a library call
// on 32-bit ARM). For end points within +-2^21 sub-pixels (8192 px) of the origin, which
// segment() checks (a line clipped to a canvas of up to 8188 px always is): then |du|, |dv| <=
// 2^22, A = 256 |du| <= 2^30, |step| <= A, and the error term stays in [0, A) after each step,
// so e + inc < 2A <= 2^31 never overflows; the column centres lie within 2^21 + 128.
// Inside: both end points are on the canvas. Then the columns need no cut (their centres lie
// between the end points), and no pixel needs a check: the line's point at every column centre
// lies between the end points, so its row is on the canvas too.
// Otherwise the columns are cut to the canvas along the major axis and each pixel is checked
// across it. Band (a line reaching past the plotter's row band): the band's rows instead of the
// canvas's. A y-major line's columns are then cut to them; an x-major line walks every column
// on the canvas, each pixel's row checked, where thin() finds the band's columns by two
// divisions (segment() sends only short x-major lines here).
template <bool Inside, int Bpp, bool Band = false>
void thin32(Plotter<CanvasSink<Bpp>>& p, int32_t u0, int32_t v0, int32_t u1, int32_t v1) {
    const CanvasSink<Bpp>& sink = p.sink;
    const int32_t du = u1 - u0, dv = v1 - v0;
    ColumnsOf<int32_t> col = columns<int32_t>(u0, u1);
    const int32_t vmin = Band && !p.swap ? p.row0 : 0, vmax = p.swap ? sink.width() : (Band ? p.row1 : sink.height());
    if constexpr (Inside) {
        if (col.count == 0) return;
    } else {
        if (!cut_columns<int32_t>(col, Band && p.swap ? p.row0 : 0,
                                  p.swap ? (Band ? p.row1 : sink.height()) : sink.width()))
            return;
    }
    const int32_t adu = du > 0 ? du : -du, sdv = du > 0 ? dv : -dv;  // |du|, sgn dv
    const int32_t A = kSub * adu;
    const int32_t uc = col.first * kSub + kSub / 2;
    // thin()'s N = v0 |du| + (uc - u0) sgn dv, as q A + M with v0 = 256 q + r (0 <= r < 256):
    // row = q + floor(M / A). M is mostly within a few A (uc lies within a column of u0, or a
    // few px from it where the canvas cut moved the first column), and its division a 32-bit
    // one; where a cut moved it further (a band's edge, far off the canvas) |M| < 2^44, and
    // the division takes 64 bits.
    const int32_t q = floor_sub<int32_t>(v0), r = v0 - q * kSub;
    const int64_t M = int64_t{r} * adu + int64_t{uc - u0} * sdv;
    int32_t row, rem;
    if (Inside || (M >= INT32_MIN && M <= INT32_MAX)) {  // Inside: |M| < 2^30 (|uc - u0| < 256)
        const int32_t m = static_cast<int32_t>(M);
        int32_t f = m / A;
        if (m - f * A < 0) --f;
        row = q + f, rem = m - f * A;
    } else {
        const int64_t f = floor_div(M, A);
        row = q + static_cast<int32_t>(f), rem = static_cast<int32_t>(M - f * A);
    }
    const int32_t step = kSub * sdv * col.step;  // |step| <= A
    const int32_t u = col.first;
    // The first pixel goes through the shared-point check (and, off the Inside case, the
    // canvas check).
    if constexpr (Inside) {
        const int32_t x = p.swap ? row : u, y = p.swap ? u : row;
        if (p.fresh(x, y)) {
            sink.opaque(x, y);
            if (p.first_x == p.kNone) p.first_x = x, p.first_y = y;
        }
    } else {
        p.opaque(u, row);
    }
    // Step a byte offset along the major axis and, on a carry, across it. Going down the minor
    // axis is going up with the error term mirrored (e = A - 1 - rem).
    const std::ptrdiff_t major = (p.swap ? sink.stride : Bpp) * col.step;
    std::ptrdiff_t minor = p.swap ? Bpp : sink.stride;
    std::ptrdiff_t off = p.swap ? u * sink.stride + row * Bpp : row * sink.stride + u * Bpp;
    int32_t e = rem, inc = step, drow = 1;
    if (step < 0) e = A - 1 - rem, inc = -step, minor = -minor, drow = -1;
    // The sink's base and word in locals: a pixel store may alias anything, the sink included,
    // and would otherwise make the compiler reload them for every pixel.
    const CanvasSink<Bpp> local = sink;
    for (int32_t k = col.count - 1; k > 0; --k) {
        off += major;
        e += inc;
        if (e >= A) e -= A, off += minor, row += drow;
        if (Inside || static_cast<uint32_t>(row - vmin) < static_cast<uint32_t>(vmax - vmin)) local.store(off);
    }
    const int32_t u_last = u + (col.count - 1) * col.step;
    if constexpr (Inside) {
        p.last_x = p.swap ? row : u_last, p.last_y = p.swap ? u_last : row;
    } else {
        p.note_last(u_last, row);
    }
}

// A thin line with both end points a and b on a canvas of at most 8192 px (within thin32's
// bound): all in 32 bits, no clipping.
constexpr int32_t kMaxSide32 = 8192;
template <int Bpp>
void thin_inside(Plotter<CanvasSink<Bpp>>& p, SubPoint a, SubPoint b) {
    const int32_t adx = a.x > b.x ? a.x - b.x : b.x - a.x, ady = a.y > b.y ? a.y - b.y : b.y - a.y;
    const bool x_major = adx >= ady;
    p.swap = !x_major;
    const int32_t u0 = x_major ? a.x : a.y, v0 = x_major ? a.y : a.x, u1 = x_major ? b.x : b.y, v1 = x_major ? b.y : b.x;
    if (u0 == u1) return;  // a point: the caller plots end points
    thin32<true>(p, u0, v0, u1, v1);
}

}  // namespace
}  // namespace noneuclid::render
