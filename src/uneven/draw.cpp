// Drawing an uneven world (see draw.hpp).
#include "uneven/draw.hpp"

#include <cmath>
#include <cstring>

#include "geometry/edges.hpp"
#include "render/backdrop.hpp"
#include "render/body_points.hpp"
#include "render/clip_sink.hpp"
#include "world/ranges.hpp"

namespace noneuclid::uneven {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr int kRayMost = static_cast<int>(world::Ranges::kReach / kDrawStep) + 4;
constexpr int kFieldBlock = 4;  // the field's curvature is computed every 4 px and interpolated

geo::ScreenMap<double> chart_map(int width, int height, const World& w, int disc) {
    return geo::ScreenMap<double>::of(width, height, w.K, w.R, geo::Projection::stereographic, disc);
}

// Whether a body never moves (a grid line): its outline changes only with the metric.
bool still(const Body& b) { return b.speed == 0 && b.spin == 0 && b.accel == 0 && !b.desc->controlled; }

// Copies one pixel of `bpp` bytes.
inline void copy_pixel(uint8_t* to, const uint8_t* from, int bpp) {
    switch (bpp) {
        case 2: std::memcpy(to, from, 2); break;
        case 3: std::memcpy(to, from, 3); break;
        default: std::memcpy(to, from, 4); break;
    }
}

}  // namespace

render::Rgb field_color(double k, render::Rgb bg) {
    const double t = std::fabs(k) / (1 + std::fabs(k));  // 0 flat, 1/2 at |K| = 1, towards 1 beyond
    const double to[3] = {k < 0 ? 50. : 235., k < 0 ? 105. : 70., k < 0 ? 235. : 80.};
    const double from[3] = {double(bg.r), double(bg.g), double(bg.b)};
    auto mix = [&](int i) { return static_cast<uint8_t>(from[i] + (to[i] - from[i]) * 0.5 * t + 0.5); };
    return {mix(0), mix(1), mix(2)};
}

bool Drawing::Key::operator==(const Key& o) const {
    return width == o.width && height == o.height && disc == o.disc && version == o.version && format.same_layout(o.format) &&
           background == o.background && outside == o.outside && rim == o.rim && rim_line == o.rim_line &&
           shade == o.shade && antialias == o.antialias && line_width == o.line_width;
}

void Drawing::prepare(const World& w) {
    bodies_.assign(w.bodies.size(), BodyCache{});
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        const Body& b = w.bodies[i];
        const std::size_t n = b.local.size(), tess = static_cast<std::size_t>(b.tessellation() > 0 ? b.tessellation() : 1);
        bodies_[i].points.resize(3 * (n * tess + 2) + 4);
    }
    ray_.reserve(kRayMost + 1);
    gauge_points_.resize(3 * (3 * kSidePoints + 2));
    fan_.resize(static_cast<std::size_t>(kFanRays) * (kFanSamples + 1));
    reach_.resize(kFanRays);
}

void Drawing::draw(const render::Canvas& c, const World& w, const render::DrawOptions& o, bool backdrop) {
    // Both views' buffers on a canvas's first frame, so that a switch of view allocates nothing.
    const int W = c.width(), H = c.height(), bpp = c.format().bytes_per_pixel();
    const std::size_t bytes = static_cast<std::size_t>(W) * H * bpp;
    if (chart_.size() != bytes) {
        chart_.assign(bytes, 0);
        field_.resize(bytes);
        table_.resize(static_cast<std::size_t>(W) * H);
        grid_.resize(static_cast<std::size_t>(W / kFieldBlock + 2) * (H / kFieldBlock + 2));
    }
    if (is_chart_view(o.projection)) return draw_chart(c, w, o, backdrop);
    // The inhabitant's view: the chart drawn aside (lines two pixels wide), then each pixel from
    // where the table says; without the backdrop only the pixels the bodies drew.
    const render::Canvas chart(chart_.data(), W, H, static_cast<std::ptrdiff_t>(W) * bpp, c.format());
    render::DrawOptions co = o;
    co.line_width = o.line_width < 2 * geo::kSub ? 2 * geo::kSub : o.line_width;
    chart_backdrop(chart, w, o);
    draw_chart(chart, w, co, false);
    Key k;
    k.width = W, k.height = H, k.disc = o.disc, k.version = w.metric_version(), k.format = c.format();
    if (!(table_key_ == k)) {
        if (fan_version_ != w.metric_version() || fan_step_ == 0) build_fan(w);
        build_table(w, W, H, o.disc);
        table_key_ = k;
    }
    if (backdrop) {
        switch (bpp) {
            case 2: return warp<2>(c, o.outside);
            case 3: return warp<3>(c, o.outside);
            default: return warp<4>(c, o.outside);
        }
    }
    const int32_t* t = table_.data();  // only the pixels the bodies drew: those not the field's
    for (int y = 0; y < H; ++y) {
        uint8_t* row = c.row(y);
        for (int x = 0; x < W; ++x, ++t) {
            if (*t < 0) continue;
            const uint8_t* from = chart_.data() + static_cast<std::size_t>(*t) * bpp;
            if (std::memcmp(from, field_.data() + static_cast<std::size_t>(*t) * bpp, bpp) == 0) continue;
            copy_pixel(row + x * bpp, from, bpp);
        }
    }
}

