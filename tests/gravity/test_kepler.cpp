// The curved Kepler problem, a test body around a fixed sun at O, against its closed forms
// (reference.hpp): with the cotangent law the bounded orbit closes at every K (its periapsis
// does not turn, its radial period is the closed form's); with Newton's 1/d^2 copied onto the
// curved surface it precesses; a circular orbit keeps its radius and has the closed form's
// speed and period.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gravity/system.hpp"
#include "reference.hpp"

namespace {

using namespace noneuclid::gravity;
using gravity_ref::kCurvatures;
using gravity_ref::LD;

// The periapsis passages of a test body (mass 1, the sun's pull alone moves it) started at
// periapsis rp = 0.2 with e = 0.5 (mu = G M = 1), through `orbits` orbits of yoshida4 steps of
// T / 2000 (T the cotangent orbit's radial period, reference.hpp). A passage is a step at which
// dr/dt turns from negative to positive; there the periapsis angle is read by the closed form
// (reference.hpp's periapsis_angle: exact on the cotangent orbit, and within the step's
// second-order remainder of the true periapsis on any orbit, since dr/dt is then within one
// step of 0), and its time interpolated linearly between the two steps.
struct Passages {
    LD period;             // the closed form's radial period
    double mean_turn = 0;  // the periapsis' turn per orbit, mean
    double max_turn = 0;   // and the largest |turn| over the orbits
    double mean_time = 0;  // the time between passages, mean
    int count = 0;
};
Passages passages(double K, Law law, int orbits) {
    const gravity_ref::Kepler k = gravity_ref::kepler(K, 1.0, 0.5, 0.2);
    System<double, 2> sys;
    sys.K = K;
    sys.law = law;
    add(sys, make_body<double>(K, {0, 0}, 0, 0, 1.0, true));
    add(sys, make_body<double>(K, {0.2, 0}, 0, double(gravity_ref::periapsis_speed(k)), 1.0));
    Passages out;
    out.period = gravity_ref::period(k);
    const double h = double(out.period) / 2000;
    gravity_ref::Reading prev = gravity_ref::read(K, sys.bodies[1]);
    LD angle0 = 0, time0 = 0, last_angle = 0, last_time = 0, sum_turn = 0;
    for (int n = 1; n <= orbits * 2000 + 1000; ++n) {
        yoshida4(sys, h, 1);
        const gravity_ref::Reading now = gravity_ref::read(K, sys.bodies[1]);
        if (prev.rdot < 0 && now.rdot >= 0) {
            const LD angle = gravity_ref::periapsis_angle(K, 1, now);
            const LD time = h * (n - 1 + prev.rdot / (prev.rdot - now.rdot));
            if (out.count == 0) angle0 = angle, time0 = time;
            else {
                const LD turn = std::remainder(angle - last_angle, 2 * gravity_ref::kPi);
                sum_turn += turn;
                out.max_turn = std::max(out.max_turn, double(std::fabs(turn)));
            }
            last_angle = angle, last_time = time;
            ++out.count;
        }
        prev = now;
    }
    if (out.count > 1) {
        out.mean_turn = double(sum_turn / (out.count - 1));
        out.mean_time = double((last_time - time0) / (out.count - 1));
    }
    (void)angle0;
    return out;
}

// The cotangent law's orbit closes: after each radial period the periapsis has turned by less
// than 1e-6 rad (measured: ~1e-8, the fourth-order step's own error at T / 2000), and the
// radial period is the closed form's within 1e-7 relative.
TEST(GravityKepler, CotangentOrbitsClose) {
    for (double K : kCurvatures) {
        const Passages p = passages(K, Law::cotangent, 10);
        std::printf("[ figures  ] cotangent K %+4.1f: period %.9f (closed form %.9Lf), periapsis turn per orbit "
                    "%.2e (largest %.2e)\n",
                    K, p.mean_time, p.period, p.mean_turn, p.max_turn);
        ASSERT_GE(p.count, 10) << K;
        EXPECT_LT(p.max_turn, 1e-6) << K;
        EXPECT_NEAR(p.mean_time, double(p.period), 1e-7 * double(p.period)) << K;
    }
}

// Newton's 1/d^2 on the curved surface precesses, forwards on the sphere (its pull falls off
// faster than the cotangent's, by K/3 per unit of G M at short range) and backwards on the
// hyperbolic plane; at K = 0 it is the cotangent law and closes. Measured for rp = 0.2, e = 0.5:
// -0.269 (K = -1), -0.140 (-0.5), 0.150 (0.5), 0.311 (1) rad per orbit. Asserted: more than
// 0.05 rad per orbit with the sign of K, and less than 1e-6 at K = 0.
TEST(GravityKepler, NewtonOnACurvedSurfacePrecesses) {
    for (double K : kCurvatures) {
        const Passages p = passages(K, Law::newton, 10);
        std::printf("[ figures  ] newton K %+4.1f: period %.6f, periapsis turn per orbit %+.4f rad\n", K, p.mean_time,
                    p.mean_turn);
        ASSERT_GE(p.count, 5) << K;
        if (K == 0) {
            EXPECT_LT(p.max_turn, 1e-6);
        } else {
            EXPECT_GT(p.mean_turn * (K > 0 ? 1 : -1), 0.05) << K;
        }
    }
}

// A circular orbit of radius a around a fixed mass (G M = 1) started at the speed
// v = sqrt(G M / (S_K(a) C_K(a))) (gravity/law.hpp derives it) keeps its radius within 1e-9
// relative over 20 orbits of 3000 yoshida4 steps, and its period is 2 pi S_K(a) / v within
// 1e-9 relative (the time of the 20th turn, linearly interpolated: theta grows linearly).
TEST(GravityKepler, CircularOrbits) {
    struct Case {
        double K, a;
    };
    const Case cases[] = {{-1, 0.3}, {-1, 1.0}, {-1, 1.2}, {-0.5, 0.3}, {-0.5, 1.0}, {0, 0.3}, {0, 1.0},
                          {0.5, 0.3}, {0.5, 1.0}, {1, 0.3}, {1, 1.0}, {1, 1.4}};
    for (const Case& c : cases) {
        const LD v = std::sqrt(1 / (gravity_ref::S(c.K, c.a) * gravity_ref::C(c.K, c.a)));
        const LD period = 2 * gravity_ref::kPi * gravity_ref::S(c.K, c.a) / v;
        System<double, 2> sys;
        sys.K = c.K;
        add(sys, make_body<double>(c.K, {0, 0}, 0, 0, 1.0, true));
        add(sys, make_body<double>(c.K, {c.a, 0}, 0, double(v), 1.0));
        const int orbits = 20, per_orbit = 3000;
        const double h = double(period) / per_orbit;
        double worst = 0;
        LD turned = 0, prev_theta = 0, turn_time = 0;
        for (int n = 1; n <= orbits * per_orbit + 100 && turn_time == 0; ++n) {
            yoshida4(sys, h, 1);
            const gravity_ref::Reading r = gravity_ref::read(c.K, sys.bodies[1]);
            worst = std::max(worst, double(std::fabs(r.r - c.a) / c.a));
            const LD step = std::remainder(r.theta - prev_theta, 2 * gravity_ref::kPi);
            const LD goal = orbits * 2 * gravity_ref::kPi;
            if (turned + step >= goal) turn_time = h * (n - 1 + (goal - turned) / step);
            turned += step, prev_theta = r.theta;
        }
        std::printf("[ figures  ] circle K %+4.1f a %.1f: v %.6Lf, radius error %.2e, period error %.2e\n", c.K, c.a,
                    v, worst, double(std::fabs(turn_time / orbits - period) / period));
        EXPECT_LT(worst, 1e-9) << c.K << " " << c.a;
        EXPECT_NEAR(double(turn_time / orbits), double(period), 1e-9 * double(period)) << c.K << " " << c.a;
    }
}

}  // namespace
