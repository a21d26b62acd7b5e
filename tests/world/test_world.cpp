// The world: physics against the reference model, the limit circle, live curvature and
// actions, determinism, built-in scenes, scene files and their errors, the dump.
#include <gtest/gtest.h>
#include <sys/stat.h>  // mkfifo

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "geometry/reference.hpp"
#include "world/budget.hpp"
#include "world/dump.hpp"
#include "world/scene_file.hpp"
#include "world/text_file.hpp"
#include "world/world.hpp"

using namespace noneuclid::world;
using noneuclid::fx::fixed;
using noneuclid::geo::Polar;
using noneuclid::geo::Pose;
namespace ref = noneuclid::geo::ref;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;

double angle_diff(double a, double b) { return std::fabs(std::remainder(a - b, 2 * kPi)); }
double plane_distance(Polar<double> a, Polar<double> b) {
    return std::hypot(a.r * std::cos(a.theta) - b.r * std::cos(b.theta), a.r * std::sin(a.theta) - b.r * std::sin(b.theta));
}
template <class T>
Polar<double> D(Polar<T> p) {
    return {static_cast<double>(p.r), static_cast<double>(p.theta)};
}

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
    // The length of one step as the engine computes it (in fixed point speed * dt is rounded).
    const double step = static_cast<double>(speed * T(1.0 / 60));
    const Pose<double> start{D(w.bodies[0].centre), static_cast<double>(w.bodies[0].travel),
                             static_cast<double>(w.bodies[0].facing)};
    Polar<double> prev = start.centre;
    double worst = 0, worst_spacing = 0;
    for (int i = 1; i <= 120; ++i) {
        w.step(T(1.0 / 60));
        ASSERT_EQ(w.bodies[0].speed, speed) << "speed is kept exactly while coasting";
        const Polar<double> c = D(w.bodies[0].centre);
        // On the geodesic through the start in its direction of travel, at i equal steps.
        const Pose<double> want = ref::move(K, start, i * step);
        // Each centre is a walk from the coast's start (world::Coast), so the steps' roundings do
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
    w.press(Action::turn_left);
    for (int i = 0; i < 60; ++i) w.step(1.0 / 60);
    EXPECT_NEAR(w.bodies[0].speed, 0.6, 1e-12);  // turning does not change the velocity
    EXPECT_NEAR(angle_diff(w.bodies[0].facing, kPi / 2 + s.turn_rate_deg * kDeg), 0, 1e-9);
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
        EXPECT_NEAR(angle_diff(w.bodies[0].centre.theta, (40 + 180) * kDeg), 0, 1e-9);
        EXPECT_NEAR(angle_diff(w.bodies[0].travel, 40 * kDeg), 0, 1e-9);
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
    w.press(Action::next_preset);
    EXPECT_EQ(w.K, 0.0);
    w.release(Action::next_preset);
    w.press(Action::next_preset);
    EXPECT_EQ(w.K, 1.0);
    w.press(Action::next_preset);
    EXPECT_EQ(w.K, -1.0);
    for (int i = 0; i < 30; ++i) w.step(1.0 / 60);
    w.press(Action::reset);
    EXPECT_EQ(w.K, -0.3);
    EXPECT_EQ(w.bodies[0].centre.r, 1.0);
    s.presets = {0.25, 0.75};
    World<double> w2(s);
    w2.press(Action::next_preset);
    EXPECT_EQ(w2.K, 0.25);
}

