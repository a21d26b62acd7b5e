#include "render/raster.hpp"

#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <type_traits>

namespace noneuclid::render {
namespace {

static_assert(std::endian::native == std::endian::little, "pixel words are stored little-endian");

// Where pixels go: into a canvas (one instantiation per pixel size, writing whole words, with
// integer blends for the two fast formats), or to a visitor (tests, counting).
template <int Bpp>
struct CanvasSink {
    static constexpr int bytes = Bpp;
    const Canvas& c;
    Rgb color;
    uint32_t word;
    uint8_t* base;
    std::ptrdiff_t stride;
    bool fast565, fast8888;
    CanvasSink(const Canvas& canvas, Rgb col)
        : c(canvas), color(col), word(canvas.format().pack(col)), base(canvas.row(0)), stride(canvas.stride()),
          fast565(canvas.format().is_rgb565()), fast8888(canvas.format().is_xrgb8888()) {}
    int width() const { return c.width(); }
    int height() const { return c.height(); }
    uint8_t* at(int x, int y) const { return base + y * stride + x * Bpp; }
    void opaque(int x, int y) const { store(y * stride + x * Bpp); }
    void store(std::ptrdiff_t offset) const {
        uint8_t* p = base + offset;
        if constexpr (Bpp == 4) {
            std::memcpy(p, &word, 4);
        } else if constexpr (Bpp == 2) {
            const uint16_t w = static_cast<uint16_t>(word);
            std::memcpy(p, &w, 2);
        } else {
            p[0] = static_cast<uint8_t>(word), p[1] = static_cast<uint8_t>(word >> 8), p[2] = static_cast<uint8_t>(word >> 16);
        }
    }
    // dst + (src - dst) * a / 255 per channel; a / 255 as (a * 257 + 128) >> 16 over 8-bit values.
    static uint32_t mix8(uint32_t s, uint32_t d, uint32_t a) {
        const int32_t diff = static_cast<int32_t>(s) - static_cast<int32_t>(d);
        return static_cast<uint32_t>(static_cast<int32_t>(d) + ((diff * static_cast<int32_t>(a) * 257 + (diff >= 0 ? 32768 : -32768)) >> 16));
    }
    void blend(int x, int y, int alpha) const {
        if (alpha >= 255) return opaque(x, y);
        if constexpr (Bpp == 4) {
            if (fast8888) {
                uint8_t* p = at(x, y);
                uint32_t d;
                std::memcpy(&d, p, 4);
                const uint32_t a = static_cast<uint32_t>(alpha);
                const uint32_t r = mix8(color.r, (d >> 16) & 0xFF, a), g = mix8(color.g, (d >> 8) & 0xFF, a),
                               b = mix8(color.b, d & 0xFF, a);
                const uint32_t out = (d & 0xFF000000u) | r << 16 | g << 8 | b;
                std::memcpy(p, &out, 4);
                return;
            }
        }
        c.blend(x, y, color, alpha);
    }
};
struct VisitSink {
    int w, h;
    PixelVisitor visit;
    void* context;
    int width() const { return w; }
    int height() const { return h; }
    void opaque(int x, int y) const { visit(x, y, 255, context); }
    void blend(int x, int y, int alpha) const { visit(x, y, alpha, context); }
};

// Sends pixels to the sink, skipping a pixel equal to the one just written (shared polyline
// points) and anything outside the canvas or the row band [row0, row1).
template <class Sink>
struct Plotter {
    const Sink& sink;
    int row0, row1;     // the rows written: [row0, row1), within the canvas
    bool banded;        // [row0, row1) is less than the whole canvas
    bool swap = false;  // (u, v) are (y, x)
    int last_x = -1 << 30, last_y = -1 << 30;

    Plotter(const Sink& s, RowRange rows)
        : sink(s), row0(rows.y0 > 0 ? rows.y0 : 0), row1(rows.y1 < s.height() ? rows.y1 : s.height()),
          banded(row0 > 0 || row1 < s.height()) {}

