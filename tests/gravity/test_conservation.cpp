// The integrator keeps the curved problem's integrals: an eccentric (e = 0.5) planet around a
// sun, fixed or free, at K = -1, -0.5, 0, 0.5, 1, for 2 10^5 leapfrog steps: the energy (the
// tests' own long-double energy, reference.hpp) within 1e-6 relative and bounded, the angular
// momentum within 1e-9 relative.
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

// A sun of mass 1 at O and a planet at periapsis rp = 0.2 on the +x axis, moving along +y with
// the speed of the curved Kepler orbit of e = 0.5 (reference.hpp; apoapsis 0.68 at K = -1,
// 0.55 at K = 1). With a free sun (mu = G (M + m)) that is their relative speed, shared as in
// the plane: the planet gets M / (M + m) of it, the sun the opposite momentum, so that the pair
// stays together and near O (given all of it, the planet escapes on the hyperbolic plane).
struct Planet {
    System<double, 2> sys;
    LD period;  // of the fixed-sun orbit (the free pair's is close)
};
Planet planet(double K, bool fixed_sun) {
    const double m = fixed_sun ? 1.0 : 0.1;
    const gravity_ref::Kepler k = gravity_ref::kepler(K, fixed_sun ? 1.0 : 1.0 + m, 0.5, 0.2);
    const double v = double(gravity_ref::periapsis_speed(k)), share = fixed_sun ? 1 : 1 / (1 + m);
    Planet out;
    out.sys.K = K;
    add(out.sys, make_body<double>(K, {0, 0}, 0, fixed_sun ? 0 : -m * v * share, 1.0, fixed_sun));
    add(out.sys, make_body<double>(K, {0.2, 0}, 0, v * share, m));
    out.period = gravity_ref::period(k);
    return out;
}

// The engine's energy and angular momentum are the tests' own (1e-13 relative), at the start of
// every orbit of the next test.
TEST(GravityConservation, EngineIntegralsAreTheReferences) {
    for (double K : kCurvatures)
        for (bool fixed_sun : {true, false}) {
            const Planet p = planet(K, fixed_sun);
            const LD e = gravity_ref::energy(p.sys);
            EXPECT_NEAR(energy(p.sys), double(e), 1e-13 * std::fabs(double(e))) << K;
            const Momentum<double> j = angular_momentum(p.sys);
            const gravity_ref::Momentum r = gravity_ref::momentum(p.sys);
            EXPECT_LT(double(gravity_ref::difference({j.o, j.x, j.y}, r)), 1e-14 * double(gravity_ref::norm(r))) << K;
        }
}

// Ten orbits of 2 10^4 leapfrog steps each, the integrals read every 10 steps. Criteria:
//   energy: |E - E0| / |E0| < 1e-6 throughout;
//   no secular drift: the largest energy error over the last 10% of the run (the last orbit) is
//     at most twice that over the first 10% (the first orbit): a drift linear in time would
//     make it ten times (a non-symplectic second-order method's does);
//   angular momentum: |J - J0| / |J0| < 1e-9 throughout (J the three components with a free
//     sun, J_o, the rotation about the fixed sun, with a fixed one).
TEST(GravityConservation, EnergyAndAngularMomentumDoNotDrift) {
    const int orbits = 10, per_orbit = 20000, every = 10;
    const int samples = orbits * per_orbit / every, tenth = samples / 10;
    for (double K : kCurvatures)
        for (bool fixed_sun : {true, false}) {
            Planet p = planet(K, fixed_sun);
            const double h = double(p.period) / per_orbit;
            const LD e0 = gravity_ref::energy(p.sys);
            const gravity_ref::Momentum j0 = gravity_ref::momentum(p.sys);
            double worst = 0, first = 0, last = 0, worst_j = 0;
            for (int n = 0; n < samples; ++n) {
                leapfrog(p.sys, h, every);
                const double de = double(std::fabs((gravity_ref::energy(p.sys) - e0) / e0));
                const gravity_ref::Momentum j = gravity_ref::momentum(p.sys);
                const double dj = fixed_sun ? double(std::fabs((j.o - j0.o) / j0.o))
                                            : double(gravity_ref::difference(j, j0) / gravity_ref::norm(j0));
                worst = std::max(worst, de), worst_j = std::max(worst_j, dj);
                if (n < tenth) first = std::max(first, de);
                if (n >= samples - tenth) last = std::max(last, de);
            }
            std::printf("[ figures  ] K %+4.1f %s sun: energy error max %.2e (first 10%% %.2e, last 10%% %.2e), "
                        "angular momentum %.2e\n",
                        K, fixed_sun ? "fixed" : "free ", worst, first, last, worst_j);
            EXPECT_LT(worst, 1e-6) << "K " << K << " fixed sun " << fixed_sun;
            EXPECT_LE(last, 2 * first) << "K " << K << " fixed sun " << fixed_sun;
            EXPECT_LT(worst_j, 1e-9) << "K " << K << " fixed sun " << fixed_sun;
        }
}

