// The fixed-point number: Q formats, rounding, saturation, ADL. Every expectation is checked
// against double arithmetic or an exact value worked out by hand in the comment beside it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "fixed/fixed.hpp"
#include "fixed/math.hpp"
#include "test_common.hpp"

using noneuclid::fx::fixed;
using noneuclid::fx::unit;

namespace {

using noneuclid::test::kStep;

TEST(Fixed, ConvertsFromDoubleRoundingToNearest) {
    EXPECT_EQ(fixed(1.5).raw(), 98304);  // 1.5 * 2^16
    EXPECT_EQ(fixed(-1.5).raw(), -98304);
    EXPECT_EQ(fixed(0.5 * kStep).raw(), 1);    // a tie rounds away from zero
    EXPECT_EQ(fixed(-0.5 * kStep).raw(), -1);
    EXPECT_EQ(fixed(0.49 * kStep).raw(), 0);
    EXPECT_EQ(fixed(3.0).to_double(), 3.0);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> d(-32000, 32000);
    for (int i = 0; i < 10000; ++i) {
        const double x = d(rng);
        EXPECT_LE(std::fabs(fixed(x).to_double() - x), 0.5 * kStep) << x;
    }
}

TEST(Fixed, ConversionSaturatesAndMapsNanToZero) {
    EXPECT_EQ(fixed(1e10), fixed::max());
    EXPECT_EQ(fixed(-1e10), fixed::min());
    EXPECT_EQ(fixed(std::numeric_limits<double>::infinity()), fixed::max());
    EXPECT_EQ(fixed(-std::numeric_limits<double>::infinity()), fixed::min());
    EXPECT_EQ(fixed(std::numeric_limits<double>::quiet_NaN()).raw(), 0);
    EXPECT_EQ(fixed(40000), fixed::max());  // integers too
    EXPECT_EQ(fixed(-40000), fixed::min());
    EXPECT_EQ(fixed(-32768).raw(), INT32_MIN);  // the one integer at the very edge
}

TEST(Fixed, AdditionAndSubtractionSaturate) {
    EXPECT_EQ(fixed::max() + fixed::epsilon(), fixed::max());
    EXPECT_EQ(fixed::min() - fixed::epsilon(), fixed::min());
    EXPECT_EQ(-fixed::min(), fixed::max());  // -(-32768) does not fit: saturates
    EXPECT_EQ(fixed(20000) + fixed(20000), fixed::max());
    EXPECT_EQ((fixed(1.25) + fixed(2.5)).to_double(), 3.75);
    EXPECT_EQ((fixed(1.25) - fixed(2.5)).to_double(), -1.25);
}

TEST(Fixed, MultiplicationRoundsToNearestAndSaturates) {
    EXPECT_EQ(fixed(200) * fixed(200), fixed::max());
    EXPECT_EQ(fixed(-200) * fixed(200), fixed::min());
    EXPECT_EQ((fixed(1.5) * fixed(-2.25)).to_double(), -3.375);
    EXPECT_EQ(fixed(3) * 4, fixed(12));
    EXPECT_EQ(fixed(30000) * 2, fixed::max());
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> d(-150, 150);
    for (int i = 0; i < 20000; ++i) {
        const fixed a(d(rng)), b(d(rng));
        const double exact = a.to_double() * b.to_double();
        EXPECT_LE(std::fabs((a * b).to_double() - exact), 0.5 * kStep) << a.to_double() << " " << b.to_double();
    }
}

TEST(Fixed, DivisionRoundsToNearestAndHandlesZero) {
    EXPECT_EQ(fixed(1) / fixed(0), fixed::max());
    EXPECT_EQ(fixed(-1) / fixed(0), fixed::min());
    EXPECT_EQ(fixed(0) / fixed(0), fixed(0));
    EXPECT_EQ(fixed(1000) / fixed(0.001), fixed::max());
    EXPECT_EQ((fixed(1) / fixed(4)).to_double(), 0.25);
    EXPECT_EQ(fixed(-7) / 2, fixed(-3.5));
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> d(-1000, 1000);
    for (int i = 0; i < 20000; ++i) {
        const fixed a(d(rng)), b(d(rng) / 100);
        if (b.raw() == 0) continue;
        const double exact = a.to_double() / b.to_double();
        if (std::fabs(exact) >= 32767) continue;
        EXPECT_LE(std::fabs((a / b).to_double() - exact), 0.5 * kStep) << a.to_double() << " / " << b.to_double();
    }
}

TEST(Fixed, QFormatConversion) {
    EXPECT_EQ(unit(0.5).raw(), 1 << 29);
    EXPECT_EQ(unit(0.5).as<16>().raw(), 1 << 15);
    EXPECT_EQ(fixed(0.75).as<30>(), unit(0.75));
    EXPECT_EQ(fixed(3).as<30>(), unit::max());  // 3 does not fit Q2.30
    EXPECT_EQ(fixed(-3).as<30>(), unit::min());
    EXPECT_EQ(unit::from_raw((1 << 13) + 0).as<16>().raw(), 1);  // 2^13 / 2^14 = 0.5 rounds up
    EXPECT_EQ(unit::from_raw((1 << 13) - 1).as<16>().raw(), 0);
}

TEST(Fixed, ComparesLikeItsValue) {
    EXPECT_LT(fixed(-1), fixed(0.5));
    EXPECT_GT(fixed(2), fixed(1.99));
    EXPECT_EQ(noneuclid::fx::abs(fixed(-2.5)), fixed(2.5));
    EXPECT_EQ(noneuclid::fx::abs(fixed::min()), fixed::max());
    EXPECT_EQ(noneuclid::fx::clamp(fixed(5), fixed(-1), fixed(1)), fixed(1));
    EXPECT_EQ(fixed(-2.5).floor_int(), -3);
}

// The same template, written once, runs on double and on fixed: ADL finds fx:: functions.
template <class T>
T everything(T x) {
    using std::acos, std::asin, std::atan2, std::cos, std::cosh, std::sin, std::sinh,
        std::sqrt, std::asinh, std::acosh, std::exp, std::log;
    const T half = T(0.5);
    return sin(x) * cos(x) + atan2(x, T(2)) + asin(x * half) + acos(x * half) + sqrt(x + T(1)) +
           sinh(x) - cosh(x) + asinh(x) + acosh(x + T(2)) + exp(x * half) - log(x + T(2));
}

TEST(Fixed, TemplatedCodeFindsFixedFunctionsByAdl) {
    for (double x = -0.9; x <= 0.9; x += 0.05) {
        const double d = everything<double>(x);
        const double f = everything<fixed>(fixed(x)).to_double();
        EXPECT_NEAR(f, d, 2e-4) << "x = " << x;  // a dozen terms, each within ~2e-5
    }
}

TEST(Fixed, CurvatureFunctionsReachableByAdl) {
    // S_K(x) = x Sf(K x^2), written once for both scalars.
    auto s_k = [](auto k, auto x) { return x * Sf(k * x * x); };
    const fixed got = s_k(fixed(-1), fixed(1.5));
    EXPECT_NEAR(got.to_double(), std::sinh(1.5), 3e-5);
}

}  // namespace
