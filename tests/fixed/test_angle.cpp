// The binary angle: wrap-around, conversions to and from radians.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "fixed/angle.hpp"
#include "test_common.hpp"

using noneuclid::fx::angle;
using noneuclid::fx::fixed;

namespace {

using noneuclid::test::kPi;

TEST(Angle, NamedAnglesHaveTheirBits) {
    EXPECT_EQ(angle::from_degrees(90).raw(), angle::quarter_turn);
    EXPECT_EQ(angle::from_degrees(180).raw(), angle::half_turn);
    EXPECT_EQ(angle::from_degrees(-90).raw(), 3u * angle::quarter_turn);
    EXPECT_EQ(angle::from_turns(1.25).raw(), angle::quarter_turn);
    EXPECT_EQ(angle::from_radians(kPi / 4).raw(), 1u << 29);
}

TEST(Angle, AdditionWrapsAroundTheCircle) {
    const angle a = angle::from_degrees(270) + angle::from_degrees(180);
    EXPECT_EQ(a, angle::from_degrees(90));
    EXPECT_EQ(angle::from_degrees(10) - angle::from_degrees(20), angle::from_degrees(-10));
    EXPECT_EQ(-angle::from_degrees(30), angle::from_degrees(330));
    EXPECT_EQ(angle::from_degrees(100) * 4, angle::from_degrees(40));
    EXPECT_EQ(angle::from_degrees(-100).half(), angle::from_degrees(-50));
}

TEST(Angle, ToRadiansIsSignedAndRounded) {
    EXPECT_EQ(angle::from_raw(angle::half_turn).to_radians(), fixed(-kPi));  // [-pi, pi)
    EXPECT_EQ(angle::from_degrees(90).to_radians(), fixed(kPi / 2));
    EXPECT_EQ(angle::from_degrees(-45).to_radians(), fixed(-kPi / 4));
    std::mt19937 rng(3);
    for (int i = 0; i < 20000; ++i) {
        const angle a = angle::from_raw(static_cast<uint32_t>(rng()));
        const double exact = static_cast<int32_t>(a.raw()) * (2 * kPi / 4294967296.0);
        EXPECT_LE(std::fabs(a.to_radians().to_double() - exact), 0.5 / 65536 + 1e-12);
        EXPECT_NEAR(a.to_radians_double(), exact, 1e-15);
    }
}

// Q16.16 radians to a binary angle, for any representable x: compare with long double.
TEST(Angle, FromFixedRadiansIsExactToAboutOneUnit) {
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<int32_t> raw(INT32_MIN, INT32_MAX);
    for (int i = 0; i < 50000; ++i) {
        const fixed x = fixed::from_raw(raw(rng));
        const long double units = static_cast<long double>(x.raw()) / 65536.0L *
                                  (4294967296.0L / (2 * std::numbers::pi_v<long double>));
        long double m = std::fmod(units, 4294967296.0L);
        if (m < 0) m += 4294967296.0L;
        const uint32_t got = angle::from_radians(x).raw();
        long double diff = static_cast<long double>(got) - m;
        if (diff > 2147483648.0L) diff -= 4294967296.0L;
        if (diff < -2147483648.0L) diff += 4294967296.0L;
        EXPECT_LE(std::fabs(static_cast<double>(diff)), 1.5) << x.to_double();
    }
}

}  // namespace
