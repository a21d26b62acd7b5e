// The world: physics against the reference model, the limit circle, live curvature and
// actions, determinism, built-in scenes. The world's budget: test_budget.cpp; scene files, input
// files and the dump: tests/files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "geometry/reference.hpp"
#include "files/dump.hpp"
#include "test_common.hpp"
#include "world/world.hpp"

using namespace noneuclid::world;
using namespace noneuclid::files;
using noneuclid::fx::fixed;
using noneuclid::geo::Polar;
using noneuclid::geo::Pose;
namespace ref = noneuclid::geo::ref;

namespace {

using noneuclid::test::kPi;
using noneuclid::test::deg;
using noneuclid::test::angle_diff;
using noneuclid::test::plane_distance;
using noneuclid::test::D;

Scene one_body(double K, double r, double theta_deg, double speed, double dir_deg, double facing_deg = 10,
               double R = kPi) {
    Scene s;
    s.curvature = K;
    s.limit_radius = R;
    SceneBody b;
    b.name = "b";
    b.r = r, b.theta_deg = theta_deg, b.speed = speed, b.direction_deg = dir_deg, b.facing_deg = facing_deg;
    b.vertices = {{0.1, 0}, {0.1, 120}, {0.1, 240}};
    s.bodies.push_back(b);
    return s;
}

// ---- physics ---------------------------------------------------------------------------

template <class T>
void check_coasting(double K) {
    World<T> w(one_body(K, 0.8, 30, 0.5, 75));
    const T speed = w.bodies[0].speed;
    // The length of one step as the engine computes it: float rounds speed * dt; fixed point
    // walks speed times the clock's exact 1/60 s (its remainders carried).
    const double step = std::is_same_v<T, fixed> ? static_cast<double>(speed) / 60 : static_cast<double>(speed * T(1.0 / 60));
    const Pose<double> start{D(w.bodies[0].centre), static_cast<double>(w.bodies[0].travel),
                             static_cast<double>(w.bodies[0].facing)};
    Polar<double> prev = start.centre;
    double worst = 0, worst_spacing = 0;
    for (int i = 1; i <= 120; ++i) {
        w.step(1.0 / 60);
        ASSERT_EQ(w.bodies[0].speed, speed) << "speed is kept exactly while coasting";
        const Polar<double> c = D(w.bodies[0].centre);
        // On the geodesic through the start in its direction of travel, at i equal steps.
        const Pose<double> want = ref::move(K, start, i * step);
        // Each centre is a walk from the coast's start (geo::Coast), so the steps' roundings do
        // not add up: the bound is one walk's rounding, in fixed point the centre's own Q16.16
        // rounding (2^-17 in r and in theta).
        const double tol = std::is_same_v<T, double> ? 1e-12 : (std::is_same_v<T, float> ? 1e-5 : 5e-5);
        // A step's length is then the difference of two walks' roundings: in float a few float
        // steps of the walk's numbers (S_K and C_K, up to 3 here) each; in fixed point two
        // centres' roundings.
        const double spacing_tol = std::is_same_v<T, double> ? 1e-12 : (std::is_same_v<T, float> ? 1e-6 : 5e-5);
        worst = std::max(worst, plane_distance(c, want.centre));
        ASSERT_LE(plane_distance(c, want.centre), tol) << "K=" << K << " step " << i;
        ASSERT_LE(angle_diff(static_cast<double>(w.bodies[0].travel), want.travel), 10 * tol) << "K=" << K;
        worst_spacing = std::max(worst_spacing, std::fabs(ref::distance(K, prev, c) - step));
        ASSERT_NEAR(ref::distance(K, prev, c), step, spacing_tol) << "equal spacing, K=" << K;
        prev = c;
    }
    char key[64], value[32];
    const char* engine = std::is_same_v<T, double> ? "double" : (std::is_same_v<T, float> ? "float" : "fixed");
    std::snprintf(key, sizeof key, "coasting_%s_K%g_worst_distance_from_geodesic", engine, K);
    std::snprintf(value, sizeof value, "%.3g", worst);
    ::testing::Test::RecordProperty(key, value);
    std::snprintf(key, sizeof key, "coasting_%s_K%g_worst_spacing_error", engine, K);
    std::snprintf(value, sizeof value, "%.3g", worst_spacing);
    ::testing::Test::RecordProperty(key, value);
}
TEST(Physics, CoastingKeepsSpeedAndFollowsOneGeodesicInEqualSteps) {
    for (double K : {-1.0, -0.3, 0.0, 0.4, 1.0}) {
        check_coasting<double>(K);
        check_coasting<float>(K);
        check_coasting<fixed>(K);
    }
}

TEST(Physics, ReturnsAfterOneCircumferenceOnTheSphere) {
    // K = 1, speed 2 pi / 6 per second: one circumference in 6 s = 360 steps.
    World<double> w(one_body(1.0, 0.8, 30, 2 * kPi / 6, 75));
    const Body<double> start = w.bodies[0];
    for (int i = 0; i < 360; ++i) w.step(1.0 / 60);
    EXPECT_LE(plane_distance(w.bodies[0].centre, start.centre), 1e-9);
    EXPECT_LE(angle_diff(w.bodies[0].travel, start.travel), 1e-9);
    EXPECT_LE(angle_diff(w.bodies[0].facing, start.facing), 1e-9);
}

TEST(Physics, ThrustAcceleratesAlongTheFacingAndSpinTurns) {
    Scene s = one_body(0.0, 0.0, 0, 0, 0, 90);
    s.bodies[0].controlled = true;
    s.thrust = 0.6;
    World<double> w(s);
    w.press(Action::thrust);
    for (int i = 0; i < 60; ++i) w.step(1.0 / 60);  // 1 s of thrust from rest, facing north
    EXPECT_NEAR(w.bodies[0].speed, 0.6, 1e-12);
    EXPECT_NEAR(w.bodies[0].travel, kPi / 2, 1e-12);
    EXPECT_NEAR(w.bodies[0].centre.r, 0.3, 1e-2);  // ~a t^2 / 2, in 60 discrete steps
    w.release(Action::thrust);
    w.press(Action::left);
    for (int i = 0; i < 60; ++i) w.step(1.0 / 60);
    EXPECT_NEAR(w.bodies[0].speed, 0.6, 1e-12);  // turning does not change the velocity
    EXPECT_NEAR(angle_diff(w.bodies[0].facing, kPi / 2 + deg(s.turn_rate_deg)), 0, 1e-9);
}

// ---- the limit circle ------------------------------------------------------------------------

TEST(LimitCircle, ACentrePastRReappearsOppositeWithTheSameDirections) {
    for (double K : {-1.0, -0.5, 0.0, 0.3}) {  // K = 0.3: pi/sqrt K > R, so the rule applies
        World<double> w(one_body(K, 3.1, 20, 1.0, 20, 55));
        double before_travel = 0, before_facing = 0;
        bool wrapped = false;
        for (int i = 0; i < 10 && !wrapped; ++i) {
            const Body<double> b = w.bodies[0];
            w.step(1.0 / 60);
            if (std::fabs(angle_diff(w.bodies[0].centre.theta, b.centre.theta) - kPi) < 1e-6) {
                wrapped = true;
                // What the step would have reached without the rule:
                const Pose<double> free = noneuclid::geo::move(K, Pose<double>{b.centre, b.travel, b.facing}, 1.0 / 60);
                EXPECT_GT(free.centre.r, w.R);
                EXPECT_NEAR(w.bodies[0].centre.r, 2 * w.R - free.centre.r, 1e-12);
                EXPECT_NEAR(angle_diff(w.bodies[0].centre.theta, free.centre.theta + kPi), 0, 1e-12);
                before_travel = free.travel, before_facing = free.facing;
                EXPECT_NEAR(angle_diff(w.bodies[0].travel, before_travel), 0, 1e-12) << "travel unchanged on screen";
                EXPECT_NEAR(angle_diff(w.bodies[0].facing, before_facing), 0, 1e-12) << "facing unchanged on screen";
            }
        }
        EXPECT_TRUE(wrapped) << "K=" << K;
        EXPECT_LE(w.bodies[0].centre.r, w.R);
    }
}

// At K > 0 with R = pi/sqrt K the rule is the geodesic itself continuing through the antipode:
// the world (no special case there) agrees with the reference model walking straight on.
TEST(LimitCircle, OnTheSphereTheRuleIsTheGeodesicThroughTheAntipode) {
    for (double K : {1.0, 0.5}) {
        const double R = kPi / std::sqrt(K);
        World<double> w(one_body(K, R - 0.2, 40, 1.0, 40, 70, R));
        const Pose<double> start{w.bodies[0].centre, w.bodies[0].travel, w.bodies[0].facing};
        for (int i = 1; i <= 30; ++i) {  // 0.5 units: through the antipode and 0.3 beyond
            w.step(1.0 / 60);
            const Pose<double> want = ref::move(K, start, i / 60.0);
            // (on the sphere: at the antipode itself every theta is the same point)
            EXPECT_LE(ref::distance(K, w.bodies[0].centre, want.centre), 1e-9) << "K=" << K << " step " << i;
            EXPECT_LE(w.bodies[0].centre.r, R + 1e-12);
        }
        // Past the antipode: opposite side, radius 2R - (R - 0.2 + 0.5) = R - 0.3, travel unchanged.
        EXPECT_NEAR(w.bodies[0].centre.r, R - 0.3, 1e-9);
        EXPECT_NEAR(angle_diff(w.bodies[0].centre.theta, deg(40 + 180)), 0, 1e-9);
        EXPECT_NEAR(angle_diff(w.bodies[0].travel, deg(40)), 0, 1e-9);
    }
}

// ---- curvature and actions -------------------------------------------------------------------

TEST(Actions, CurvatureChangesLiveAndLeavesPolarNumbersAlone) {
    Scene s = one_body(0.0, 1.0, 30, 0, 0);
    s.curvature_rate = 0.5;
    World<double> w(s);
    const Body<double> before = w.bodies[0];
    w.press(Action::curvature_down);
    for (int i = 0; i < 60; ++i) w.step(1.0 / 60);
    EXPECT_NEAR(w.K, -0.5, 1e-12);  // 0.5 per second
    EXPECT_EQ(w.bodies[0].centre.r, before.centre.r);
    EXPECT_EQ(w.bodies[0].centre.theta, before.centre.theta);
    EXPECT_EQ(w.bodies[0].facing, before.facing);
    for (int i = 0; i < 240; ++i) w.step(1.0 / 60);
    EXPECT_EQ(w.K, -1.0);  // clamped
    w.release(Action::curvature_down);
    w.press(Action::curvature_up);
    for (int i = 0; i < 600; ++i) w.step(1.0 / 60);
    EXPECT_EQ(w.K, 1.0);
}

TEST(Actions, PresetsCycleAndResetRestores) {
    Scene s = one_body(-0.3, 1.0, 30, 0.5, 10);
    World<double> w(s);
    w.press(Action::preset);
    EXPECT_EQ(w.K, 0.0);
    w.release(Action::preset);
    w.press(Action::preset);
    EXPECT_EQ(w.K, 1.0);
    w.press(Action::preset);
    EXPECT_EQ(w.K, -1.0);
    for (int i = 0; i < 30; ++i) w.step(1.0 / 60);
    w.press(Action::reset);
    EXPECT_EQ(w.K, -0.3);
    EXPECT_EQ(w.bodies[0].centre.r, 1.0);
    s.presets = {0.25, 0.75};
    World<double> w2(s);
    w2.press(Action::preset);
    EXPECT_EQ(w2.K, 0.25);
}

// Same scene, same actions: the same dump, byte for byte, for every engine (every frame's; under
// emulation every kEmulatedStride-th frame's and the last).
struct Press {
    double time;
    Action action;
    bool down;
};
template <class W>
std::string run(const Scene& s, const std::vector<Press>& presses, int frames) {
    W w(s);
    std::string out;
    std::size_t next = 0;
    auto apply_due = [&] {
        for (; next < presses.size() && presses[next].time <= w.time + 1e-9; ++next)
            presses[next].down ? w.press(presses[next].action) : w.release(presses[next].action);
    };
    apply_due();
    dump_frame(w, {}, out);
    for (int i = 0; i < frames; ++i) {
        w.step(1.0 / 60);
        apply_due();
        if (i % noneuclid::test::kEmulatedStride == 0 || i == frames - 1) dump_frame(w, {}, out);
    }
    return out;
}
TEST(Determinism, SameActionsSameResultBitForBit) {
    Scene s;
    ASSERT_TRUE(builtin_scene("kiosk", {}, s));
    const std::vector<Press> ev = {{0.1, Action::thrust, true},          {0.5, Action::left, true},
                                   {0.9, Action::thrust, false},         {1.0, Action::curvature_down, true},
                                   {1.4, Action::curvature_down, false}, {1.5, Action::preset, true},
                                   {1.5, Action::preset, false},    {1.7, Action::spherical, true}};
    EXPECT_EQ(run<World<fixed>>(s, ev, 120), run<World<fixed>>(s, ev, 120));
    EXPECT_EQ(run<World<double>>(s, ev, 120), run<World<double>>(s, ev, 120));
    using PaperWorld = World<double, noneuclid::geo::Paper>;
    EXPECT_EQ(run<PaperWorld>(s, ev, 60), run<PaperWorld>(s, ev, 60));
    // and the actions did something
    EXPECT_NE(run<World<fixed>>(s, ev, 120), run<World<fixed>>(s, {}, 120));
}

TEST(Actions, HyperbolicFlatSphericalSetKOnThePress) {
    Scene s = one_body(-0.3, 1.0, 30, 0.5, 10);
    World<double> w(s);
    w.press(Action::spherical);
    EXPECT_EQ(w.K, 1.0);
    w.release(Action::spherical);
    w.press(Action::hyperbolic);
    EXPECT_EQ(w.K, -1.0);
    w.press(Action::flat);
    EXPECT_EQ(w.K, 0.0);
    for (Action a : {Action::spherical, Action::hyperbolic, Action::flat, Action::preset, Action::reset})
        EXPECT_TRUE(acts_on_press(a)) << action_name(a);
    for (Action a : {Action::thrust, Action::left, Action::right, Action::curvature_up, Action::curvature_down,
                     Action::fire})
        EXPECT_FALSE(acts_on_press(a)) << action_name(a);
}

// ---- scenes ------------------------------------------------------------------------------------

TEST(Scenes, EveryBuiltInSceneBuildsAndRuns) {
    for (const std::string& name : builtin_scene_names()) {
        Scene s;
        const SceneParams small{20, 5, 4};
        ASSERT_TRUE(builtin_scene(name, small, s)) << name;
        if (s.space) continue;  // (the 3D world makes its own bodies: tests/app/test_space_session.cpp)
        EXPECT_FALSE(s.bodies.empty() && s.measures.empty()) << name;  // (fig2 is an instrument alone)
        World<fixed> w(s);
        for (int i = 0; i < 30; ++i) w.step(1.0 / 60);
        std::string out;
        dump_frame(w, {}, out);
        EXPECT_EQ(out.find("null"), std::string::npos) << name;  // no NaN, nothing hidden
    }
    Scene s;
    EXPECT_FALSE(builtin_scene("fig99", {}, s));
    const SceneParams seven{7, 5, 3};
    ASSERT_TRUE(builtin_scene("stress", seven, s));
    ASSERT_EQ(s.bodies.size(), 7u);
    EXPECT_EQ(s.bodies[0].vertices.size(), 5u);
    EXPECT_EQ(s.bodies[0].tessellation, 3);
}

TEST(Scenes, Fig16IsThePapersSquareAtNinetyPaperPixels) {
    Scene s;
    ASSERT_TRUE(builtin_scene("fig16", {}, s));
    const SceneBody& sq = s.bodies.back();
    ASSERT_EQ(sq.vertices.size(), 4u);
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(sq.vertices[static_cast<std::size_t>(i)].rho, kPi / 6, 1e-12);  // 90 px at 540 px = pi
        // Equally spaced, as the paper's text says (its vertex list, pi/8 + k pi/4, spans only
        // 135 degrees; docs/rendering.md): pi/8 + k pi/2.
        EXPECT_NEAR(sq.vertices[static_cast<std::size_t>(i)].phi_deg, 22.5 + 90.0 * i, 1e-12);
    }
}