// The fourth-order composition keeps them too, far better: 10 orbits of 2000 steps, energy
// within 1e-8, bounded the same way, angular momentum within 1e-9.
TEST(GravityConservation, FourthOrderStepToo) {
    const int orbits = 10, per_orbit = 2000, samples = orbits * per_orbit, tenth = samples / 10;
    for (double K : kCurvatures) {
        Planet p = planet(K, false);
        const double h = double(p.period) / per_orbit;
        const LD e0 = gravity_ref::energy(p.sys);
        const gravity_ref::Momentum j0 = gravity_ref::momentum(p.sys);
        double worst = 0, first = 0, last = 0, worst_j = 0;
        for (int n = 0; n < samples; ++n) {
            yoshida4(p.sys, h, 1);
            const double de = double(std::fabs((gravity_ref::energy(p.sys) - e0) / e0));
            worst = std::max(worst, de);
            worst_j = std::max(worst_j, double(gravity_ref::difference(gravity_ref::momentum(p.sys), j0) / gravity_ref::norm(j0)));
            if (n < tenth) first = std::max(first, de);
            if (n >= samples - tenth) last = std::max(last, de);
        }
        std::printf("[ figures  ] yoshida4 K %+4.1f free sun: energy error max %.2e (first %.2e, last %.2e), "
                    "angular momentum %.2e\n",
                    K, worst, first, last, worst_j);
        EXPECT_LT(worst, 1e-8) << K;
        EXPECT_LE(last, 2 * first) << K;
        EXPECT_LT(worst_j, 1e-9) << K;
    }
}

// settle() moves a body that is on the surface by no more than rounding, and puts one that
// rounding walked off it back: <p, p> = 1 and <p, v> = 0 to 1e-15.
TEST(GravityConservation, SettleTakesBackRoundingOnly) {
    for (double K : kCurvatures) {
        Planet p = planet(K, false);
        const Body<double> before = p.sys.bodies[1];
        settle(p.sys);
        const Body<double>& b = p.sys.bodies[1];
        EXPECT_NEAR(b.p.w, before.p.w, 1e-15);
        EXPECT_NEAR(b.v.y, before.v.y, 1e-15);
        p.sys.bodies[1].p = (1 + 1e-9) * b.p;
        p.sys.bodies[1].v = b.v + 1e-9 * b.p;
        settle(p.sys);
        EXPECT_NEAR(form(K, b.p, b.p), 1.0, 1e-15) << K;
        EXPECT_NEAR(form(K, b.p, b.v), 0.0, 1e-15) << K;
    }
}

// make_body's velocity is the tests' polar reading (reference.hpp: dr/dt and S_K(r)^2 dtheta/dt),
// and turning K (set_curvature) keeps every body's polar position and velocity, to 1e-13.
TEST(GravityConservation, PolarBodiesAndTurningK) {
    for (double K : kCurvatures) {
        System<double, 2> sys;
        sys.K = K;
        add(sys, make_body<double>(K, {0.7, 2.0}, -0.3, 0.9, 1.0));
        add(sys, make_body<double>(K, {0.0, 0.0}, 0.4, 0.2, 1.0));
        const gravity_ref::Reading r = gravity_ref::read(K, sys.bodies[0]);
        EXPECT_NEAR(double(r.r), 0.7, 1e-13);
        EXPECT_NEAR(double(r.theta), 2.0, 1e-13);
        EXPECT_NEAR(double(r.rdot), -0.3, 1e-13);
        EXPECT_NEAR(double(r.L), double(0.9 * gravity_ref::S(K, 0.7)), 1e-13);
        EXPECT_NEAR(double(r.speed2), 0.9 * 0.9 + 0.3 * 0.3, 1e-13);
        EXPECT_NEAR(double(gravity_ref::read(K, sys.bodies[1]).speed2), 0.4 * 0.4 + 0.2 * 0.2, 1e-13);
        for (double to : kCurvatures) {
            System<double, 2> turned = sys;
            set_curvature(turned, to);
            const PolarMotion<double> m = polar_motion(to, turned.bodies[0]);
            EXPECT_NEAR(m.at.r, 0.7, 1e-13) << K << " to " << to;
            EXPECT_NEAR(m.at.theta, 2.0, 1e-13) << K << " to " << to;
            EXPECT_NEAR(m.radial, -0.3, 1e-13) << K << " to " << to;
            EXPECT_NEAR(m.tangential, 0.9, 1e-13) << K << " to " << to;
            EXPECT_NEAR(form(to, turned.bodies[0].p, turned.bodies[0].v), 0.0, 1e-15);
        }
    }
}

}  // namespace