// Same scene, same actions: the same dump, byte for byte, for every engine.
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
        w.step(typename W::scalar(1.0 / 60));
        apply_due();
        dump_frame(w, {}, out);
    }
    return out;
}
TEST(Determinism, SameActionsSameResultBitForBit) {
    Scene s;
    ASSERT_TRUE(builtin_scene("kiosk", {}, s));
    const std::vector<Press> ev = {{0.1, Action::thrust, true},          {0.5, Action::turn_left, true},
                                   {0.9, Action::thrust, false},         {1.0, Action::curvature_down, true},
                                   {1.4, Action::curvature_down, false}, {1.5, Action::next_preset, true},
                                   {1.5, Action::next_preset, false},    {1.7, Action::spherical, true}};
    EXPECT_EQ(run<World<fixed>>(s, ev, 120), run<World<fixed>>(s, ev, 120));
    EXPECT_EQ(run<World<double>>(s, ev, 120), run<World<double>>(s, ev, 120));
    using PaperWorld = World<double, true>;
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
    for (Action a : {Action::spherical, Action::hyperbolic, Action::flat, Action::next_preset, Action::reset})
        EXPECT_TRUE(acts_on_press(a)) << action_name(a);
    for (Action a : {Action::thrust, Action::turn_left, Action::turn_right, Action::curvature_up, Action::curvature_down,
                     Action::fire})
        EXPECT_FALSE(acts_on_press(a)) << action_name(a);
}

// ---- scenes ------------------------------------------------------------------------------------