// Every pixel from the chart as the table says (-1: the outside's colour), B bytes each.
template <int B>
void Drawing::warp(const render::Canvas& c, render::Rgb outside) {
    const uint32_t word = c.format().pack(outside);
    uint8_t out[4];
    for (int i = 0; i < 4; ++i) out[i] = static_cast<uint8_t>(word >> (8 * i));
    const int32_t* t = table_.data();
    const uint8_t* chart = chart_.data();
    for (int y = 0; y < c.height(); ++y) {
        uint8_t* row = c.row(y);
        for (int x = 0; x < c.width(); ++x, ++t, row += B) std::memcpy(row, *t < 0 ? out : chart + static_cast<std::size_t>(*t) * B, B);
    }
}

void Drawing::draw_chart(const render::Canvas& c, const World& w, const render::DrawOptions& o, bool backdrop) {
    const geo::ScreenMap<double> m = chart_map(c.width(), c.height(), w, o.disc);
    if (backdrop) chart_backdrop(c, w, o);
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
        const Body& b = w.bodies[i];
        if (!render::body_shown(b, o)) continue;
        BodyCache& bc = bodies_[i];
        if (!(still(b) && bc.version == w.metric_version() + 1 && bc.width == c.width() && bc.height == c.height() && bc.disc == o.disc)) {
            body_outline(w, i, m);
            bc.version = w.metric_version() + 1, bc.width = c.width(), bc.height = c.height(), bc.disc = o.disc;
        }
        render::draw_screen_points(c, bc.points.data(), bc.count, render::body_color(b, o),
                                   render::LineStyle{o.antialias, o.line_width});
    }
    draw_triangles(c, w, o, m);
}

// The instruments: each shown triangle's sides (once measured) and its marks, in the constant-K
// world's instrument colours (the live one's warm, the scene's cool).
void Drawing::draw_triangles(const render::Canvas& c, const World& w, const render::DrawOptions& o,
                             const geo::ScreenMap<double>& m) {
    if (!o.bodies) return;
    const render::LineStyle line{o.antialias, o.line_width};
    auto at = [&](Vec2 x) { return geo::spot_at(m, geo::to_sub(m.cx + m.scale * x.x, m.cy - m.scale * x.y)); };
    for (const World::Gauge& g : w.gauges()) {
        if (!g.on()) continue;
        const render::Rgb own = g.live ? render::Rgb{255, 210, 90} : render::Rgb{120, 230, 255};
        const render::Rgb colour = render::palette_line(o.palette, render::LineRole::instrument, own);
        if (g.triangle.valid) {
            render::ClipSink sink(m, gauge_points_.data());
            geo::Spot prev = at(g.triangle.path[0][0]);
            sink.start(prev);
            for (const auto& side : g.triangle.path)
                for (const Vec2& x : side) {
                    const geo::Spot s = at(x);
                    sink.chord(prev, s);
                    prev = s;
                }
            sink.end();
            render::draw_screen_points(c, gauge_points_.data(), sink.count(), colour, line);
        }
        for (int i = 0; i < g.marks; ++i) {  // a mark: a small cross
            const geo::SubPoint p = at(g.triangle.mark[i]).at;
            constexpr int32_t r = 3 * geo::kSub;
            render::draw_line(c, {p.x - r, p.y}, {p.x + r, p.y}, colour, line, true);
            render::draw_line(c, {p.x, p.y - r}, {p.x, p.y + r}, colour, line, true);
        }
    }
}

