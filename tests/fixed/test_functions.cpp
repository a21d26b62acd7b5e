// Special values, domain edges and behaviour outside the domain of the fixed-point functions
// (the dense accuracy sweeps are in tests/fixed/test_accuracy.cpp). References are exact values or std::.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "fixed/math.hpp"
#include "test_common.hpp"

using namespace noneuclid::fx;

namespace {

using noneuclid::test::kHalfStep;
using noneuclid::test::kPi;

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

// Every function over a stride through all 2^32 raw values (and the extreme ones): under the
// sanitizer preset this proves there is no undefined behaviour anywhere (overflow, shifts,
// out-of-bounds reads); in every build, each result is checked against std:: in double, or
// against the out-of-domain rule math.hpp documents, so the test means something without the
// sanitizer too.
//
// The reference is the exact function of the exact (Q16.16) input, saturated to [min, max] as
// the functions saturate. The tolerance is absolute, kAbs, for results up to 1 in magnitude and
// relative, kAbs * |reference|, above (the functions round to Q16.16, whose steps are
// absolute, or compute in relative terms: exp, sinh, cosh, Sf and Cf beyond their tables).
// kAbs = 1.1e-5: above every absolute and relative figure tests/fixed/test_accuracy.cpp asserts (at most
// 1.06e-5, Cf on [-40, 40]), below one Q16.16 step (1.53e-5). sqrt and hypot are correctly
// rounded: half a step. Beyond the accuracy report's domains (|x| up to 32768, u down to
// -32768) the same tolerance holds: the stride below is what shows it.
struct Check {
    double got, want, tol;
};
constexpr double kAbs = 1.1e-5;
constexpr double kMaxD = 32767.0 + 65535.0 / 65536;  // fixed::max()
constexpr double kMinD = -32768.0;                   // fixed::min()
double saturated(double v) { return v > kMaxD ? kMaxD : (v < kMinD ? kMinD : v); }
Check near(fixed got, double want) {
    const double w = saturated(want);
    return {d(got), w, kAbs * std::max(1.0, std::fabs(w))};
}
Check rounded(fixed got, double want) { return {d(got), saturated(want), kHalfStep + 1e-9}; }
Check exactly(fixed got, fixed want) { return {d(got), d(want), 0}; }
// atan2: the angular difference, wrapped; (0, 0) gives 0 by rule.
Check angular(fixed got, fixed y, fixed x) {
    if (y.raw() == 0 && x.raw() == 0) return exactly(got, fixed(0));
    const double diff = std::remainder(d(got) - std::atan2(d(y), d(x)), 2 * kPi);
    return {diff, 0, kAbs};
}
// The curvature functions straight from their definitions (test_accuracy.cpp has references of
// its own, with the series near 0).
double direct_Sf(double u) {
    if (u == 0) return 1;
    const double s = std::sqrt(std::fabs(u));
    return u > 0 ? std::sin(s) / s : std::sinh(s) / s;
}
double direct_Cf(double u) { return u >= 0 ? std::cos(std::sqrt(u)) : std::cosh(std::sqrt(-u)); }
double direct_ASf(double u) {
    if (u == 0) return 1;
    const double s = std::sqrt(std::fabs(u));
    return u > 0 ? std::asin(s) / s : std::asinh(s) / s;
}
double direct_ATf(double u) {
    if (u == 0) return 1;
    const double s = std::sqrt(std::fabs(u));
    return u > 0 ? std::atan(s) / s : std::atanh(s) / s;
}

TEST(Functions, WholeRawRangeIsDefined) {
    struct Named {
        const char* name;
        Check (*check)(fixed);
    };
    const Named kChecks[] = {
        {"sin", [](fixed x) { return near(sin(x), std::sin(d(x))); }},
        {"cos", [](fixed x) { return near(cos(x), std::cos(d(x))); }},
        // Outside [-1, 1]: clamped to +-1.
        {"asin", [](fixed x) {
             if (d(x) > 1) return exactly(asin(x), asin(fixed(1)));
             if (d(x) < -1) return exactly(asin(x), asin(fixed(-1)));
             return near(asin(x), std::asin(d(x)));
         }},
        {"acos", [](fixed x) {
             if (d(x) > 1) return exactly(acos(x), fixed(0));
             if (d(x) < -1) return exactly(acos(x), acos(fixed(-1)));
             return near(acos(x), std::acos(d(x)));
         }},
        // sqrt(x < 0) = 0; correctly rounded.
        {"sqrt", [](fixed x) { return d(x) < 0 ? exactly(sqrt(x), fixed(0)) : rounded(sqrt(x), std::sqrt(d(x))); }},
        {"exp", [](fixed x) { return near(exp(x), std::exp(d(x))); }},
        // log(x <= 0) = min().
        {"log", [](fixed x) { return d(x) <= 0 ? exactly(log(x), fixed::min()) : near(log(x), std::log(d(x))); }},
        {"sinh", [](fixed x) { return near(sinh(x), std::sinh(d(x))); }},
        {"cosh", [](fixed x) { return near(cosh(x), std::cosh(d(x))); }},
        {"asinh", [](fixed x) { return near(asinh(x), std::asinh(d(x))); }},
        // acosh(x < 1) = 0.
        {"acosh", [](fixed x) { return d(x) < 1 ? exactly(acosh(x), fixed(0)) : near(acosh(x), std::acosh(d(x))); }},
        {"Sf", [](fixed u) { return near(Sf(u), direct_Sf(d(u))); }},
        {"Cf", [](fixed u) { return near(Cf(u), direct_Cf(d(u))); }},
        // ASf(u > 1) = ASf(1) = pi/2.
        {"ASf", [](fixed u) { return d(u) > 1 ? exactly(ASf(u), ASf(fixed(1))) : near(ASf(u), direct_ASf(d(u))); }},
        // ATf(u <= -1) = max() (atanh diverges).
        {"ATf", [](fixed u) { return d(u) <= -1 ? exactly(ATf(u), fixed::max()) : near(ATf(u), direct_ATf(d(u))); }},
        {"atan2(x, 1)", [](fixed x) { return angular(atan2(x, fixed(1)), x, fixed(1)); }},
        {"atan2(-3, x)", [](fixed x) { return angular(atan2(fixed(-3), x), fixed(-3), x); }},
        {"atan2(x, x)", [](fixed x) { return angular(atan2(x, x), x, x); }},
        {"atan2(x, -x)", [](fixed x) { return angular(atan2(x, -x), x, -x); }},  // -min() saturates
        {"hypot(x, x)", [](fixed x) { return rounded(hypot(x, x), std::hypot(d(x), d(x))); }},
        {"hypot(x, -7)", [](fixed x) { return rounded(hypot(x, fixed(-7)), std::hypot(d(x), 7.0)); }},
    };
    for (const Named& f : kChecks) {
        double worst = 0;  // the largest error as a fraction of the tolerance
        auto one = [&](int32_t r) {
            const fixed x = fixed::from_raw(r);
            const Check c = f.check(x);
            const double err = std::fabs(c.got - c.want);
            if (c.tol > 0) worst = std::max(worst, err / c.tol);
            ASSERT_TRUE(std::isfinite(c.want)) << f.name << "(" << d(x) << "): the reference";
            ASSERT_LE(err, c.tol) << f.name << "(" << d(x) << ") = " << c.got << ", reference " << c.want;
        };
        for (int64_t r = INT32_MIN; r <= INT32_MAX; r += 40009) {
            one(static_cast<int32_t>(r));
            if (::testing::Test::HasFatalFailure()) return;
        }
        for (int32_t r : {INT32_MIN, INT32_MIN + 1, -65537, -65536, -65535, -1, 0, 1, 65535, 65536, 65537,
                          INT32_MAX - 1, INT32_MAX}) {
            one(r);
            if (::testing::Test::HasFatalFailure()) return;
        }
        ::testing::Test::RecordProperty(std::string(f.name) + "_worst_of_tolerance", std::to_string(worst));
    }
}

}  // namespace
