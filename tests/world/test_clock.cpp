// The world's clock (world/world.hpp, geo::Tick): world time is exactly dt a frame in every
// engine, and what moves at a rate (speed * dt along a coast, spin * dt) follows it. In fixed
// point dt = 1/60 s rounds to 1092/65536 in Q16.16, 0.015% short, and a slow spin's spin * dt to
// nothing; each step therefore moves by its exact share of the clock, remainders carried
// (issue 33). The reference is the double engine, whose steps are the clock's, given the same
// rates: the scenes' numbers sit on the Q16.16 grid, so that both engines solve one problem.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "geometry/geometry.hpp"
#include "test_common.hpp"
#include "world/world.hpp"

using namespace noneuclid::world;
using noneuclid::fx::fixed;
using noneuclid::test::angle_diff;
using noneuclid::test::kPi;

namespace {

double on_grid(double x) { return fixed(x).to_double(); }
// Degrees whose radians are on the Q16.16 grid.
double grid_deg(double degrees) { return on_grid(degrees * kPi / 180) * 180 / kPi; }

// Bodies that coast and spin: speeds 0 to 2 units a second, spins from 0.02 to 90 degrees a
// second either way, centres, directions and facings spread round O.
Scene clock_scene(double K) {
    Scene s;
    s.curvature = K;
    s.limit_radius = kPi;
    const double speeds[] = {0, 0.3, 0.5, 1, 2, 0};
    const double spins[] = {0.02, 0.2, -25, 90, -0.2, 7.5};
    for (int i = 0; i < 6; ++i) {
        SceneBody b;
        b.name = "b" + std::to_string(i);
        b.r = on_grid(0.3 + 0.4 * i), b.theta_deg = grid_deg(-150 + 55 * i);
        b.speed = on_grid(speeds[i]), b.direction_deg = grid_deg(20 + 61 * i);
        b.facing_deg = grid_deg(10 * i), b.spin_deg = grid_deg(spins[i]);
        b.vertices = {{0.1, 0}, {0.1, 120}, {0.1, 240}};
        s.bodies.push_back(b);
    }
    return s;
}

// World time is the sum of the steps' dt, the same number in every engine: after 60 frames of
// 1/60 s, 1 s (it was 0.999755859 in fixed point).
TEST(Clock, WorldTimeIsTheClockInEveryEngine) {
    const Scene s = clock_scene(0);
    World<fixed> f(s);
    World<double> d(s);
    World<float> fl(s);
    for (int i = 0; i < 60; ++i) f.step(1.0 / 60), d.step(1.0 / 60), fl.step(1.0 / 60);
    EXPECT_NEAR(f.time, 1.0, 1e-12);
    EXPECT_EQ(f.time, d.time);
    EXPECT_EQ(fl.time, d.time);
}

// A body at speed 1 from O in the plane is at r = 1 after one second (it was 2.4e-4 short):
// within the centre's Q16.16 rounding.
TEST(Clock, AFixedBodyCoversItsSpeedInTime) {
    Scene s;
    s.limit_radius = kPi;
    SceneBody b;
    b.speed = 1, b.direction_deg = 0;
    b.vertices = {{0.1, 0}, {0.1, 120}, {0.1, 240}};
    s.bodies.push_back(b);
    World<fixed> w(s);
    for (int i = 0; i < 60; ++i) w.step(1.0 / 60);
    EXPECT_NEAR(w.bodies[0].centre.r.to_double(), 1.0, noneuclid::test::kHalfStep + 1e-12);
    for (int i = 0; i < 120; ++i) w.step(1.0 / 60);
    EXPECT_NEAR(w.bodies[0].centre.r.to_double(), 3.0, noneuclid::test::kHalfStep + 1e-12);
}

// Spins turn at their rate: after 10 s, 0.02 degrees a second has turned 0.2 degrees (it never
// turned), 0.2 has turned 2 (2.098: 4.9% fast), -25 ends at 110 degrees (110.31). The bound:
// the spin's own Q16.16 rounding (at most 2^-17 rad/s) over the time, and one step.
TEST(Clock, SpinsTurnAtTheirRates) {
    for (const double spin : {0.02, 0.2, -25.0, 1e-3, 360.0}) {
        Scene s;
        SceneBody b;
        b.spin_deg = spin;
        b.vertices = {{0.1, 0}, {0.1, 120}, {0.1, 240}};
        s.bodies.push_back(b);
        World<fixed> w(s);
        for (int frames : {600, 10000}) {
            while (w.frame < frames) w.step(1.0 / 60);
            const double t = frames / 60.0, want = spin * t * kPi / 180;
            const double tol = t * 0x1p-17 + 0x1p-16;
            EXPECT_LE(angle_diff(w.bodies[0].facing.to_double(), want), tol) << spin << " deg/s after " << frames << " frames";
        }
    }
}

// Over 10^4 frames (2.8 minutes) the fixed world follows the double world: the same time, every
// centre and facing within the fixed engine's long-run bound (docs/accuracy.md, "The long run":
// 1e-3 world units after 10^4 steps; the facing likewise in radians), at K = -1, 0 and +1.
TEST(Clock, FixedFollowsDoubleForTenThousandFrames) {
    for (const double K : {-1.0, 0.0, 1.0}) {
        const Scene s = clock_scene(K);
        World<fixed> f(s);
        World<double> d(s);
        double worst_centre = 0, worst_facing = 0;
        for (int i = 1; i <= 10000; ++i) {
            f.step(1.0 / 60), d.step(1.0 / 60);
            if (i % 100 != 0) continue;
            ASSERT_EQ(f.time, d.time);
            for (std::size_t k = 0; k < d.bodies.size(); ++k) {
                const noneuclid::geo::Polar<double> c{f.bodies[k].centre.r.to_double(), f.bodies[k].centre.theta.to_double()};
                worst_centre = std::max(worst_centre, noneuclid::geo::distance(K, c, d.bodies[k].centre));
                worst_facing = std::max(worst_facing, angle_diff(f.bodies[k].facing.to_double(), d.bodies[k].facing));
            }
        }
        EXPECT_LE(worst_centre, 1e-3) << "K = " << K;
        EXPECT_LE(worst_facing, 1e-3) << "K = " << K;
        std::printf("K = %g: after 10^4 frames, centres within %.3g, facings within %.3g rad of double\n", K,
                    worst_centre, worst_facing);
    }
}

}  // namespace