// Grid lines are geodesics: every vertex of "grid x=1" is on the geodesic perpendicular to the
// x axis at distance 1, for any K (and so they bend as K changes).
TEST(Scenes, GridLinesAreTheGeodesicsPerpendicularToTheAxes) {
    Scene s;
    s.limit_radius = kPi;
    std::string why;
    ASSERT_TRUE(add_axis_grid(s, 1.0, 2.0, 0.5, {1, 2, 3}, why)) << why;
    const SceneBody* line = nullptr;
    for (const SceneBody& b : s.bodies)
        if (b.name == "grid x=1") line = &b;
    ASSERT_NE(line, nullptr);
    for (double K : {-1.0, 0.0, 0.7}) {
        World<double> w(s);
        w.K = K;
        std::size_t checked = 0;  // the line's vertices, checked below
        for (const Body<double>& b : w.bodies) {
            if (b.desc != line && b.desc->name != "grid x=1") continue;
            checked += b.local.size();
            std::vector<Polar<double>> v(b.local.size());
            w.vertices(b, v.data());
            const Polar<double> foot{1.0, 0.0};
            for (std::size_t i = 0; i < v.size(); ++i) {
                // distance from the foot equals rho, and the bearing is perpendicular to the axis
                EXPECT_NEAR(ref::distance(K, foot, v[i]), b.local[i].r, 1e-12);
                if (b.local[i].r > 0) {
                    EXPECT_NEAR(std::fabs(std::sin(ref::bearing(K, foot, v[i]))), 1.0, 1e-12) << "K=" << K;
                }
            }
        }
        EXPECT_EQ(checked, line->vertices.size()) << "K=" << K << ": the world has the grid line's body, once";
        EXPECT_GE(checked, 3u) << "K=" << K;
    }
}

}  // namespace