TEST(Scenes, EveryBuiltInSceneBuildsAndRuns) {
    for (const char* const* n = builtin_scene_names(); *n; ++n) {
        Scene s;
        const SceneParams small{20, 5, 4};
        ASSERT_TRUE(builtin_scene(*n, small, s)) << *n;
        EXPECT_FALSE(s.bodies.empty()) << *n;
        World<fixed> w(s);
        for (int i = 0; i < 30; ++i) w.step(fixed(1.0 / 60));
        std::string out;
        dump_frame(w, {}, out);
        EXPECT_EQ(out.find("null"), std::string::npos) << *n;  // no NaN, nothing hidden
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

// ---- scene files -------------------------------------------------------------------------------

const char* kExample = R"(curvature = -1.0            # K in [-1, 1]
limit_radius = 3.14159      # R in world units
[[body]]
name = "ship"
position = [0.5, 30.0]      # [r, theta deg]
facing = 90.0
velocity = [0.2, 90.0]
spin = 0.0
color = "#ff4040"
closed = true
tessellation = 8
vertices = [[0.1, 0.0], [0.1, 140.0], [0.1, 220.0]]
)";

TEST(SceneFile, TheDocumentedExampleLoads) {
    Scene s;
    SceneError err;
    ASSERT_TRUE(parse_scene(kExample, "ship.toml", s, err)) << err.to_string();
    EXPECT_EQ(s.curvature, -1.0);
    EXPECT_EQ(s.limit_radius, 3.14159);
    ASSERT_EQ(s.bodies.size(), 1u);
    const SceneBody& b = s.bodies[0];
    EXPECT_EQ(b.name, "ship");
    EXPECT_EQ(b.r, 0.5);
    EXPECT_EQ(b.theta_deg, 30.0);
    EXPECT_EQ(b.speed, 0.2);
    EXPECT_EQ(b.color, (Rgb{255, 64, 64}));
    EXPECT_TRUE(b.controlled);  // a body named ship is the one the buttons fly
    ASSERT_EQ(b.vertices.size(), 3u);
    EXPECT_EQ(b.vertices[1].phi_deg, 140.0);
}

struct BadCase {
    const char* text;
    long line, column;
    const char* says;
};
TEST(SceneFile, EveryErrorNamesItsPlaceWhatWasExpectedAndWhatWasFound) {
    const BadCase cases[] = {
        {"curvature = \n", 1, 13, "not valid TOML"},
        {"curvature = 2.0\n", 1, 13, "'curvature' must be from -1 to 1 (K), found 2"},
        {"curvature = \"flat\"\n", 1, 13, "expected a number for 'curvature' (K), found a string"},
        {"curvture = 0.5\n", 1, 1, "unknown key 'curvture'"},
        {"limit_radius = -1\n", 1, 16, "'limit_radius' must be from"},
        {"presets = \"all\"\n", 1, 11, "expected presets = [K, ...]"},
        {"presets = [0, 3]\n", 1, 15, "'presets' must be from -1 to 1"},
        {"body = 3\n", 1, 8, "expected [[body]] tables, found an integer"},
        {"[[body]]\nname = \"a\"\n", 1, 1, "body 'a': expected 'vertices' = [[rho, phi], ...], found none"},
        {"[[body]]\nname = \"a\"\nvertices = []\n", 3, 12, "with at least one vertex, found an empty array"},
        {"[[body]]\nname = \"a\"\nvertices = [[0.1]]\n", 3, 13, "expected each vertex as [rho, phi in degrees], found an array of 1"},
        {"[[body]]\nname = \"a\"\nvertices = [[-0.1, 0]]\n", 3, 14, "'vertices' must be from 0"},
        {"[[body]]\nname = \"a\"\nvertices = [[0.1, \"x\"]]\n", 3, 19, "expected a number for 'vertices'"},
        {"[[body]]\nname = \"a\"\nposition = [1]\nvertices = [[0.1, 0]]\n", 3, 12, "expected 'position' = [r, theta in degrees], found an array of 1"},
        {"[[body]]\nname = \"a\"\ncolor = \"red\"\nvertices = [[0.1, 0]]\n", 3, 9, "expected a colour \"#rrggbb\" for 'color', found \"red\""},
        {"[[body]]\nname = \"a\"\nclosed = 1\nvertices = [[0.1, 0]]\n", 3, 10, "expected true or false for 'closed', found an integer"},
        {"[[body]]\nname = \"a\"\ntessellation = 0\nvertices = [[0.1, 0]]\n", 3, 16, "'tessellation' must be from 1 to 256"},
        {"[[body]]\nname = \"a\"\ntessellation = 2.5\nvertices = [[0.1, 0]]\n", 3, 16, "expected a whole number for 'tessellation'"},
        {"[[body]]\nname = \"a\"\nfacing = [90]\nvertices = [[0.1, 0]]\n", 3, 10, "expected a number for 'facing' (degrees), found an array"},
        {"[[body]]\nname = \"a\"\nspeed = 1\nvertices = [[0.1, 0]]\n", 3, 1, "body 'a': unknown key 'speed'"},
        {"[[body]]\nname = 7\nvertices = [[0.1, 0]]\n", 2, 8, "expected a string for 'name', found an integer"},
        {"[[grid]]\nkind = \"hex\"\n", 2, 8, "grid: expected kind = \"axes\" or \"radial\", found \"hex\""},
        {"[[grid]]\nspacing = 0\n", 2, 11, "'spacing' must be from"},
    };
    for (const BadCase& c : cases) {
        Scene s;
        SceneError err;
        EXPECT_FALSE(parse_scene(c.text, "s.toml", s, err)) << c.text;
        EXPECT_EQ(err.line, c.line) << c.text << " -> " << err.to_string();
        EXPECT_EQ(err.column, c.column) << c.text << " -> " << err.to_string();
        EXPECT_NE(err.message.find(c.says), std::string::npos) << c.text << " -> " << err.to_string();
        EXPECT_EQ(err.to_string().rfind("s.toml:" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": ", 0), 0u)
            << err.to_string();
    }
    Scene s;
    SceneError err;
    EXPECT_FALSE(load_scene_file("/nonexistent/scene.toml", s, err));
    EXPECT_EQ(err.to_string().rfind("/nonexistent/scene.toml: the scene file: cannot read it", 0), 0u) << err.to_string();
}

TEST(SceneFile, GridsAndExtensions) {
    Scene s;
    SceneError err;
    ASSERT_TRUE(parse_scene("presets = [-0.5, 0.5]\nsweep_rate = 0.2\n[[grid]]\nkind = \"radial\"\nlines = 8\n"
                            "[[body]]\nvertices = [[0.1, 0]]\nacceleration = [0.1, 45]\ncontrolled = true\n",
                            "g.toml", s, err))
        << err.to_string();
    EXPECT_EQ(s.presets, (std::vector<double>{-0.5, 0.5}));
    EXPECT_EQ(s.bodies.size(), 9u);
    EXPECT_TRUE(s.bodies[0].grid);
    EXPECT_EQ(s.bodies.back().name, "body1");
    EXPECT_EQ(s.bodies.back().accel, 0.1);
    EXPECT_TRUE(s.bodies.back().controlled);
}

// ---- the dump ----------------------------------------------------------------------------------

TEST(Dump, EdgesListTheirPointsEndsIncludedAndScreenMirrorsThem) {
    Scene s = one_body(0.0, 1.0, 0, 0, 0, 90);
    s.bodies[0].tessellation = 4;
    World<double> w(s);
    std::string out;
    dump_frame(w, {200, 100, noneuclid::geo::Projection::azimuthal_equidistant}, out);
    // 3 closed edges of 5 points; screen: R = pi fills 50 px (half the smaller side)
    EXPECT_EQ(out.rfind("{\"frame\":0,\"t\":0,\"K\":0,\"bodies\":[{\"name\":\"b\",\"kind\":\"body\",\"center\":[1,0],\"facing\":90,", 0),
              0u)
        << out;
    EXPECT_NE(out.find("\"travel\":[0,0]"), std::string::npos);
    const std::size_t edges = out.find("\"edges\":["), screen = out.find("\"screen\":[");
    ASSERT_NE(edges, std::string::npos);
    ASSERT_NE(screen, std::string::npos);
    const std::string e = out.substr(edges, screen - edges), sc = out.substr(screen);
    EXPECT_EQ(std::count(e.begin(), e.end(), '['), 1 + 3 + 15);   // the list, 3 edges, 15 points
    EXPECT_EQ(std::count(sc.begin(), sc.end(), '['), 1 + 3 + 15);
    // the first vertex: centre (1, 0) plus 0.1 north (facing 90) -> x = 100 + 50/pi * 1, y = 50 - 50/pi * 0.1
    char want[64];
    std::snprintf(want, sizeof want, "\"screen\":[[[%.9g,%.9g]", 100 + 50 / kPi * 1.0, 50 - 50 / kPi * 0.1);
    EXPECT_NE(out.find(want), std::string::npos) << out.substr(screen, 80) << " vs " << want;
    EXPECT_EQ(out.back(), '\n');
}

}  // namespace

