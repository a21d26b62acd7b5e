// The fixed engine's textured body against double's, the same picture within one texel: both
// engines draw the same body (a "C", not star-shaped about its centre, textured with an image
// whose texels hold their own coordinates), and at every pixel both light the texels read must be
// the same or neighbours, for K in {-1, -0.5, 0, 0.5, 1} and places from O to near the limit.
#include <gtest/gtest.h>

#include <algorithm>
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
