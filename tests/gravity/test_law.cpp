// gravity/law.hpp against closed forms: ctn_K through K = 0, each law's force as minus the
// derivative of its potential (softened too), the circular orbit's speed.
#include <gtest/gtest.h>

#include <cmath>

#include "gravity/law.hpp"
#include "reference.hpp"

namespace {

using namespace noneuclid::gravity;
using gravity_ref::LD;

constexpr double kLawCurvatures[] = {-1.0, -0.5, -1e-9, 0.0, 1e-9, 0.5, 1.0};

// ctn_K against sqrt K cot, 1/d, sqrt -K coth, to 1e-14 relative; and continuous: K = +-1e-9
// within 1e-9 relative of 1/d.
TEST(GravityLaw, CotangentOfTheCurvature) {
    for (double K : kLawCurvatures)
        for (double d : {0.01, 0.3, 1.0, 1.5}) {
            const LD want = gravity_ref::ctn(K, d);
            EXPECT_NEAR(ctn_K(K, d), double(want), 1e-14 * std::fabs(double(want))) << "K " << K << " d " << d;
            if (std::fabs(K) < 1e-6) {
                EXPECT_NEAR(ctn_K(K, d), 1 / d, 1e-9 / d);
            }
        }
}

// The unsoftened laws: cotangent U = -ctn_K(d), force 1/S_K(d)^2; newton U = -1/d, force
// 1/d^2; logarithmic U = log(2 T_K(d/2)), force 1/S_K(d) (each the attraction dU/dd). 1e-13.
TEST(GravityLaw, PotentialsAndForcesInClosedForm) {
    for (double K : kLawCurvatures)
        for (double d : {0.05, 0.4, 1.2}) {
            const LD s = gravity_ref::S(K, d), c = gravity_ref::C(K, d);
            const auto near = [](double got, LD want) { return std::fabs(got - double(want)) <= 1e-13 * std::fabs(double(want)); };
            EXPECT_TRUE(near(potential(Law::cotangent, K, d), -gravity_ref::ctn(K, d))) << K << " " << d;
            EXPECT_TRUE(near(force(Law::cotangent, K, d), 1 / (s * s))) << K << " " << d;
            EXPECT_TRUE(near(potential(Law::newton, K, d), LD(-1) / d)) << K << " " << d;
            EXPECT_TRUE(near(force(Law::newton, K, d), LD(1) / (LD(d) * d))) << K << " " << d;
            EXPECT_TRUE(near(potential(Law::logarithmic, K, d), std::log(2 * s / (1 + c)))) << K << " " << d;
            EXPECT_TRUE(near(force(Law::logarithmic, K, d), 1 / s)) << K << " " << d;
        }
}

// The attraction is dU/dd for every law, softened or not: against the five-point difference
// of the potential with step d / 10^4 (truncation ~(1e-4)^4, rounding ~1e-12 relative), to
// 1e-9 relative.
TEST(GravityLaw, AttractionIsTheDerivativeOfThePotential) {
    for (Law law : {Law::cotangent, Law::newton, Law::logarithmic})
        for (double K : kLawCurvatures)
            for (double eps : {0.0, 0.05, 0.3})
                for (double d : {0.02, 0.3, 1.1}) {
                    const double h = d * 1e-4;
                    const auto U = [&](double x) { return potential(law, K, x, eps); };
                    const double dU = (U(d - 2 * h) - 8 * U(d - h) + 8 * U(d + h) - U(d + 2 * h)) / (12 * h);
                    EXPECT_NEAR(force(law, K, d, eps), dU, 1e-9 * std::fabs(dU))
                        << "law " << int(law) << " K " << K << " eps " << eps << " d " << d;
                }
}

// Softening keeps the force finite as the bodies meet: the cotangent law's pull at s = 0 is
// (1 + K eps^2) / eps^3; at the sphere's antipode (s = 0, c = -1) the pull is finite and the
// potential +1/eps (the cotangent's repulsive image).
TEST(GravityLaw, SofteningIsFiniteWhereTheBodiesMeet) {
    for (double K : kLawCurvatures) {
        const PairLaw<double> at = pair_law(Law::cotangent, K, 0.0, 1.0, 0.1);
        EXPECT_NEAR(at.pull, (1 + K * 0.01) / 1e-3, 1e-9);
        EXPECT_NEAR(at.potential, -10.0, 1e-12);
    }
    const PairLaw<double> antipode = pair_law(Law::cotangent, 1.0, 0.0, -1.0, 0.1);
    EXPECT_NEAR(antipode.potential, 10.0, 1e-12);
    EXPECT_TRUE(std::isfinite(antipode.pull));
}

// v^2 = G M / (S_K(a) C_K(a)) (docs/gravity.md), and no circular orbit on the sphere's equator or
// beyond it.
TEST(GravityLaw, CircularSpeed) {
    for (double K : kLawCurvatures)
        for (double a : {0.1, 0.7, 1.3}) {
            const LD want = 2 / (gravity_ref::S(K, a) * gravity_ref::C(K, a));
            EXPECT_NEAR(circular_speed_squared(K, 2.0, a), double(want), 1e-13 * double(want)) << K << " " << a;
        }
    const double equator = gravity_ref::kPi / 2;
    EXPECT_GT(circular_speed_squared(1.0, 1.0, equator - 1e-3), 0.0);
    EXPECT_LT(circular_speed_squared(1.0, 1.0, equator + 1e-9), 0.0);
    EXPECT_LT(circular_speed_squared(1.0, 1.0, 2.5), 0.0);
    EXPECT_LT(circular_speed_squared(0.5, 1.0, equator * std::sqrt(2.0) + 1e-6), 0.0);
}

}  // namespace