// ---- input files ----------------------------------------------------------------------------

// Only a regular file within its limit is read: a FIFO does not block (it is not opened), a
// directory or a device is not read as an empty or endless file.
TEST(InputFiles, OnlyRegularFilesWithinTheLimit) {
    const std::string dir = ::testing::TempDir() + "input_files";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string fifo = dir + "/fifo", big = dir + "/big.toml", small = dir + "/small.toml";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    { std::ofstream(big) << std::string(kSceneFileLimit + 1, '#'); }
    { std::ofstream(small) << "curvature = 0.5\n"; }
    std::string text, why;
    EXPECT_FALSE(read_text_file(fifo, kSceneFileLimit, "a scene file", text, why));
    EXPECT_NE(why.find("not a regular file"), std::string::npos) << why;
    EXPECT_FALSE(read_text_file(dir, kSceneFileLimit, "a scene file", text, why));
    EXPECT_EQ(why, "it is a directory, not a file");
    EXPECT_FALSE(read_text_file("/dev/zero", kSceneFileLimit, "a scene file", text, why));
    EXPECT_NE(why.find("not a regular file"), std::string::npos) << why;
    EXPECT_FALSE(read_text_file(big, kSceneFileLimit, "a scene file", text, why));
    EXPECT_EQ(why, "it is 1048577 bytes, over the 1 MiB a scene file may have");
    EXPECT_FALSE(read_text_file(dir + "/none", kSceneFileLimit, "a scene file", text, why));
    EXPECT_NE(why.find("cannot read it (No such file or directory)"), std::string::npos) << why;
    ASSERT_TRUE(read_text_file(small, kSceneFileLimit, "a scene file", text, why)) << why;
    EXPECT_EQ(text, "curvature = 0.5\n");
    // Through the scene loader: one sentence with the path.
    Scene s;
    SceneError err;
    EXPECT_FALSE(load_scene_file(fifo, s, err));
    EXPECT_EQ(err.to_string().rfind(fifo + ": the scene file: it is not a regular file", 0), 0u) << err.to_string();
}