// The backdrop (render/backdrop.hpp) with the curvature's colour inside the limit circle, kept
// in field_ until the metric, the canvas or the colours change.
void Drawing::chart_backdrop(const render::Canvas& c, const World& w, const render::DrawOptions& o) {
    Key k;
    k.width = c.width(), k.height = c.height(), k.disc = o.disc, k.version = w.metric_version(), k.format = c.format();
    k.background = o.background, k.outside = o.outside, k.rim = o.rim, k.rim_line = o.rim_line;
    k.shade = o.shade_outside, k.antialias = o.antialias, k.line_width = o.line_width;
    const std::size_t row_bytes = static_cast<std::size_t>(c.width()) * c.format().bytes_per_pixel();
    if (field_key_ == k) {
        for (int y = 0; y < c.height(); ++y) std::memcpy(c.row(y), field_.data() + y * row_bytes, row_bytes);
        return;
    }
    const geo::ScreenMap<double> m = chart_map(c.width(), c.height(), w, o.disc);
    render::draw_backdrop(c, m, o);
    // The curvature at every kFieldBlock-th pixel, interpolated between.
    const int gw = c.width() / kFieldBlock + 2, gh = c.height() / kFieldBlock + 2;
    const double inside = m.rim - 1.5;
    grid_.resize(static_cast<std::size_t>(gw) * gh);
    std::vector<double>& grid = grid_;
    for (int gy = 0; gy < gh; ++gy)
        for (int gx = 0; gx < gw; ++gx) {
            const double px = gx * kFieldBlock - m.cx, py = m.cy - gy * kFieldBlock;
            const bool near = std::hypot(px, py) < m.rim + 2 * kFieldBlock;
            grid[gy * gw + gx] = near ? w.metric().curvature({px / m.scale, py / m.scale}) : 0;
        }
    for (int y = 0; y < c.height(); ++y) {
        const double dy = m.cy - (y + 0.5);
        const int gy = y / kFieldBlock;
        const double fy = (y % kFieldBlock) / double(kFieldBlock);
        for (int x = 0; x < c.width(); ++x) {
            const double dx = x + 0.5 - m.cx;
            if (dx * dx + dy * dy >= inside * inside) continue;
            const int gx = x / kFieldBlock;
            const double fx = (x % kFieldBlock) / double(kFieldBlock);
            const double* g = &grid[gy * gw + gx];
            const double kk = (g[0] * (1 - fx) + g[1] * fx) * (1 - fy) + (g[gw] * (1 - fx) + g[gw + 1] * fx) * fy;
            c.set(x, y, field_color(kk, o.background));
        }
    }
    field_.resize(row_bytes * c.height());
    for (int y = 0; y < c.height(); ++y) std::memcpy(field_.data() + y * row_bytes, c.row(y), row_bytes);
    field_key_ = k;
}

// Body i's outline on the chart map m into its cache: each edge's points in the world of
// constant K, in the body's local coordinates, carried out by the exponential map.
void Drawing::body_outline(const World& w, std::size_t i, const geo::ScreenMap<double>& m) {
    const Body& b = w.bodies[i];
    BodyCache& bc = bodies_[i];
    render::ClipSink sink(m, bc.points.data());
    const Vec2 from = w.chart(b.centre);
    ray_.clear();
    bool first = true;
    geo::Spot prev;
    auto emit = [&](geo::Polar<double> lp) {
        const Vec2 x = trace(w.metric(), from, b.facing + lp.theta, lp.r);
        const geo::Spot s = geo::spot_at(m, geo::to_sub(m.cx + m.scale * x.x, m.cy - m.scale * x.y));
        if (first) sink.start(s), first = false;
        else sink.chord(prev, s);
        prev = s;
    };
    const std::size_t n = b.local.size();
    if (n == 1) emit(b.local[0]);
    const std::size_t edges = b.closed() && n >= 3 ? n : (n > 0 ? n - 1 : 0);
    const int tess = b.tessellation() > 0 ? b.tessellation() : 1;
    for (std::size_t e = 0; e < edges; ++e)
        geo::edge_points(w.K, b.local[e], b.local[(e + 1) % n], tess, [&](int k, geo::Polar<double> p) {
            if (k > 0 || e == 0) emit(p);
        });
    sink.end();
    bc.count = sink.count();
}

// The point rho along the geodesic from `from` in chart direction dir: from the trace kept
// for this direction (extended as needed) plus one step of the rest.
Vec2 Drawing::trace(const Metric& metric, Vec2 from, double dir, double rho) {
    if (!(rho > 0)) return from;
    const bool same = !ray_.empty() && ray_from_.x == from.x && ray_from_.y == from.y &&
                      std::fabs(std::remainder(dir - ray_dir_, kTwoPi)) < 1e-9;
    if (!same) {
        ray_.clear();
        ray_.push_back({from, dir});
        ray_dir_ = dir, ray_from_ = from;
    }
    int k = static_cast<int>(rho / kDrawStep);
    if (k > kRayMost) k = kRayMost;
    while (static_cast<int>(ray_.size()) <= k) ray_.push_back(rk4(metric, ray_.back(), 1.0, kDrawStep));
    const double rest = rho - k * kDrawStep;
    return rest > 0 ? rk4(metric, ray_[k], 1.0, rest).x : ray_[k].x;
}

