// Special values, domain edges and behaviour outside the domain of the fixed-point functions
// (the dense accuracy sweeps are in tests/accuracy). References are exact values or std::.
#include <gtest/gtest.h>

#include <cmath>

#include "fixed/math.hpp"

using namespace noneuclid::fx;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfStep = 0.5 / 65536;

double d(fixed x) { return x.to_double(); }

TEST(Functions, SinCosAtTheCardinalAnglesAreExact) {
    EXPECT_EQ(sin(angle{}), fixed(0));
    EXPECT_EQ(sin(angle::from_degrees(90)), fixed(1));
    EXPECT_EQ(sin(angle::from_degrees(270)), fixed(-1));
    EXPECT_EQ(cos(angle{}), fixed(1));
    EXPECT_EQ(cos(angle::from_degrees(180)), fixed(-1));
    // Between table nodes: within the interpolation bound (1.2e-6) in Q2.30.
    EXPECT_NEAR(sin_unit(angle::from_degrees(30)).to_double(), 0.5, 1.2e-6);
}

TEST(Functions, Atan2CoversEveryQuadrantAndTheOrigin) {
    EXPECT_EQ(atan2_angle(fixed(0), fixed(0)).raw(), 0u);
    EXPECT_EQ(atan2(fixed(0), fixed(0)), fixed(0));
    EXPECT_EQ(atan2_angle(fixed(1), fixed(0)).raw(), angle::quarter_turn);
    EXPECT_EQ(atan2_angle(fixed(0), fixed(-1)).raw(), angle::half_turn);
    EXPECT_EQ(atan2_angle(fixed(-1), fixed(0)).raw(), 3u * angle::quarter_turn);
    EXPECT_EQ(atan2(fixed(0), fixed(-1)), fixed(kPi));  // (-pi, pi] like std::atan2(+0, -1)
    for (int q = 0; q < 8; ++q) {
        const double th = -kPi + kPi / 8 + q * kPi / 4;
        const fixed y(3 * std::sin(th)), x(3 * std::cos(th));
        EXPECT_NEAR(d(atan2(y, x)), std::atan2(d(y), d(x)), 1e-5) << th;
    }
    // The extreme raw values (|INT32_MIN| does not fit an int32) do not overflow.
    EXPECT_EQ(atan2_angle(fixed::min(), fixed::min()).raw(), 5u * (angle::quarter_turn / 2));
    EXPECT_EQ(atan2_angle(fixed::min(), fixed(0)).raw(), 3u * angle::quarter_turn);
    // Any Q format: the angle depends only on the ratio of the raw integers.
    EXPECT_EQ(atan2_angle(unit(0.375), unit(0.5)), atan2_angle(fixed(0.375), fixed(0.5)));
}

TEST(Functions, AsinAcosEndsAndClamping) {
    EXPECT_NEAR(d(asin(fixed(1))), kPi / 2, kHalfStep);
    EXPECT_NEAR(d(asin(fixed(-1))), -kPi / 2, kHalfStep);
    EXPECT_EQ(asin(fixed(2)), asin(fixed(1)));    // clamped
    EXPECT_EQ(asin(fixed(-5)), asin(fixed(-1)));
    EXPECT_NEAR(d(acos(fixed(-1))), kPi, kHalfStep);
    EXPECT_EQ(acos(fixed(1)), fixed(0));
    EXPECT_EQ(acos(fixed(3)), fixed(0));
    // The steep end: one step below 1, asin = pi/2 - sqrt(2 * 2^-16) + ...
    const fixed x = fixed::from_raw(65535);
    EXPECT_NEAR(d(asin(x)), std::asin(d(x)), 1e-5);
    // Monotone over the whole domain.
    fixed prev = asin(fixed(-1));
    for (int32_t r = -65536; r <= 65536; ++r) {
        const fixed v = asin(fixed::from_raw(r));
        ASSERT_GE(v, prev) << r;
        prev = v;
    }
}

TEST(Functions, SqrtIsCorrectlyRoundedAndExactOnSquares) {
    EXPECT_EQ(sqrt(fixed(0)), fixed(0));
    EXPECT_EQ(sqrt(fixed(-4)), fixed(0));                          // documented
    EXPECT_EQ(sqrt(fixed::epsilon()).raw(), 256);                  // sqrt(2^-16) = 2^-8
    for (int k = 0; k <= 181; ++k) EXPECT_EQ(sqrt(fixed(k * k)), fixed(k)) << k;
    EXPECT_NEAR(d(sqrt(fixed::max())), std::sqrt(d(fixed::max())), kHalfStep);
    // Every raw value over a stride through the whole range: within half a step.
    for (int64_t r = 1; r <= INT32_MAX; r += 65521) {
        const fixed x = fixed::from_raw(static_cast<int32_t>(r));
        ASSERT_LE(std::fabs(d(sqrt(x)) - std::sqrt(d(x))), kHalfStep + 1e-12) << r;
    }
}

