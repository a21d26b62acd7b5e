// Part of the rasteriser (raster.cpp, which alone includes it): anti-aliased and thick lines,
// drawn as a band of the line's width around it, column by column.
#pragma once

#include <cmath>
#include <cstdint>

#include "render/raster.hpp"
#include "render/raster_plot.hpp"

namespace noneuclid::render {
namespace {

// The band of the given width around the line, per column: exact coverage (anti-aliased) or
// the pixels whose centre it covers (thick aliased).
// Per column of a band, in integers with 32 fractional bits of a pixel: the band's centre v at
// the first column (stepped by dv_col per column) and its minor-axis extent h = width * length /
// major, set up once per line.
struct Band {
    Columns col;
    int64_t h, v, dv_col;
    Band(int64_t u0, int64_t v0, int64_t u1, int64_t v1, int32_t width) : col(columns<int64_t>(u0, u1)) {
        const double du = static_cast<double>(u1 - u0), dv = static_cast<double>(v1 - v0);
        constexpr double kQ = 4294967296.0;
        const double slope = dv / du;
        h = static_cast<int64_t>((width / double(kSub)) * std::sqrt(du * du + dv * dv) / std::fabs(du) * kQ);
        const double uc0 = static_cast<double>(col.first * kSub + kSub / 2);
        v = static_cast<int64_t>((static_cast<double>(v0) + (uc0 - static_cast<double>(u0)) * slope) / kSub * kQ);
        dv_col = static_cast<int64_t>(slope * static_cast<double>(col.step) * kQ);
    }
};

// A one-pixel anti-aliased line into a canvas it lies wholly on (and, in a row band, wholly in
// the band), the canvas blended in integers (direct()): the same band and the same coverages as
// wide_line, pixel for pixel, with no check per pixel. The band is at most sqrt 2 px across, so
// each column writes its first row, the next, and a third only where the band reaches it; the
// coverages are the band's overlaps with those rows, 255 in all, as wide_line computes them.
// A line this long (50 px) touches a new cache line in most columns: the pixels kAhead columns
// on are fetched while this column is blended. False (nothing written) where it does not apply.
template <int Bpp>
bool aa_direct(Plotter<CanvasSink<Bpp>>& p, const Band& s) {
    if (!p.sink.direct() || s.col.count == 0) return false;
    const CanvasSink<Bpp> sink = p.sink;  // in a local: a pixel store (bytes) may alias p.sink
    constexpr int64_t one = int64_t{1} << 32;
    const int64_t last = s.col.first + (s.col.count - 1) * s.col.step, v_end = s.v + (s.col.count - 1) * s.dv_col;
    const int64_t umin = s.col.first < last ? s.col.first : last, umax = s.col.first < last ? last : s.col.first;
    const int64_t vlo = ((s.v < v_end ? s.v : v_end) - s.h / 2) >> 32, vhi = ((s.v < v_end ? v_end : s.v) + s.h / 2) >> 32;
    // The columns' axis and the rows' on the canvas and in the band.
    const int64_t along0 = p.swap ? p.row0 : 0, along = p.swap ? p.row1 : sink.width();
    const int64_t across0 = p.swap ? 0 : p.row0, across = p.swap ? sink.width() : p.row1;
    if (umin < along0 || umax >= along || vlo < across0 || vhi >= across) return false;
    const std::ptrdiff_t major = (p.swap ? sink.stride : Bpp) * s.col.step, minor = p.swap ? Bpp : sink.stride;
    uint8_t* at = sink.base + (p.swap ? s.col.first * sink.stride : s.col.first * Bpp);
    auto put = [&sink](uint8_t* px, int64_t cover) {  // cover in 1/2^32 px
        const uint32_t a = static_cast<uint32_t>((cover * 255 + (one >> 1)) >> 32);
        if (a >= 255) sink.store(px - sink.base);
        else if (a > 0) sink.blend_at(px, a);
    };
    constexpr int64_t kAhead = 12;
    int64_t v = s.v;
    for (int64_t k = 0; k < s.col.count; ++k, at += major, v += s.dv_col) {
        if (k + kAhead < s.col.count) {
            const int64_t ra = (v + kAhead * s.dv_col - s.h / 2) >> 32;  // its first row, and the next
            uint8_t* ahead = at + kAhead * major + ra * minor;
            __builtin_prefetch(ahead, 1);
            if (ra < vhi) __builtin_prefetch(ahead + minor, 1);
        }
        const int64_t lo = v - s.h / 2, hi = v + s.h / 2;
        const int64_t r = lo >> 32, edge = (r + 1) << 32;
        uint8_t* px = at + r * minor;
        if (hi <= edge) {  // one row
            put(px, hi - lo);
            continue;
        }
        put(px, edge - lo);
        if (hi <= edge + one) {
            put(px + minor, hi - edge);
        } else {
            put(px + minor, one);
            put(px + 2 * minor, hi - edge - one);
        }
    }
    return true;
}

template <class P>
void wide_line(P& p, int64_t u0, int64_t v0, int64_t u1, int64_t v1, int32_t width, bool aa, bool cut) {
    const Band band(u0, v0, u1, v1, width);
    if constexpr (requires { p.sink.base; }) {
        if (aa && width == kSub && !cut && aa_direct(p, band)) return;
    }
    const Columns col = band.col;
    if (col.count == 0) return;
    // Rows across the band are checked one by one below: [rlo, rhi) are the rows (or columns)
    // that may be written across it.
    const int64_t rlo = p.swap ? 0 : p.row0, rhi = p.swap ? p.sink.width() : p.row1;
    const int64_t h = band.h, dv_col = band.dv_col;
    int64_t v = band.v;
    constexpr int64_t one = int64_t{1} << 32;
    // In a row band, only the columns that can reach it: y major, the columns are rows; x major,
    // the columns whose centre v is within the band widened by h / 2 and a pixel (v moves by
    // dv_col per column, exactly: v + k dv_col is what k additions give). A column more than
    // needed costs nothing but time: the rows are checked one by one.
    int64_t kmin = 0, kmax = col.count - 1;
    if (cut) {
        if (p.swap) {
            if (col.step > 0)
                kmin = p.row0 - col.first, kmax = p.row1 - 1 - col.first;
            else
                kmin = col.first - p.row1 + 1, kmax = col.first - p.row0;
        } else {
            const int64_t L = (p.row0 - 1) * one - h / 2, H = (p.row1 + 1) * one + h / 2;  // L < v < H
            if (dv_col > 0)
                kmin = floor_div(L - v, dv_col), kmax = ceil_div(H - v, dv_col);
            else if (dv_col < 0)
                kmin = floor_div(v - H, -dv_col), kmax = ceil_div(v - L, -dv_col);
        }
        if (kmin < 0) kmin = 0;
        if (kmax > col.count - 1) kmax = col.count - 1;
    }
    int64_t u = col.first + kmin * col.step;
    v += kmin * dv_col;
    for (int64_t k = kmin; k <= kmax; ++k, u += col.step, v += dv_col) {
        const int64_t lo = v - h / 2, hi = v + h / 2;
        int64_t r = lo >> 32;
        if (aa) {
            if (r < rlo) r = rlo;
            for (; r < rhi && (r << 32) < hi; ++r) {
                const int64_t top = (r << 32) > lo ? (r << 32) : lo, bottom = ((r + 1) << 32) < hi ? ((r + 1) << 32) : hi;
                const int alpha = static_cast<int>(((bottom - top) * 255 + (one >> 1)) >> 32);
                if (alpha > 0) p.blend(u, r, alpha);
            }
        } else {  // rows whose centre r + 1/2 lies in [lo, hi)
            const int64_t first = (lo - (one >> 1) + one - 1) >> 32, last = ((hi - (one >> 1) + one - 1) >> 32) - 1;
            for (r = first > rlo ? first : rlo; r <= last && r < rhi; ++r) p.opaque(u, r);
        }
    }
}

// A thick aliased line as its capsule: the pixels whose centre lies within width / 2 of the
// segment (not only of its line between the end columns), so that the segments of a polyline
// overlap at every join, however sharp the turn, with no notch. Per column, the capsule (convex)
// meets the column's centre line in one interval: the union of the strip about the line within
// the segment's perpendicular slab and the two end discs. In double, in 1/256 px.
template <class P>
void capsule_line(P& p, int64_t u0, int64_t v0, int64_t u1, int64_t v1, int32_t width) {
    const double r = width / 2.0, a = static_cast<double>(u0), b = static_cast<double>(v0);
    const double du = static_cast<double>(u1 - u0), dv = static_cast<double>(v1 - v0);
    const double L2 = du * du + dv * dv, half = r * std::sqrt(L2) / std::fabs(du);  // du != 0: u is the major axis
    const int64_t lo_u = (u0 < u1 ? u0 : u1) - width, hi_u = (u0 < u1 ? u1 : u0) + width;
    int64_t first = ceil_sub<int64_t>(lo_u - kSub / 2), last = floor_sub<int64_t>(hi_u - kSub / 2);
    const int64_t along = p.swap ? p.row1 : p.sink.width(), along0 = p.swap ? p.row0 : 0;  // the columns on the canvas
    if (first < along0) first = along0;
    if (last > along - 1) last = along - 1;
    const int64_t rlo = p.swap ? 0 : p.row0, rhi = p.swap ? p.sink.width() : p.row1;
    for (int64_t u = first; u <= last; ++u) {
        const double uc = static_cast<double>(u * kSub + kSub / 2), x = uc - a;
        double lo = INFINITY, hi = -INFINITY;
        auto disc = [&](double eu, double ev) {
            const double d = uc - eu;
            if (std::fabs(d) >= r) return;
            const double s = std::sqrt(r * r - d * d);
            lo = std::fmin(lo, ev - s), hi = std::fmax(hi, ev + s);
        };
        disc(a, b), disc(static_cast<double>(u1), static_cast<double>(v1));
        // The strip within width / 2 of the line, cut to the slab 0 <= (P - A).d <= L^2.
        const double vline = b + x * dv / du;
        double slo = vline - half, shi = vline + half;
        if (dv != 0) {
            const double e0 = b - du * x / dv, e1 = b + (L2 - du * x) / dv;
            slo = std::fmax(slo, std::fmin(e0, e1)), shi = std::fmin(shi, std::fmax(e0, e1));
        } else if (x * du < 0 || x * du > L2) {
            shi = -INFINITY;
        }
        if (slo < shi) lo = std::fmin(lo, slo), hi = std::fmax(hi, shi);
        if (!(lo < hi)) continue;
        // Rows whose centre r + 1/2 lies in [lo, hi).
        int64_t row = static_cast<int64_t>(std::ceil((lo - kSub / 2) / kSub));
        const int64_t end = static_cast<int64_t>(std::ceil((hi - kSub / 2) / kSub));  // exclusive
        for (row = row > rlo ? row : rlo; row < end && row < rhi; ++row) p.opaque(u, row);
    }
}

}  // namespace
}  // namespace noneuclid::render
