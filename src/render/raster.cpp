// The rasteriser's lines and polylines (raster.hpp): clipping, each segment sent to the thin
// (raster_thin.hpp) or wide (raster_wide.hpp) line loop, polylines in and out of a row band,
// and the public entry points, one instantiation per pixel size.
#include "render/raster.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <type_traits>

#include "render/raster_plot.hpp"
#include "render/raster_thin.hpp"
#include "render/raster_wide.hpp"

namespace noneuclid::render {
namespace {

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
    if (!thin_line && !style.antialias) return capsule_line(p, u0, v0, u1, v1, style.width);
    if (!thin_line) return wide_line(p, u0, v0, u1, v1, style.width, style.antialias, cut);
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

// The join at b of the segments a -> b -> c, for thin aliased lines (bands cover their joins).
// Where both segments step along the same axis the same way, the last column of one and the
// first of the other are neighbours on either side of b, and one of them is within a pixel of
// it. Otherwise (a fold back, or a turn across a diagonal from x-major to y-major) both may stop
// up to a pixel short of b along their own axes, leaving b up to 1.8 px from the nearest pixel:
// there b's own pixel is plotted too (Plotter::join).
// (Signs only, no products: the points may lie anywhere in the int32 range.)
template <class P>
void sharp_join(P& p, SubPoint a, SubPoint b, SubPoint c, bool closing = false) {
    const int64_t ux = int64_t{b.x} - a.x, uy = int64_t{b.y} - a.y, vx = int64_t{c.x} - b.x, vy = int64_t{c.y} - b.y;
    const bool ax = (ux < 0 ? -ux : ux) >= (uy < 0 ? -uy : uy), bx = (vx < 0 ? -vx : vx) >= (vy < 0 ? -vy : vy);
    if (ax != bx || (ax ? (ux ^ vx) : (uy ^ vy)) < 0)  // other axes, or the same axis the other way
        p.join(static_cast<int>(floor_sub<int64_t>(b.x)), static_cast<int>(floor_sub<int64_t>(b.y)), closing);
}

template <class P>
void end_point(P& p, SubPoint e, LineStyle style) {
    if (style.antialias || style.width > kSub) return;  // bands cover their ends
    p.swap = false;
    p.opaque(floor_sub<int64_t>(e.x), floor_sub<int64_t>(e.y));
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
    const bool thin_style = !style.antialias && style.width <= kSub;
    if (!closed && n > 1) end_point(p, points[0], style);
    for (int i = 0; i + 1 < n; ++i) {
        const SubPoint a = points[i], b = points[i + 1];
        bool done = false;
        if constexpr (requires { sink.base; }) {
            if (fast && static_cast<uint32_t>(a.x) < Wi && static_cast<uint32_t>(b.x) < Wi &&
                static_cast<uint32_t>(a.y) - static_cast<uint32_t>(in_lo) < span &&
                static_cast<uint32_t>(b.y) - static_cast<uint32_t>(in_lo) < span)
                thin_inside(p, a, b), done = true;
        }
        if (!done && reaches(a, b)) segment(p, a, b, style);
        if (thin_style && (i + 2 < n || closed)) sharp_join(p, a, b, points[i + 2 < n ? i + 2 : 0]);
    }
    if (closed && n > 1) {
        if (reaches(points[n - 1], points[0])) segment(p, points[n - 1], points[0], style);
        if (thin_style) sharp_join(p, points[n - 1], points[0], points[1], true);
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
    const bool thin_style = !style.antialias && style.width <= kSub;
    if (!closed && n > 1) end_point(p, points[0], style);
    for (int i = 0; i + 1 < n; ++i) {
        const SubPoint a = points[i], b = points[i + 1];
        bool done = false;
        if constexpr (requires { sink.base; }) {
            if (small && both_on(a, b, Wi, Hi)) thin_inside(p, a, b), done = true;
        }
        if (!done) segment(p, a, b, style);
        if (thin_style && (i + 2 < n || closed)) sharp_join(p, a, b, points[i + 2 < n ? i + 2 : 0]);
    }
    if (closed && n > 1) {
        segment(p, points[n - 1], points[0], style);
        if (thin_style) sharp_join(p, points[n - 1], points[0], points[1], true);
    } else {
        end_point(p, points[n - 1], style);
    }
}

}  // namespace

template <int Bpp>
void line_in(const Canvas& c, SubPoint a, SubPoint b, Rgb color, LineStyle style, bool plot_ends, RowRange rows) {
    const CanvasSink<Bpp> sink(c, color);
    Plotter<CanvasSink<Bpp>> p(sink, rows);
    if (p.row0 >= p.row1) return;
    if (plot_ends) end_point(p, a, style);
    segment(p, a, b, style);
    if (plot_ends) end_point(p, b, style);
}

void draw_line(const Canvas& c, SubPoint a, SubPoint b, Rgb color, LineStyle style, bool plot_ends, RowRange rows) {
    switch (c.format().bytes_per_pixel()) {
        case 2: return line_in<2>(c, a, b, color, style, plot_ends, rows);
        case 3: return line_in<3>(c, a, b, color, style, plot_ends, rows);
        default: return line_in<4>(c, a, b, color, style, plot_ends, rows);
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