TEST(Functions, ExpLogSaturateOutsideTheirRange) {
    EXPECT_EQ(exp(fixed(0)), fixed(1));
    EXPECT_EQ(exp(fixed(20)), fixed::max());
    EXPECT_EQ(exp(fixed(-20)), fixed(0));
    EXPECT_EQ(log(fixed(1)), fixed(0));
    EXPECT_EQ(log(fixed(0)), fixed::min());
    EXPECT_EQ(log(fixed(-3)), fixed::min());
    EXPECT_NEAR(d(log(fixed::epsilon())), std::log(1.0 / 65536), 1e-5);
}

TEST(Functions, HyperbolicSpecialValues) {
    EXPECT_EQ(cosh(fixed(0)), fixed(1));
    EXPECT_EQ(sinh(fixed(0)), fixed(0));
    EXPECT_EQ(cosh(fixed(12)), fixed::max());
    EXPECT_EQ(cosh(fixed(-12)), fixed::max());
    EXPECT_EQ(sinh(fixed(12)), fixed::max());
    EXPECT_EQ(sinh(fixed(-12)), fixed::min());
    EXPECT_EQ(sinh(fixed(-1.5)), -sinh(fixed(1.5)));  // odd
    EXPECT_EQ(asinh(fixed(0)), fixed(0));
    EXPECT_EQ(asinh(fixed(-7)), -asinh(fixed(7)));
    EXPECT_NEAR(d(asinh(fixed::max())), std::asinh(d(fixed::max())), 1e-5);
    EXPECT_NEAR(d(asinh(fixed::min())), std::asinh(d(fixed::min())), 1e-5);
    EXPECT_EQ(acosh(fixed(1)), fixed(0));
    EXPECT_EQ(acosh(fixed(0.5)), fixed(0));  // documented: below the domain gives 0
    EXPECT_EQ(acosh(fixed(-9)), fixed(0));
    const fixed just_above = fixed::from_raw(65537);  // acosh(1 + e) ~ sqrt(2 e): steep
    EXPECT_NEAR(d(acosh(just_above)), std::acosh(d(just_above)), 1e-5);
}

TEST(Functions, CurvatureFunctionsAtSpecialPoints) {
    EXPECT_EQ(Sf(fixed(0)), fixed(1));
    EXPECT_EQ(Cf(fixed(0)), fixed(1));
    EXPECT_EQ(ASf(fixed(0)), fixed(1));
    const fixed pi2(kPi * kPi);                  // sqrt(u) = pi
    EXPECT_NEAR(d(Sf(pi2)), 0, 2e-5);
    EXPECT_NEAR(d(Cf(pi2)), -1, 2e-5);
    EXPECT_NEAR(d(ASf(fixed(1))), kPi / 2, kHalfStep);
    EXPECT_EQ(ASf(fixed(5)), ASf(fixed(1)));    // documented clamp
    // ASf is steep at u = 1 (asin(sqrt u) has an infinite slope): the last steps still match.
    for (int32_t r = 65536 - 8; r < 65536; ++r) {
        const double u = r / 65536.0;
        EXPECT_NEAR(d(ASf(fixed::from_raw(r))), std::asin(std::sqrt(u)) / std::sqrt(u), 1e-5) << r;
    }
    EXPECT_EQ(Sf(fixed(-1000)), fixed::max());  // sinh(31.6)/31.6 does not fit
    EXPECT_EQ(Cf(fixed(-1000)), fixed::max());
    EXPECT_EQ(Sf(fixed::min()), fixed::max());
    EXPECT_EQ(Cf(fixed::min()), fixed::max());
    EXPECT_NEAR(d(Sf(fixed::max())), std::sin(std::sqrt(32768.0)) / std::sqrt(32768.0), 2e-5);
    EXPECT_NEAR(d(Cf(fixed::max())), std::cos(std::sqrt(32768.0)), 2e-5);
}

TEST(Functions, ATfAndHypot) {
    EXPECT_EQ(ATf(fixed(0)), fixed(1));
    EXPECT_NEAR(d(ATf(fixed(1))), kPi / 4, kHalfStep);          // atan(1)/1
    EXPECT_EQ(ATf(fixed(-1)), fixed::max());                    // atanh(1) diverges
    EXPECT_EQ(ATf(fixed(-5)), fixed::max());
    EXPECT_NEAR(d(ATf(fixed(30000))), std::atan(std::sqrt(30000.0)) / std::sqrt(30000.0), 2e-5);
    EXPECT_EQ(hypot(fixed(3), fixed(4)), fixed(5));
    EXPECT_NEAR(d(hypot(fixed(20000), fixed(20000))), 20000 * std::sqrt(2.0), kHalfStep);  // squares > 2^31
    EXPECT_EQ(hypot(fixed(30000), fixed(30000)), fixed::max());  // saturates, no overflow
    EXPECT_NEAR(d(hypot(fixed(300), fixed(-400))), 500, kHalfStep);
    EXPECT_EQ(hypot(fixed::min(), fixed(0)), fixed::max());
}