// ---- the world's budget -----------------------------------------------------------------------

// Values each within their range can multiply past what a world may hold: refused with a
// sentence, before anything is allocated, whatever the product (here up to 4e13 vertices).
TEST(Budget, GridsAndTheStressSceneOverItAreRefusedBeforeAnythingIsBuilt) {
    Scene s;
    s.limit_radius = 1e4;
    std::string why;
    EXPECT_FALSE(add_axis_grid(s, 0.01, 1e4, 0.001, {1, 2, 3}, why));
    EXPECT_TRUE(s.bodies.empty());
    EXPECT_EQ(why, "it would have 20,000,001 vertices in one body, over the 10,000 a world may have: use fewer vertices "
                   "(a larger spacing or step, a shorter length, fewer lines)");
    s.limit_radius = kPi;
    EXPECT_FALSE(add_radial_grid(s, 360, 10, 0.002, {1, 2, 3}, why));  // 360 lines of 5,001 vertices
    EXPECT_NE(why.find("1,800,360 vertices, over the 524,288"), std::string::npos) << why;
    EXPECT_TRUE(s.bodies.empty());
    // Many lines, each small: the count of bodies.
    s.limit_radius = 1e4;
    EXPECT_FALSE(add_axis_grid(s, 0.01, 0.1, 0.05, {1, 2, 3}, why));
    EXPECT_NE(why.find("4,000,002 bodies, over the 20,000"), std::string::npos) << why;
    // The stress scene's parameters, each at its documented maximum.
    Scene stress;
    EXPECT_FALSE(builtin_scene("stress", {100000, 10000, 256}, stress, &why));
    EXPECT_EQ(why.rfind("the stress scene: it would have ", 0), 0u) << why;
    EXPECT_TRUE(stress.bodies.empty());
    EXPECT_FALSE(builtin_scene("stress", {4000, 200, 8}, stress, &why));  // 800,000 vertices
    EXPECT_NE(why.find("800,000 vertices"), std::string::npos) << why;
    // Just within: built, and within_budget agrees.
    ASSERT_TRUE(builtin_scene("stress", {2000, 64, 8}, stress, &why)) << why;
    EXPECT_TRUE(within_budget(stress, why)) << why;
    // Every built-in scene is well within.
    for (const char* const* n = builtin_scene_names(); *n; ++n) {
        Scene b;
        ASSERT_TRUE(builtin_scene(*n, {}, b, &why)) << *n;
        EXPECT_TRUE(within_budget(b, why)) << *n << ": " << why;
    }
}

TEST(Budget, ASceneFileOverItNamesTheGridAndWhatToLower) {
    Scene s;
    SceneError err;
    // 2 (2 * 314 + 1) = 1,258 lines (spacing 0.01 over R = pi), each 2 * 3,142 + 1 = 6,285 vertices
    // (a vertex every 0.001 along pi each way).
    EXPECT_FALSE(parse_scene("[[grid]]\nkind = \"axes\"\nspacing = 0.01\nstep = 0.001\n", "big.toml", s, err));
    EXPECT_EQ(err.to_string(), "big.toml:1:1: grid: it would have 7,906,530 vertices, over the 524,288 a world may have: "
                               "use fewer bodies or vertices (a larger spacing or step, a shorter length, fewer lines)");
    // Points: few bodies, but each tessellated finely.
    std::string text = "[[body]]\nname = \"b\"\ntessellation = 256\nvertices = [";
    for (int i = 0; i < 5000; ++i) text += (i ? ", " : "") + std::string("[0.1, ") + std::to_string(i * 0.072) + "]";
    text += "]\n";
    ASSERT_TRUE(parse_scene(text, "fine.toml", s, err)) << err.to_string();
    std::string why;
    EXPECT_FALSE(within_budget(s, why));
    EXPECT_EQ(why, "it would have 1,280,001 points to draw a frame, over the 1,048,576 a world may have: use fewer "
                   "bodies or vertices, or a lower tessellation");
}