// kFanRays geodesics from O, kFanSamples + 1 points along each, out to where each leaves the
// chart's limit circle (at most twice the limit's length: a mass contracts the world around it,
// so its geodesics from O take longer to get there). The view reaches the longest of them.
void Drawing::build_fan(const World& w) {
    const double L = w.limit(), edge = chart_radius(w.K, L);
    fan_step_ = 2 * L / kFanSamples;
    fan_reach_ = 0;
    for (int i = 0; i < kFanRays; ++i) {
        Geodesic g{{0, 0}, kTwoPi * i / kFanRays};
        Vec2* row = &fan_[static_cast<std::size_t>(i) * (kFanSamples + 1)];
        row[0] = g.x;
        // Past the edge the ray goes on (its neighbours may not have left yet, and the view
        // interpolates between them), up to three times the edge's chart radius.
        int exit = 0;
        for (int j = 1; j <= kFanSamples; ++j) {
            if (dot(g.x, g.x) < 9 * edge * edge) {
                g = rk4(w.metric(), g, 1.0, fan_step_ / 2);
                g = rk4(w.metric(), g, 1.0, fan_step_ / 2);
            }
            row[j] = g.x;
            if (exit == 0 && dot(g.x, g.x) >= edge * edge) exit = j;
        }
        if (exit > 0) {  // where it crossed the edge, between the samples either side
            const double a = std::sqrt(dot(row[exit - 1], row[exit - 1])), b = std::sqrt(dot(row[exit], row[exit]));
            const double f = b > a ? (edge - a) / (b - a) : 1;
            reach_[i] = fan_step_ * (exit - 1 + (f < 0 ? 0 : f > 1 ? 1 : f));
        } else {
            reach_[i] = fan_step_ * kFanSamples;
        }
        fan_reach_ = std::fmax(fan_reach_, reach_[i]);
    }
    fan_version_ = w.metric_version();
}

// Linear along each ray, then a Catmull-Rom cubic across four neighbouring rays: where a bump
// spreads the rays apart, a straight line between two of them would cut the corner.
Vec2 Drawing::fan_point(double s, double a) const {
    double u = a / kTwoPi * kFanRays;
    u -= std::floor(u / kFanRays) * kFanRays;
    int i = static_cast<int>(u);
    if (i >= kFanRays) i = 0;
    const double fu = u - i;
    double v = fan_step_ > 0 ? s / fan_step_ : 0;
    if (v > kFanSamples) v = kFanSamples;
    int j = static_cast<int>(v);
    if (j >= kFanSamples) j = kFanSamples - 1;
    const double fv = v - j;
    Vec2 p[4];
    for (int k = 0; k < 4; ++k) {
        const Vec2* r = &fan_[static_cast<std::size_t>((i + k - 1 + kFanRays) % kFanRays) * (kFanSamples + 1)];
        p[k] = r[j] + fv * (r[j + 1] - r[j]);
    }
    const double t = fu, t2 = t * t, t3 = t2 * t;
    return 0.5 * ((2 * t2 - t3 - t) * p[0] + (3 * t3 - 5 * t2 + 2) * p[1] + (4 * t2 - 3 * t3 + t) * p[2] + (t3 - t2) * p[3]);
}
double Drawing::fan_reach(double a) const {
    double u = a / kTwoPi * kFanRays;
    u -= std::floor(u / kFanRays) * kFanRays;
    int i = static_cast<int>(u);
    if (i >= kFanRays) i = 0;
    const double fu = u - i;
    return reach_[i] + fu * (reach_[(i + 1) % kFanRays] - reach_[i]);
}

// Each pixel of the inhabitant's view: the chart pixel it shows; -1 past where its geodesic
// leaves the chart's limit circle (the outside's colour), itself outside the view's own circle
// (where both views shade the same).
void Drawing::build_table(const World& w, int width, int height, int disc) {
    const geo::ScreenMap<double> em =
        geo::ScreenMap<double>::of(width, height, w.K, fan_reach_, geo::Projection::azimuthal_equidistant, disc);
    const geo::ScreenMap<double> cm = chart_map(width, height, w, disc);
    table_.resize(static_cast<std::size_t>(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double X = (x + 0.5 - em.cx) / em.scale, Y = (em.cy - (y + 0.5)) / em.scale;
            const double s = std::hypot(X, Y);
            int32_t from = y * width + x;
            if (s < fan_reach_ && s >= fan_reach(std::atan2(Y, X))) {
                from = -1;
            } else if (s < fan_reach_) {
                const Vec2 p = fan_point(s, std::atan2(Y, X));
                const double qx = std::floor(cm.cx + cm.scale * p.x), qy = std::floor(cm.cy - cm.scale * p.y);
                if (qx >= 0 && qy >= 0 && qx < width && qy < height) from = static_cast<int32_t>(qy) * width + static_cast<int32_t>(qx);
            }
            table_[static_cast<std::size_t>(y) * width + x] = from;
        }
}

}  // namespace noneuclid::uneven