// Where a table hands over to the formula beyond it, the value must not jump.
TEST(Functions, CurvatureFunctionsAreContinuousAtTableEdges) {
    struct Edge {
        fixed (*f)(fixed);
        double u;
    } edges[] = {{Sf, 10}, {Sf, -10}, {Cf, 10}, {Cf, -10}, {ASf, 0.5}, {ASf, -4}, {ATf, -0.5}, {ATf, -0.9375}, {ATf, 1}};
    // A jump shows as a change of the step from one argument to the next (the second
    // difference), which stays near 0 however steep the function is (ATf at -15/16 rises by
    // 1.1e-4 per step of u).
    for (const Edge& e : edges) {
        const int32_t r = fixed(e.u).raw();
        for (int k = -3; k < 3; ++k) {
            const double a = d(e.f(fixed::from_raw(r + k - 1))), b = d(e.f(fixed::from_raw(r + k))),
                         c = d(e.f(fixed::from_raw(r + k + 1)));
            EXPECT_LE(std::fabs((c - b) - (b - a)), 4e-5) << "u = " << e.u << " + " << k << " steps";
        }
    }
}

// The integer kernels: exact floor square root and rounded division, checked against exact
// integer arithmetic (no floating point in the reference).
// Both the divide-instruction path and the reciprocal path (the one 32-bit ARM uses), here.
template <bool Native>
void check_isqrt() {
    uint64_t x = 0x243F6A8885A308D3ull;  // a fixed pseudo-random walk over all magnitudes
    for (int k = 0; k < 200000; ++k) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        const uint64_t v = x >> (k % 64);
        const uint64_t r = detail::isqrt64<Native>(v);
        ASSERT_LE(r * r, v) << v;
        ASSERT_TRUE(r == 0xFFFFFFFFu || (r + 1) * (r + 1) > v) << v;
    }
    EXPECT_EQ(detail::isqrt64<Native>(~0ull), 0xFFFFFFFFu);
    EXPECT_EQ(detail::isqrt64<Native>(1ull << 62), 1u << 31);
    EXPECT_EQ(detail::isqrt64<Native>((1ull << 62) - 1), (1u << 31) - 1);
}
TEST(Kernels, IntegerSquareRootIsExactFloor) {
    check_isqrt<true>();
    check_isqrt<false>();
}

template <bool Native>
void check_division() {
    uint64_t x = 0x13198A2E03707344ull;
    for (int k = 0; k < 200000; ++k) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        const uint32_t den = static_cast<uint32_t>(x >> (32 + k % 32)) | 1u;
        const int64_t num = static_cast<int64_t>(x >> (2 + k % 61)) * (k % 2 ? -1 : 1);
        const uint64_t a = num < 0 ? 0u - static_cast<uint64_t>(num) : static_cast<uint64_t>(num);
        uint64_t q = a / den;
        if (2 * (a % den) >= den) ++q;  // exact reference: round half away from zero
        ASSERT_EQ(detail::div_round<Native>(num, den), num < 0 ? -static_cast<int64_t>(q) : static_cast<int64_t>(q))
            << num << " / " << den;
    }
}
TEST(Kernels, DivisionRoundsExactlyOnBothPaths) {
    check_division<true>();
    check_division<false>();
}

// Every function over a stride through all 2^32 raw values: under the sanitizer preset this
// proves there is no undefined behaviour anywhere (overflow, shifts, out-of-bounds reads).
TEST(Functions, WholeRawRangeIsDefined) {
    int64_t acc = 0;
    auto all = [&acc](fixed x) {
        for (fixed v : {sin(x), cos(x), asin(x), acos(x), sqrt(x), exp(x), log(x), sinh(x),
                        cosh(x), asinh(x), acosh(x), Sf(x), Cf(x), ASf(x), ATf(x), atan2(x, fixed(1)),
                        hypot(x, x), hypot(x, fixed(-7)),
                        atan2(fixed(-3), x), atan2(x, x), atan2(x, -x)})
            acc += v.raw();
    };
    for (int64_t r = INT32_MIN; r <= INT32_MAX; r += 40009) all(fixed::from_raw(static_cast<int32_t>(r)));
    for (int32_t r : {INT32_MIN, INT32_MIN + 1, -1, 0, 1, INT32_MAX - 1, INT32_MAX}) all(fixed::from_raw(r));
    SUCCEED() << acc;
}

}  // namespace
