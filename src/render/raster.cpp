#include "render/raster.hpp"

#include <cmath>
#include <cstdlib>

namespace noneuclid::render {
namespace {

// Where pixels go: into a canvas, or to a visitor (tests, counting).
struct CanvasSink {
    const Canvas& c;
    Rgb color;
    uint32_t word;
    int width() const { return c.width(); }
    int height() const { return c.height(); }
    void opaque(int x, int y) const { c.set_word(x, y, word); }
    void blend(int x, int y, int alpha) const { c.blend(x, y, color, alpha); }
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
// points) and anything outside the canvas.
template <class Sink>
struct Plotter {
    const Sink& sink;
    bool swap = false;  // (u, v) are (y, x)
    int last_x = -1 << 30, last_y = -1 << 30;

    bool inside(int64_t x, int64_t y) const { return x >= 0 && y >= 0 && x < sink.width() && y < sink.height(); }
    void opaque(int64_t u, int64_t v) {
        const int64_t x = swap ? v : u, y = swap ? u : v;
        if (!inside(x, y) || (x == last_x && y == last_y)) return;
        sink.opaque(static_cast<int>(x), static_cast<int>(y));
        last_x = static_cast<int>(x), last_y = static_cast<int>(y);
    }
    void blend(int64_t u, int64_t v, int alpha) {
        const int64_t x = swap ? v : u, y = swap ? u : v;
        if (!inside(x, y)) return;
        sink.blend(static_cast<int>(x), static_cast<int>(y), alpha);
    }
};

int64_t floor_div(int64_t a, int64_t b) {  // b > 0
    const int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}
int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }

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
struct Columns {
    int64_t first, count, step;
};
Columns columns(int64_t u0, int64_t u1) {
    if (u1 > u0) {
        const int64_t a = ceil_div(u0 - kSub / 2, kSub), b = ceil_div(u1 - kSub / 2, kSub) - 1;
        return {a, b >= a ? b - a + 1 : 0, 1};
    }
    const int64_t a = floor_div(u0 - kSub / 2, kSub), b = floor_div(u1 - kSub / 2, kSub) + 1;
    return {a, a >= b ? a - b + 1 : 0, -1};
}

template <class P>
void thin(P& p, int64_t u0, int64_t v0, int64_t u1, int64_t v1) {
    const int64_t du = u1 - u0, dv = v1 - v0;
    const Columns col = columns(u0, u1);
    if (col.count == 0) return;
    // v at a column centre uc, in px: (v0 du + (uc - u0) dv) / (256 du) = N / A, A > 0.
    const int64_t sgn = du > 0 ? 1 : -1;
    const int64_t A = kSub * du * sgn;
    const int64_t uc = col.first * kSub + kSub / 2;
    const int64_t N = sgn * (v0 * du + (uc - u0) * dv);
    int64_t row = floor_div(N, A), rem = N - row * A;  // 0 <= rem < A
    const int64_t step = kSub * dv * col.step * sgn;    // |step| <= A
    int64_t u = col.first;
    for (int64_t k = 0; k < col.count; ++k) {
        p.opaque(u, row);
        u += col.step;
        rem += step;
        if (rem >= A) rem -= A, ++row;
        else if (rem < 0) rem += A, --row;
    }
}

// The band of the given width around the line, per column: exact coverage (anti-aliased) or
// the pixels whose centre it covers (thick aliased).
template <class P>
void band(P& p, int64_t u0, int64_t v0, int64_t u1, int64_t v1, int32_t width, bool aa) {
    const double du = static_cast<double>(u1 - u0), dv = static_cast<double>(v1 - v0);
    const Columns col = columns(u0, u1);
    if (col.count == 0) return;
    const double slope = dv / du;
    const double h = (width / double(kSub)) * std::sqrt(du * du + dv * dv) / std::fabs(du);  // px
    int64_t u = col.first;
    for (int64_t k = 0; k < col.count; ++k, u += col.step) {
        const double uc = static_cast<double>(u * kSub + kSub / 2);
        const double v = (static_cast<double>(v0) + (uc - static_cast<double>(u0)) * slope) / kSub;  // px
        const double lo = v - h / 2, hi = v + h / 2;
        if (aa) {
            for (int64_t r = static_cast<int64_t>(std::floor(lo)); static_cast<double>(r) < hi; ++r) {
                const double a = std::fmin(hi, static_cast<double>(r + 1)) - std::fmax(lo, static_cast<double>(r));
                const int alpha = static_cast<int>(a * 255 + 0.5);
                if (alpha > 0) p.blend(u, r, alpha);
            }
        } else {  // rows whose centre r + 1/2 lies in [lo, hi)
            const int64_t first = static_cast<int64_t>(std::ceil(lo - 0.5)), last = static_cast<int64_t>(std::ceil(hi - 0.5)) - 1;
            for (int64_t r = first; r <= last; ++r) p.opaque(u, r);
        }
    }
}

template <class P>
void segment(P& p, SubPoint a, SubPoint b, LineStyle style) {
    // Clip against the canvas grown by 2 px; end points inside it stay exactly as given.
    const double m = 2.0 * kSub;
    double x0 = a.x, y0 = a.y, x1 = b.x, y1 = b.y;
    const double W = static_cast<double>(p.sink.width()) * kSub, H = static_cast<double>(p.sink.height()) * kSub;
    const double grow = style.width > kSub ? m + style.width : m;
    if (!clip(x0, y0, x1, y1, -grow, -grow, W + grow, H + grow)) return;
    const int64_t X0 = std::llround(x0), Y0 = std::llround(y0), X1 = std::llround(x1), Y1 = std::llround(y1);
    const bool x_major = (X1 > X0 ? X1 - X0 : X0 - X1) >= (Y1 > Y0 ? Y1 - Y0 : Y0 - Y1);
    p.swap = !x_major;
    const int64_t u0 = x_major ? X0 : Y0, v0 = x_major ? Y0 : X0, u1 = x_major ? X1 : Y1, v1 = x_major ? Y1 : X1;
    if (u0 == u1) return;  // a point: the caller plots end points
    if (style.antialias || style.width > kSub)
        band(p, u0, v0, u1, v1, style.width, style.antialias);
    else
        thin(p, u0, v0, u1, v1);
}

template <class P>
void end_point(P& p, SubPoint e, LineStyle style) {
    if (style.antialias || style.width > kSub) return;  // bands cover their ends
    p.swap = false;
    p.opaque(floor_div(e.x, kSub), floor_div(e.y, kSub));
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

template <class Sink>
void polyline(const Sink& sink, const SubPoint* points, int n, bool closed, LineStyle style) {
    if (n <= 0) return;
    Plotter<Sink> p{sink};
    for (int i = 0; i + 1 < n; ++i) segment(p, points[i], points[i + 1], style);
    if (closed && n > 1)
        segment(p, points[n - 1], points[0], style);
    else
        end_point(p, points[n - 1], style);
}

}  // namespace

SubPoint to_sub(double x, double y) { return to_sub_impl(x, y); }

void draw_line(const Canvas& c, SubPoint a, SubPoint b, Rgb color, LineStyle style, bool plot_end) {
    const CanvasSink sink{c, color, c.format().pack(color)};
    Plotter<CanvasSink> p{sink};
    segment(p, a, b, style);
    if (plot_end) end_point(p, b, style);
}

void draw_polyline(const Canvas& c, const SubPoint* points, int n, bool closed, Rgb color, LineStyle style) {
    polyline(CanvasSink{c, color, c.format().pack(color)}, points, n, closed, style);
}

void visit_polyline(int width, int height, const SubPoint* points, int n, bool closed, LineStyle style,
                    PixelVisitor visit, void* context) {
    polyline(VisitSink{width, height, visit, context}, points, n, closed, style);
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
        const double dy = y + 0.5 - cy;
        int in0 = 0, in1 = -1;  // columns whose centre is inside: [in0, in1]
        if (std::fabs(dy) < r) {
            const double half = std::sqrt(r * r - dy * dy);
            in0 = static_cast<int>(std::fmax(-1.0, std::floor(cx - half - 0.5) + 1));
            in1 = static_cast<int>(std::fmin(c.width(), std::ceil(cx + half - 0.5) - 1));
        }
        for (int x = 0; x < c.width(); ++x)
            if (x < in0 || x > in1) put(x, y);
    }
}

}  // namespace noneuclid::render
