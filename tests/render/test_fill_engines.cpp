// The fixed engine's textured body against double's, the same picture within one texel: both
// engines draw the same body (a "C", not star-shaped about its centre, textured with an image
// whose texels hold their own coordinates), and at every pixel both light the texels read must be
// the same or neighbours, for K in {-1, -0.5, 0, 0.5, 1} and places from O to near the limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "coordinate_image.hpp"
#include "render/draw_world.hpp"

using namespace noneuclid;

namespace {

constexpr int kEnginesW = 400, kEnginesH = 400;

using test::coordinate_image;

world::Scene c_scene(double K, double r, double theta, double facing) {
    world::Scene sc;
    sc.curvature = K;
    world::SceneBody b;
    b.name = "C";
    for (double phi : {40, 90, 140, 180, 220, 270, 320}) b.vertices.push_back({0.4, phi});
    for (double phi : {300, 240, 180, 120, 60}) b.vertices.push_back({0.2, phi});
    b.r = r, b.theta_deg = theta, b.facing_deg = facing;
    b.texture = coordinate_image();
    sc.bodies.push_back(b);
    return sc;
}

// The body's fill alone on a black XRGB8888 canvas.
template <class T>
std::vector<render::Rgb> textured(const world::Scene& sc) {
    world::World<T> w(sc);
    render::DrawScratch<T> s;
    s.prepare(w);
    std::vector<uint8_t> px(kEnginesW * kEnginesH * 4, 0);
    const render::Canvas c{px.data(), kEnginesW, kEnginesH, kEnginesW * 4, render::PixelFormat::xrgb8888()};
    const render::DrawOptions o;
    s.fill.begin_frame(c);
    if (const render::FillJob* j = s.fill.plan(w, 0, render::ScreenMap<T>::of(c, w.K, w.R, o.projection), o, kEnginesW, kEnginesH))
        render::fill_rows(c, *j, 0, kEnginesH, s.fill.work[0]);
    std::vector<render::Rgb> out;
    for (int y = 0; y < kEnginesH; ++y)
        for (int x = 0; x < kEnginesW; ++x) out.push_back(c.get(x, y));
    return out;
}

using test::texel_gap;

TEST(FillEngines, FixedDrawsDoublesTexelsWithinOne) {
    struct Place {
        double r, theta, facing;
    };
    for (double K : {-1.0, -0.5, 0.0, 0.5, 1.0})
        for (Place p : {Place{0, 0, 20}, Place{0.9, 30, 200}, Place{1.8, 200, 75}, Place{2.7, 300, 10}}) {
            const world::Scene sc = c_scene(K, p.r, p.theta, p.facing);
            const std::vector<render::Rgb> f = textured<fx::fixed>(sc), d = textured<double>(sc);
            long both = 0;
            int worst = 0;
            for (std::size_t i = 0; i < f.size(); ++i) {
                if (f[i].b != 0x80 || d[i].b != 0x80) continue;  // not drawn by both
                ++both;
                worst = std::max({worst, texel_gap(f[i].r / 4, d[i].r / 4), texel_gap(f[i].g / 4, d[i].g / 4)});
            }
            EXPECT_GT(both, 300) << "K " << K << " r " << p.r;
            EXPECT_LE(worst, 1) << "K " << K << " r " << p.r;
        }
}

}  // namespace

// Each engine fills the shape it outlines: the paper engine (its own vertices and edge points,
// geometry/paper.hpp) against its own outline. Every boundary pixel of the fill (lit, with an
// unlit 4-neighbour) has its centre within 1 px of the outline's polyline, and every point of
// the polyline is within 1 px of a boundary pixel's centre, for a large hexagon (edges of 0.9
// on a body of radius 0.9, where a chord sags most) at K in {-1, -0.5, 0, 0.5, 1}, near O and
// far out, in the equidistant and stereographic views.
double to_segment(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}