    template <class I>
    bool inside(I x, I y) const { return x >= 0 && y >= row0 && x < sink.width() && y < row1; }
    template <class I>
    void opaque(I u, I v) {
        const I x = swap ? v : u, y = swap ? u : v;
        if (!inside(x, y) || (x == last_x && y == last_y)) return;
        sink.opaque(static_cast<int>(x), static_cast<int>(y));
        last_x = static_cast<int>(x), last_y = static_cast<int>(y);
    }
    void blend(int64_t u, int64_t v, int alpha) {
        const int64_t x = swap ? v : u, y = swap ? u : v;
        if (!inside(x, y)) return;
        sink.blend(static_cast<int>(x), static_cast<int>(y), alpha);
    }
    // A pixel known to be on the canvas, with no shared-point check (the loop's inner pixels).
    void raw(int64_t u, int64_t v) const {
        sink.opaque(static_cast<int>(swap ? v : u), static_cast<int>(swap ? u : v));
    }
    // Remember the segment's last pixel for the next segment's shared-point check.
    template <class I>
    void note_last(I u, I v) {
        const I x = swap ? v : u, y = swap ? u : v;
        if (inside(x, y)) last_x = static_cast<int>(x), last_y = static_cast<int>(y);
    }
};

int64_t floor_div(int64_t a, int64_t b) {  // b > 0
    const int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}
int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }  // b > 0

// Liang-Barsky: clips the segment to [lo, hi] x [lo_y, hi_y]; false if nothing is left.
bool clip(double& x0, double& y0, double& x1, double& y1, double xmin, double ymin, double xmax, double ymax) {
    const double dx = x1 - x0, dy = y1 - y0;
    double t0 = 0, t1 = 1;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {x0 - xmin, xmax - x0, y0 - ymin, ymax - y0};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return false;
            continue;
        }
        const double r = q[i] / p[i];
        if (p[i] < 0) {
            if (r > t1) return false;
            if (r > t0) t0 = r;
        } else {
            if (r < t0) return false;
            if (r < t1) t1 = r;
        }
    }
    const double ax = x0, ay = y0;
    if (t1 < 1) x1 = ax + t1 * dx, y1 = ay + t1 * dy;
    if (t0 > 0) x0 = ax + t0 * dx, y0 = ay + t0 * dy;
    return true;
}

// The major-axis columns whose centres lie in [u0, u1) (or (u1, u0] going down), as a first
// index, a count and a step.
template <class I>
struct ColumnsOf {
    I first, count, step;
};
using Columns = ColumnsOf<int64_t>;
// floor(v / 256) and ceil(v / 256) by arithmetic shifts (C++20: >> of a negative value rounds
// toward negative infinity).
template <class I>
I floor_sub(I v) { return v >> kSubBits; }
template <class I>
I ceil_sub(I v) { return -((-v) >> kSubBits); }
template <class I>
ColumnsOf<I> columns(I u0, I u1) {
    if (u1 > u0) {
        const I a = ceil_sub<I>(u0 - kSub / 2), b = ceil_sub<I>(u1 - kSub / 2) - 1;
        return {a, b >= a ? b - a + 1 : 0, 1};
    }
    const I a = floor_sub<I>(u0 - kSub / 2), b = floor_sub<I>(u1 - kSub / 2) + 1;
    return {a, a >= b ? a - b + 1 : 0, -1};
}
// Cuts the columns to [umin, umax); false if none is left.
template <class I>
bool cut_columns(ColumnsOf<I>& col, I umin, I umax) {
    if (col.count == 0) return false;
    I last = col.first + (col.count - 1) * col.step;
    if (col.step > 0) {
        if (col.first < umin) col.first = umin;
        if (last > umax - 1) last = umax - 1;
        col.count = last - col.first + 1;
    } else {
        if (col.first > umax - 1) col.first = umax - 1;
        if (last < umin) last = umin;
        col.count = col.first - last + 1;
    }
    return col.count > 0;
}

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
        if (x != p.last_x || y != p.last_y) sink.opaque(x, y);
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

