// The triangle instrument in an uneven world (src/uneven/triangle.hpp): without bumps it reads
// what the constant-K instrument reads (geo::measure_triangle's closed forms); among bumps its
// angle excess follows the curvature it holds, computed apart (Gauss-Bonnet); the live triangle
// marked where the ship flies, in the dump and on a scene file's [[measure]].
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "files/scene_file.hpp"
#include "geometry/measure.hpp"
#include "test_common.hpp"
#include "uneven/dump.hpp"
#include "uneven/world.hpp"

namespace {
namespace uneven_measure_test {

using namespace noneuclid;
using uneven::Vec2;

constexpr double kPi = test::kPi, kDeg = kPi / 180;

// Without bumps, at five K: the sides, angles, excess, area and K times the area of the
// constant-K instrument's closed forms.
TEST(UnevenMeasure, WithoutBumpsTheTriangleReadsTheClosedForms) {
    const geo::Polar<double> marks[3] = {{1.2, 90 * kDeg}, {1.2, 210 * kDeg}, {0.7, 330 * kDeg}};
    double worst_angle = 0, worst_side = 0, worst_k = 0, worst_area = 0;
    for (double K : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
        geo::TriangleReading want;
        ASSERT_EQ(geo::measure_triangle(K, marks, kPi, want), geo::MeasureError::none);
        uneven::Metric m;
        m.K = K;
        uneven::Triangle t;
        for (int i = 0; i < 3; ++i) {
            const double rho = uneven::chart_radius(K, marks[i].r);
            t.mark[i] = {rho * std::cos(marks[i].theta), rho * std::sin(marks[i].theta)};
        }
        uneven::measure(m, t);
        ASSERT_TRUE(t.valid) << K;
        for (int i = 0; i < 3; ++i) {
            worst_angle = std::fmax(worst_angle, std::fabs(t.angle[i] / kDeg - want.angle_deg[i]));
            worst_side = std::fmax(worst_side, std::fabs(t.side[i] - want.side[i]));
        }
        worst_k = std::fmax(worst_k, std::fabs(t.curvature / kDeg - want.k_area_deg));
        worst_area = std::fmax(worst_area, std::fabs(t.area - want.area) / want.area);
    }
    std::printf("no bumps, K = -1 to 1: angles within %.1e deg, sides %.1e, K*A %.1e deg, area %.2f%%\n", worst_angle,
                worst_side, worst_k, 100 * worst_area);
    EXPECT_LT(worst_angle, 1e-7);
    EXPECT_LT(worst_side, 1e-9);
    EXPECT_LT(worst_k, 1e-6);
    EXPECT_LT(worst_area, 0.02);  // (the midpoint rule on a 64 x 64 grid over the chart triangle)
}

// Among the hills and about a mass, at three K: the excess from the angles against the integral
// of K dA from the flux of grad psi through the sides.
TEST(UnevenMeasure, AmongBumpsTheExcessFollowsTheCurvatureHeld) {
    double worst = 0, largest = 0;
    int measured = 0;
    for (const char* name : {"hills", "lens"})
        for (double K : {-0.6, 0.0, 0.5}) {
            world::Scene s;
            ASSERT_TRUE(world::builtin_scene(name, {}, s));
            s.curvature = K;
            const uneven::World w(s);
            for (int c = 0; c < 6; ++c) {
                uneven::Triangle t;
                for (int i = 0; i < 3; ++i)
                    t.mark[i] = w.chart({0.4 + 0.25 * ((c + i) % 4), (40.0 * c + 120 * i) * kDeg});
                uneven::measure(w.metric(), t);
                if (!t.valid) continue;
                ++measured;
                worst = std::fmax(worst, std::fabs(t.excess - t.curvature));
                largest = std::fmax(largest, std::fabs(t.curvature));
            }
        }
    std::printf("among bumps: %d triangles, |excess - integral of K dA| within %.1e rad (the largest integral %.3f)\n",
                measured, worst, largest);
    EXPECT_GE(measured, 30);
    EXPECT_GT(largest, 0.3);
    EXPECT_LT(worst, 1e-6);
}

// The live triangle: the instrument key, then fire where the ship has flown; its reading in the
// dump; a scene file's [[measure]] triangle among bumps read from the start.
TEST(UnevenMeasure, TheLiveTriangleIsMarkedWhereTheShipFlies) {
    world::Scene s;
    ASSERT_TRUE(world::builtin_scene("hills", {}, s));
    uneven::World w(s);
    EXPECT_FALSE(w.measuring());
    w.press(world::Action::instrument), w.release(world::Action::instrument);
    ASSERT_TRUE(w.measuring());
    w.press(world::Action::thrust);
    for (int mark = 0; mark < 3; ++mark) {
        for (int i = 0; i < 50; ++i) w.step(1.0 / 60);
        if (mark == 1) w.press(world::Action::left);
        w.press(world::Action::fire), w.release(world::Action::fire);
    }
    const auto& g = w.gauges().back();
    ASSERT_EQ(g.marks, 3);
    EXPECT_EQ(g.reading().error, geo::MeasureError::none);
    EXPECT_FALSE(g.reading().waiting);
    EXPECT_NEAR(g.reading().triangle.excess_deg, g.reading().triangle.k_area_deg, 1e-4);
    std::string line;
    files::dump_frame(w, {}, line);
    EXPECT_NE(line.find("\"measure\":[{\"instrument\":\"triangle\""), std::string::npos) << line.substr(line.size() - 300);
    for (int i = 0; i < 60; ++i) w.step(1.0 / 60);  // a fourth mark starts a new triangle
    w.press(world::Action::fire), w.release(world::Action::fire);
    EXPECT_EQ(w.gauges().back().marks, 1);
    EXPECT_TRUE(w.gauges().back().reading().waiting);

    world::Scene f;
    files::SceneError e;
    ASSERT_TRUE(files::parse_scene("[[bump]]\nkind = \"mass\"\nstrength = 0.4\nwidth = 0.3\n[[measure]]\n"
                                   "instrument = \"triangle\"\npoints = [[1, 90], [1, 210], [1, 330]]\n",
                                   "t.toml", f, e))
        << e.to_string();
    const uneven::World u(f);
    ASSERT_EQ(u.gauges().size(), 2u);
    const world::GaugeReading& r = u.gauges().front().reading();
    std::printf("a mass of 0.4 inside a triangle: excess %.4f deg, integral of K dA %.4f deg (2 pi alpha = %.1f)\n",
                r.triangle.excess_deg, r.triangle.k_area_deg, 360 * 0.4);
    EXPECT_NEAR(r.triangle.excess_deg, r.triangle.k_area_deg, 1e-4);
    EXPECT_GT(r.triangle.k_area_deg, 0.5 * 144);  // more than half the mass's 2 pi alpha is inside
}

}  // namespace uneven_measure_test
}  // namespace