TEST(FillEngines, ThePaperEngineFillsTheShapeItOutlines) {
    using W = world::World<double, geo::Paper>;
    double worst_fill = 0, worst_line = 0;
    for (double K : {-1.0, -0.5, 0.0, 0.5, 1.0})
        for (double r : {0.3, 1.4})
            for (geo::Projection p : {geo::Projection::azimuthal_equidistant, geo::Projection::stereographic}) {
                SCOPED_TRACE(::testing::Message() << "K " << K << " r " << r << " projection " << static_cast<int>(p));
                world::Scene sc;
                sc.curvature = K;
                world::SceneBody b;
                b.name = "hexagon";
                for (double phi : {0, 60, 120, 180, 240, 300}) b.vertices.push_back({0.9, phi});
                b.r = r, b.theta_deg = 30, b.facing_deg = 10;
                b.filled = true, b.fill = {200, 200, 200};
                sc.bodies.push_back(b);
                W w(sc);
                render::DrawScratch<double, geo::Paper> s;
                s.prepare(w);
                std::vector<uint8_t> px(kEnginesW * kEnginesH * 4, 0);
                const render::Canvas c{px.data(), kEnginesW, kEnginesH, kEnginesW * 4, render::PixelFormat::xrgb8888()};
                render::DrawOptions o;
                o.projection = p, o.antialias = false;
                const auto m = render::ScreenMap<double>::of(c, w.K, w.R, o.projection);
                s.fill.begin_frame(c);
                const render::FillJob* j = s.fill.plan(w, 0, m, o, kEnginesW, kEnginesH);
                ASSERT_NE(j, nullptr);
                render::fill_rows(c, *j, 0, kEnginesH, s.fill.work[0]);
                const std::size_t n = render::body_screen_points(w, w.bodies[0], s.shapes[0], m, o, s.vertices.data(),
                                                                 s.vectors.data(), s.points.data());
                std::vector<std::pair<double, double>> line;
                const double gap = std::nan("");  // (a break: where the view's edge cuts the outline)
                for (std::size_t k = 0; k < n; ++k) {
                    const bool cut = s.points[k].x == render::kBreak.x && s.points[k].y == render::kBreak.y;
                    line.push_back(cut ? std::pair{gap, gap} : std::pair{s.points[k].x / double(render::kSub), s.points[k].y / double(render::kSub)});
                }
                ASSERT_GE(line.size(), 6u);
                auto lit = [&](int x, int y) {
                    return x >= 0 && y >= 0 && x < kEnginesW && y < kEnginesH && c.get(x, y).r > 100;
                };
                // (The view's edge cuts both: pixels and points within 1.5 px of it are not the outline's.)
                auto near_clip = [&](double x, double y) {
                    return std::abs(std::hypot(x - j->clip_cx / double(render::kSub), y - j->clip_cy / double(render::kSub)) -
                                    j->clip_r / double(render::kSub)) < 1.5;
                };
                std::vector<std::pair<double, double>> edge;
                for (int y = 0; y < kEnginesH; ++y)
                    for (int x = 0; x < kEnginesW; ++x)
                        if (lit(x, y) && (!lit(x - 1, y) || !lit(x + 1, y) || !lit(x, y - 1) || !lit(x, y + 1)) &&
                            !near_clip(x + 0.5, y + 0.5))
                            edge.push_back({x + 0.5, y + 0.5});
                ASSERT_GT(edge.size(), 50u);
                for (auto [ex, ey] : edge) {
                    double d = 1e9;
                    for (std::size_t k = 0; k + 1 < line.size(); ++k)
                        if (!std::isnan(line[k].first) && !std::isnan(line[k + 1].first))
                            d = std::min(d, to_segment(ex, ey, line[k].first, line[k].second, line[k + 1].first, line[k + 1].second));
                    worst_fill = std::max(worst_fill, d);
                    EXPECT_LE(d, 1.0) << "fill edge pixel " << ex << "," << ey;
                }
                for (std::size_t k = 0; k + 1 < line.size(); ++k)
                    for (int t = 0; t < 8 && !std::isnan(line[k].first + line[k + 1].first); ++t) {  // along each chord
                        const double qx = line[k].first + (line[k + 1].first - line[k].first) * t / 8;
                        const double qy = line[k].second + (line[k + 1].second - line[k].second) * t / 8;
                        if (near_clip(qx, qy)) continue;
                        double d = 1e9;
                        for (auto [ex, ey] : edge)  // (to the pixel's square: a corner's point may be off every centre)
                            d = std::min(d, std::hypot(std::max(std::abs(qx - ex) - 0.5, 0.0), std::max(std::abs(qy - ey) - 0.5, 0.0)));
                        worst_line = std::max(worst_line, d);
                        EXPECT_LE(d, 1.0) << "outline point " << qx << "," << qy;
                    }
            }
    std::printf("paper engine: fill edge to outline at most %.3f px, outline to fill edge %.3f px\n", worst_fill, worst_line);
}