// The band of the given width around the line, per column: exact coverage (anti-aliased) or
// the pixels whose centre it covers (thick aliased).
template <class P>
void band(P& p, int64_t u0, int64_t v0, int64_t u1, int64_t v1, int32_t width, bool aa, bool cut) {
    const double du = static_cast<double>(u1 - u0), dv = static_cast<double>(v1 - v0);
    const Columns col = columns<int64_t>(u0, u1);
    if (col.count == 0) return;
    // Rows across the band are checked one by one below: [rlo, rhi) are the rows (or columns)
    // that may be written across it.
    const int64_t rlo = p.swap ? 0 : p.row0, rhi = p.swap ? p.sink.width() : p.row1;
    // Per column, in integers with 32 fractional bits of a pixel: the band's centre v (stepped by
    // the slope) and its minor-axis extent h = width * length / major (set up once per line).
    constexpr double kQ = 4294967296.0;
    const double slope = dv / du;
    const int64_t h = static_cast<int64_t>((width / double(kSub)) * std::sqrt(du * du + dv * dv) / std::fabs(du) * kQ);
    const double uc0 = static_cast<double>(col.first * kSub + kSub / 2);
    int64_t v = static_cast<int64_t>((static_cast<double>(v0) + (uc0 - static_cast<double>(u0)) * slope) / kSub * kQ);
    const int64_t dv_col = static_cast<int64_t>(slope * static_cast<double>(col.step) * kQ);
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

// A clipped coordinate rounded to nearest, ties away from zero: std::llround. Where the clip box
// lies within +-2^30 (`small`), the same as std::round (one instruction on ARMv8 and x86-64
// with SSE4.1) and a 32-bit conversion, instead of llround's library call on 32-bit targets.
int64_t round_clipped(double x, bool small) {
    return small ? static_cast<int64_t>(static_cast<int32_t>(std::round(x))) : static_cast<int64_t>(std::llround(x));
}

// Both end points on a canvas of Wi x Hi sub-pixels (a negative coordinate compares as huge).
bool both_on(SubPoint a, SubPoint b, uint32_t Wi, uint32_t Hi) {
    return static_cast<uint32_t>(a.x) < Wi && static_cast<uint32_t>(b.x) < Wi && static_cast<uint32_t>(a.y) < Hi &&
           static_cast<uint32_t>(b.y) < Hi;
}

template <class P>
void segment(P& p, SubPoint a, SubPoint b, LineStyle style) {
    constexpr bool to_canvas = requires { p.sink.base; };
    const bool thin_line = !style.antialias && style.width <= kSub;
    if constexpr (to_canvas) {
        // The common case first, all in 32 bits.
        const int32_t w = p.sink.width(), h = p.sink.height();
        if (thin_line && w <= kMaxSide32 && h <= kMaxSide32) {
            const uint32_t Wi = static_cast<uint32_t>(w) * kSub, Hi = static_cast<uint32_t>(h) * kSub;
            // In a row band, only a segment whose pixels all lie in it (row_margin).
            // (In 64 bits: a y near the ends of int32 would overflow.)
            const bool in_band = !p.banded || (int64_t{a.y < b.y ? a.y : b.y} - row_margin(style) >= int64_t{p.row0} * kSub &&
                                               int64_t{a.y < b.y ? b.y : a.y} + row_margin(style) < int64_t{p.row1} * kSub);
            if (in_band && both_on(a, b, Wi, Hi)) return thin_inside(p, a, b);
        }
    }
    // Clip against the canvas grown by 2 px; end points inside it stay exactly as given (and
    // when both are inside, there is nothing to clip: no floating point at all).
    const int64_t Wi = int64_t{p.sink.width()} * kSub, Hi = int64_t{p.sink.height()} * kSub;
    int64_t X0 = a.x, Y0 = a.y, X1 = b.x, Y1 = b.y;
    const bool inside = X0 >= 0 && Y0 >= 0 && X1 >= 0 && Y1 >= 0 && X0 < Wi && X1 < Wi && Y0 < Hi && Y1 < Hi;
    if (!inside) {
        const double m = 2.0 * kSub;
        double x0 = a.x, y0 = a.y, x1 = b.x, y1 = b.y;
        const double grow = style.width > kSub ? m + style.width : m;
        if (!clip(x0, y0, x1, y1, -grow, -grow, static_cast<double>(Wi) + grow, static_cast<double>(Hi) + grow)) return;
        // The clipped points lie in the box (to within rounding, x0 + t dx with 0 <= t <= 1).
        const bool small = static_cast<double>(Wi > Hi ? Wi : Hi) + grow < 1073741824.0;
        X0 = round_clipped(x0, small), Y0 = round_clipped(y0, small), X1 = round_clipped(x1, small), Y1 = round_clipped(y1, small);
    }
    const bool x_major = (X1 > X0 ? X1 - X0 : X0 - X1) >= (Y1 > Y0 ? Y1 - Y0 : Y0 - Y1);
    p.swap = !x_major;
    const int64_t u0 = x_major ? X0 : Y0, v0 = x_major ? Y0 : X0, u1 = x_major ? X1 : Y1, v1 = x_major ? Y1 : X1;
    if (u0 == u1) return;  // a point: the caller plots end points
    // In a row band: does the (clipped) segment reach past it (raster.hpp, row_margin)? If not,
    // every pixel it writes is in the band and the loops need not look for the band's ends.
    bool cut = false;
    if (p.banded) {
        const int32_t m = row_margin(style);
        cut = (Y0 < Y1 ? Y0 : Y1) - m < int64_t{p.row0} * kSub || (Y0 < Y1 ? Y1 : Y0) + m >= int64_t{p.row1} * kSub;
    }
    if (!thin_line) return band(p, u0, v0, u1, v1, style.width, style.antialias, cut);
    if constexpr (to_canvas) {
        constexpr int64_t lim = int64_t{1} << 21;  // thin32's bound
        auto fits = [](int64_t c) { return static_cast<uint64_t>(c + lim) <= static_cast<uint64_t>(2 * lim); };
        // Lines past a band's edge too (each is drawn once per band it reaches: they are most of
        // what a second band costs), unless x-major and longer than kWalk columns.
        constexpr int64_t kWalk = 64 * kSub;
        if ((!cut || p.swap || (u1 > u0 ? u1 - u0 : u0 - u1) <= kWalk) && fits(u0) && fits(v0) && fits(u1) && fits(v1)) {
            const auto n = [](int64_t c) { return static_cast<int32_t>(c); };
            // (Inside here only on a canvas over 8192 px, whose lines take the general way.)
            if (cut) return thin32<false, std::remove_cvref_t<decltype(p.sink)>::bytes, true>(p, n(u0), n(v0), n(u1), n(v1));
            return thin32<false>(p, n(u0), n(v0), n(u1), n(v1));
        }
    }
    thin(p, u0, v0, u1, v1, cut);
}

template <class P>
void end_point(P& p, SubPoint e, LineStyle style) {
    if (style.antialias || style.width > kSub) return;  // bands cover their ends
    p.swap = false;
    p.opaque(floor_sub<int64_t>(e.x), floor_sub<int64_t>(e.y));
}

SubPoint to_sub_impl(double x, double y) {
    constexpr double lim = 4194304.0 * kSub;  // 2^22 px
    auto conv = [](double v) {
        if (!(v == v)) return static_cast<int32_t>(lim);  // NaN: far outside
        const double s = v * kSub;
        return static_cast<int32_t>(s > lim ? lim : (s < -lim ? -lim : std::nearbyint(s)));
    };
    return {conv(x), conv(y)};
}

// polyline() in a row band less than the canvas (out of line: the unbanded loop, the
// one-thread frame's, does not carry it).
template <class Sink>
[[gnu::noinline]] void banded_polyline(Plotter<Sink>& p, const Sink& sink, const SubPoint* points, int n, bool closed,
                                       LineStyle style) {
    // Segments that cannot reach the band are passed over here, before any set-up, and thin
    // ones on a canvas wholly inside it (their pixels too: row_margin) go straight to
    // thin_inside, as segment() would send them. The bodies that cross a band's edge are
    // drawn this way by each band they reach: the per-segment set-up is most of what a
    // second band costs.
    const int32_t m = row_margin(style);
    const int64_t lo = int64_t{p.row0} * kSub - m, hi = int64_t{p.row1} * kSub + m;  // reaches: lo <= y < hi
    auto reaches = [lo, hi](SubPoint a, SubPoint b) {
        return (a.y >= lo || b.y >= lo) && (a.y < hi || b.y < hi);
    };
    bool fast = false;  // thin lines on a canvas of at most 8192 px
    uint32_t Wi = 0, span = 0;
    int32_t in_lo = 0;  // within: in_lo <= y < in_lo + span, 0 <= x < Wi
    if constexpr (requires { sink.base; }) {
        fast = !style.antialias && style.width <= kSub && sink.width() <= kMaxSide32 && sink.height() <= kMaxSide32;
        Wi = static_cast<uint32_t>(sink.width()) * kSub;
        in_lo = p.row0 * kSub + m;
        const int32_t in_hi = p.row1 * kSub - m;
        span = in_hi > in_lo ? static_cast<uint32_t>(in_hi - in_lo) : 0;
    }
    for (int i = 0; i + 1 < n; ++i) {
        const SubPoint a = points[i], b = points[i + 1];
        if constexpr (requires { sink.base; }) {
            if (fast && static_cast<uint32_t>(a.x) < Wi && static_cast<uint32_t>(b.x) < Wi &&
                static_cast<uint32_t>(a.y) - static_cast<uint32_t>(in_lo) < span &&
                static_cast<uint32_t>(b.y) - static_cast<uint32_t>(in_lo) < span) {
                thin_inside(p, a, b);
                continue;
            }
        }
        if (reaches(a, b)) segment(p, a, b, style);
    }
    if (closed && n > 1) {
        if (reaches(points[n - 1], points[0])) segment(p, points[n - 1], points[0], style);
    } else {
        end_point(p, points[n - 1], style);
    }
}

template <class Sink>
void polyline(const Sink& sink, const SubPoint* points, int n, bool closed, LineStyle style, RowRange rows) {
    if (n <= 0) return;
    Plotter<Sink> p(sink, rows);
    if (p.row0 >= p.row1) return;
    if (p.banded) return banded_polyline(p, sink, points, n, closed, style);
    bool small = false;  // thin lines on a canvas of at most 8192 px: the segments on it go straight to thin_inside
    uint32_t Wi = 0, Hi = 0;
    if constexpr (requires { sink.base; }) {
        small = !style.antialias && style.width <= kSub && sink.width() <= kMaxSide32 && sink.height() <= kMaxSide32;
        Wi = static_cast<uint32_t>(sink.width()) * kSub, Hi = static_cast<uint32_t>(sink.height()) * kSub;
    }
    for (int i = 0; i + 1 < n; ++i) {
        const SubPoint a = points[i], b = points[i + 1];
        if constexpr (requires { sink.base; }) {
            if (small && both_on(a, b, Wi, Hi)) {
                thin_inside(p, a, b);
                continue;
            }
        }
        segment(p, a, b, style);
    }
    if (closed && n > 1)
        segment(p, points[n - 1], points[0], style);
    else
        end_point(p, points[n - 1], style);
}

}  // namespace

