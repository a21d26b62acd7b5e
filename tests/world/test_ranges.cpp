// The accepted ranges are the engines' ranges (world/ranges.hpp, docs/reliability.md "Ranges"):
// random scenes drawn from the whole accepted range of a scene file (K, limit_radius, positions,
// speeds, accelerations, sizes, spins) are checked in every engine:
//  - every vertex and edge point the fixed, double and float engines compute is finite, every
//    frame, while K moves
//    over [-1, 1] and the ship thrusts and turns (no null in the dump, no body silently missing);
//  - every centre stays inside the limit circle, every speed at or under the ceiling;
//  - every engine's drawing is within one pixel of the true curve (curve_reference.hpp) on a
//    1920x1080 canvas, at K from -1 to 1, the antipode included.
// And the other way round: values just outside the ranges are refused with a sentence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../render/curve_reference.hpp"
#include "render/draw_world.hpp"
#include "files/dump.hpp"
#include "test_common.hpp"
#include "world/ranges.hpp"
#include "files/scene_file.hpp"

namespace noneuclid {
namespace {

using fx::fixed;
using world::Ranges;

using testing::kGapPx;
using testing::kWithinPx;
using noneuclid::test::kPi;

// A scene drawn from the accepted ranges, every body within them (body_within_ranges), so that
// the largest values occur: a body's reach up to 2 pi, speeds up to the ceiling.
world::Scene random_scene(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    world::Scene s;
    s.curvature = 2 * u(rng) - 1;
    // Half the scenes near the largest R, the rest anywhere down to the smallest.
    s.limit_radius =
        u(rng) < 0.5 ? Ranges::kLimitRadius * (0.6 + 0.4 * u(rng)) : 1e-3 + (Ranges::kLimitRadius - 1e-3) * u(rng);
    s.sweep_rate = u(rng) < 0.3 ? 3 * u(rng) : 0;
    s.thrust = 1000 * u(rng);
    const int bodies = 2 + static_cast<int>(4 * u(rng));
    for (int i = 0; i < bodies; ++i) {
        world::SceneBody b;
        b.name = "b" + std::to_string(i);
        b.controlled = i == 0;
        const bool moves = b.controlled || u(rng) < 0.7;
        b.r = s.limit_radius * (u(rng) < 0.3 ? 1 : u(rng));
        b.theta_deg = 360 * u(rng) - 180;
        b.facing_deg = 720 * u(rng) - 360;
        if (moves) {
            b.speed = Ranges::kSpeed * (u(rng) < 0.3 ? 1 : u(rng));
            b.direction_deg = 360 * u(rng);
            b.accel = u(rng) < 0.5 ? 1000 * u(rng) : 0;
            b.accel_direction_deg = 360 * u(rng);
        }
        b.spin_deg = 2000 * u(rng) - 1000;
        b.tessellation = 1 + static_cast<int>(16 * u(rng));
        // The largest rho the ranges leave this body, all of it half the time.
        const double room = Ranges::kReach - (moves ? std::max(b.r, s.limit_radius) : b.r);
        const double rho_max = std::min(Ranges::kBodyRadius, std::max(0.0, room)) * (u(rng) < 0.5 ? 1 : u(rng));
        const int n = 1 + static_cast<int>(6 * u(rng));
        for (int k = 0; k < n; ++k)
            b.vertices.push_back({rho_max * (k == 0 ? 1 : u(rng)), 360.0 * k / n + 20 * u(rng)});
        s.bodies.push_back(b);
    }
    return s;
}

template <class W>
bool all_finite(const W& w, std::string& where) {
    using T = typename W::scalar;
    std::vector<geo::Polar<T>> v;
    for (const auto& b : w.bodies) {
        v.resize(b.local.size());
        w.vertices(b, v.data());
        auto bad = [&](geo::Polar<T> p) {
            return !std::isfinite(static_cast<double>(p.r)) || !std::isfinite(static_cast<double>(p.theta));
        };
        bool ok = !bad(b.centre);
        for (std::size_t e = 0; ok && e < v.size(); ++e) {
            ok = !bad(v[e]);
            W::engine::edge_points(w.K, v[e], v[(e + 1) % v.size()], b.desc->tessellation, [&](int, geo::Polar<T> p) {
                if (bad(p))
                    ok = false;
            });
        }
        if (!ok) {
            where = b.desc->name + " at frame " + std::to_string(w.frame)
                    + " at K = " + std::to_string(static_cast<double>(w.K));
            return false;
        }
    }
    return true;
}

// Steps the world `frames` frames with the ship thrusting and turning and K pushed up and down,
// checking after every step what the ranges promise.
// The paper's engine (its formulas, literally) is run for its positions only: its polar
// formulas divide by zero and take acos of rounding errors at K > 0 (geometry/paper.hpp), which
// is what it is there to show.
template <class W>
void run_and_check(W w, int frames, const char* engine, int scene_index, bool finite = true) {
    w.press(world::Action::thrust);
    for (int f = 0; f < frames; ++f) {
        if (f % 40 == 0) {  // K down for a while, then up
            w.release(f % 80 ? world::Action::curvature_down : world::Action::curvature_up);
            w.press(f % 80 ? world::Action::curvature_up : world::Action::curvature_down);
            w.press(f % 80 ? world::Action::left : world::Action::right);
        }
        w.step(1.0 / 60);
        std::string where;
        if (!finite)
            continue;
        ASSERT_TRUE(all_finite(w, where)) << engine << ", scene " << scene_index << ": not finite: " << where;
        for (const auto& b : w.bodies) {
            ASSERT_LE(static_cast<double>(b.centre.r), static_cast<double>(w.R) * (1 + 1e-6) + 1e-4)
                << engine << " " << scene_index;
            ASSERT_LE(static_cast<double>(b.speed), Ranges::kSpeed * (1 + 1e-6) + 1e-4) << engine << " " << scene_index;
        }
    }
}

TEST(Ranges, EveryEngineStaysFiniteOverTheWholeAcceptedRange) {
    std::mt19937 rng(20261125);
    for (int i = 0; i < 60; ++i) {
        const world::Scene s = random_scene(rng);
        std::string why;
        ASSERT_TRUE(world::within_ranges(s, why)) << why;
        if (i % test::kEmulatedStride != 0) continue;  // (every scene is drawn, so the sequence is the same)
        run_and_check(world::World<fixed>(s), 240, "fixed", i);
        run_and_check(world::World<double>(s), 240, "double", i);
        run_and_check(world::World<float>(s), 240, "float", i);
        run_and_check(world::World<double, geo::Paper>(s), 240, "paper", i, false);
    }
}

// Every engine draws within one pixel of the true curve over the whole accepted range: the
// within-one-pixel check (curve_reference.hpp) on a 1920x1080 canvas, K from -1 to 1, the
// antipode included (at K = 1 the limit circle is the antipode).
// One engine over the random scenes (the same scenes for each: the generator starts again),
// each engine its own test so that ctest runs them side by side.
template <class W>
void draws_within_one_pixel(const char* name) {
    std::mt19937 rng(7);
    testing::CurveCheck worst;
    for (int i = 0; i < 120; ++i) {
        world::Scene s = random_scene(rng);
        if (i % 2 != 0 && i != 119) continue;  // (every other one and the last: 61 scenes, six K each)
        for (const double K : {-1.0, -0.5, 0.0, 0.5, 1.0, s.curvature}) {
            s.curvature = K;
            const std::string what = "scene " + std::to_string(i) + " K " + std::to_string(K) + " R " + std::to_string(s.limit_radius);
            const testing::CurveCheck c = testing::check_world(W(s), geo::Projection::azimuthal_equidistant, 1920, 1080);
            EXPECT_LE(c.worst, kWithinPx) << what << " " << name << " body " << c.worst_body;
            EXPECT_LE(c.gap, kGapPx) << what << " " << name << " body " << c.gap_body;
            worst.add(c);
        }
    }
    ::testing::Test::RecordProperty(std::string(name) + "_worst_px", std::to_string(worst.worst));
    std::printf("%s: worst %.3f px from the curve, gap %.3f px (%ld pixels)\n", name, worst.worst, worst.gap, worst.pixels);
}

TEST(Ranges, EveryEngineDrawsWithinOnePixelOverTheWholeAcceptedRangeFixed) { draws_within_one_pixel<world::World<fixed>>("fixed"); }
TEST(Ranges, EveryEngineDrawsWithinOnePixelOverTheWholeAcceptedRangeDouble) { draws_within_one_pixel<world::World<double>>("double"); }
TEST(Ranges, EveryEngineDrawsWithinOnePixelOverTheWholeAcceptedRangeFloat) { draws_within_one_pixel<world::World<float>>("float"); }

// Just past each range: one sentence, from the scene file reader, naming the value.
TEST(Ranges, ValuesJustPastTheRangesAreRefusedWithTheReason) {
    struct Case {
        const char* text;
        const char* says;
    } cases[] = {
        {"limit_radius = 3.15\n", "'limit_radius' must be from 0.001 to 3.14159"},
        {"limit_radius = 3\n[[body]]\nposition = [3.01, 0]\nvertices = [[0.1, 0]]\n",
         "body 'body1': its position r = 3.01 is outside the limit circle (limit_radius = 3): place it at r <= 3"},
        {"[[body]]\nvelocity = [20.01, 0]\nvertices = [[0.1, 0]]\n", "'velocity' must be from 0 to 20"},
        {"[[body]]\nvertices = [[1.41, 0]]\n", "'vertices' must be from 0 to 1.4 (rho, distance from the centre)"},
        {"[[grid]]\nstep = 1.5\n", "'step' must be from 0.001 to 1.4"},
        {"limit_radius = 3\n[[grid]]\nkind = \"axes\"\nlength = 3.5\n",
         "grid: its lines could reach 6.5 from O (the farthest line is 3"},
    };
    for (const Case& c : cases) {
        world::Scene s;
        files::SceneError err;
        EXPECT_FALSE(files::parse_scene(c.text, "s.toml", s, err)) << c.text;
        EXPECT_NE(err.to_string().find(c.says), std::string::npos) << err.to_string();
    }
    // And just inside: read.
    world::Scene s;
    files::SceneError err;
    EXPECT_TRUE(files::parse_scene(
        "limit_radius = 3\n[[body]]\nposition = [3, 0]\nvelocity = [20, 0]\nvertices = [[1.4, 0]]\n", "s.toml", s, err))
        << err.to_string();
}

// The speed ceiling: a body accelerating for ten seconds at the largest acceleration ends at it.
TEST(Ranges, AccelerationStopsAtTheSpeedCeiling) {
    world::Scene s;
    world::SceneBody b;
    b.name = "fast", b.speed = 1, b.accel = 1000, b.vertices = {{0.1, 0}};
    s.bodies.push_back(b);
    world::World<fixed> wf(s);
    world::World<double> wd(s);
    for (int f = 0; f < 600; ++f)
        wf.step(1.0 / 60), wd.step(1.0 / 60);
    EXPECT_NEAR(static_cast<double>(wf.bodies[0].speed), Ranges::kSpeed, 1e-4);
    EXPECT_DOUBLE_EQ(wd.bodies[0].speed, Ranges::kSpeed);
}

// The dump's angles are in (-180, 180] as printed: angles at and just around -pi, +pi and
// their multiples, as the double engine's wrap leaves them, never print as -180.
TEST(Ranges, DumpAnglesNeverPrintAsMinus180) {
    long printed_180 = 0;
    for (const double base : {-kPi, kPi, -3 * kPi, 3 * kPi})
        for (int k = -3000; k <= 3000; ++k) {
            const double rad = base + k * 1e-10;
            std::string out;
            files::detail::polar(out, 1, rad);
            const double deg = std::stod(out.substr(out.find(',') + 1));
            EXPECT_GT(deg, -180) << out << " from " << rad;
            EXPECT_LE(deg, 180) << out << " from " << rad;
            printed_180 += deg == 180;
        }
    EXPECT_GT(printed_180, 0);  // the angles near -pi are there, as +180
}

}  // namespace
}  // namespace noneuclid