SubPoint to_sub(double x, double y) { return to_sub_impl(x, y); }

template <int Bpp>
void line_in(const Canvas& c, SubPoint a, SubPoint b, Rgb color, LineStyle style, bool plot_end, RowRange rows) {
    const CanvasSink<Bpp> sink(c, color);
    Plotter<CanvasSink<Bpp>> p(sink, rows);
    if (p.row0 >= p.row1) return;
    segment(p, a, b, style);
    if (plot_end) end_point(p, b, style);
}

void draw_line(const Canvas& c, SubPoint a, SubPoint b, Rgb color, LineStyle style, bool plot_end, RowRange rows) {
    switch (c.format().bytes_per_pixel()) {
        case 2: return line_in<2>(c, a, b, color, style, plot_end, rows);
        case 3: return line_in<3>(c, a, b, color, style, plot_end, rows);
        default: return line_in<4>(c, a, b, color, style, plot_end, rows);
    }
}

void draw_polyline(const Canvas& c, const SubPoint* points, int n, bool closed, Rgb color, LineStyle style, RowRange rows) {
    switch (c.format().bytes_per_pixel()) {
        case 2: return polyline(CanvasSink<2>(c, color), points, n, closed, style, rows);
        case 3: return polyline(CanvasSink<3>(c, color), points, n, closed, style, rows);
        default: return polyline(CanvasSink<4>(c, color), points, n, closed, style, rows);
    }
}

void visit_polyline(int width, int height, const SubPoint* points, int n, bool closed, LineStyle style,
                    PixelVisitor visit, void* context, RowRange rows) {
    polyline(VisitSink{width, height, visit, context}, points, n, closed, style, rows);
}

void shade_outside_circle(const Canvas& c, double cx, double cy, double r, Rgb shade, int blend_alpha) {
    const uint32_t word = c.format().pack(shade);
    auto put = [&](int x, int y) {
        if (blend_alpha >= 255)
            c.set_word(x, y, word);
        else
            c.blend(x, y, shade, blend_alpha);
    };
    for (int y = 0; y < c.height(); ++y) {
        const ColumnSpan in = columns_inside_circle(cx, cy, r, y, c.width());
        for (int x = 0; x < c.width(); ++x)
            if (x < in.first || x > in.last) put(x, y);
    }
}

}  // namespace noneuclid::render
