// The division kernels compute what the plain arithmetic computes, bit for bit: fx::fixed's
// operator/ on 32-bit targets (a reciprocal instead of __aeabi_ldivmod) and the per-divisor
// reciprocal fx::divisor against plain 64-bit integer division, rounded to nearest with ties
// away from zero, as fixed.hpp specifies; the reciprocal's floor. (geo::Fractions<fixed>, the
// same kernels carried along an edge: tests/geometry/test_scalar.cpp.)
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "fixed/math.hpp"

namespace {

using namespace noneuclid;
using fx::fixed;

// x / d in Q16.16 from the definition: (x 2^16) / d rounded half away from zero, saturated.
int32_t reference_div(int32_t x, int32_t d) {
    if (d == 0) return x > 0 ? INT32_MAX : (x < 0 ? INT32_MIN : 0);
    int64_t n = int64_t{x} * 65536, dd = d;
    if (dd < 0) n = -n, dd = -dd;
    const int64_t q = n >= 0 ? (n + dd / 2) / dd : -((-n + dd / 2) / dd);
    return q > INT32_MAX ? INT32_MAX : (q < INT32_MIN ? INT32_MIN : static_cast<int32_t>(q));
}

std::vector<int32_t> interesting() {
    std::vector<int32_t> v = {0, 1, -1, 2, -2, 3, 7, 255, 256, 65535, 65536, -65536, 65537, 98304, 1 << 20,
                              INT32_MAX, INT32_MIN, INT32_MIN + 1, INT32_MAX - 1, 1 << 30, -(1 << 30)};
    std::mt19937 rng(8);
    for (int i = 0; i < 300; ++i) {
        const int bits = static_cast<int>(rng() % 32);
        const int32_t x = static_cast<int32_t>(rng() >> (31 - bits % 31));
        v.push_back(x), v.push_back(-x);
    }
    return v;
}

TEST(FastPaths, OperatorDivideMatchesTheDefinition) {
    const auto vals = interesting();
    for (int32_t x : vals)
        for (int32_t d : vals) ASSERT_EQ((fixed::from_raw(x) / fixed::from_raw(d)).raw(), reference_div(x, d)) << x << " / " << d;
}

TEST(FastPaths, PortableDivisionMatchesTheDefinition) {
    const auto vals = interesting();
    for (int32_t x : vals)
        for (int32_t d : vals) {
            if (d == 0) continue;
            const int64_t n = int64_t{x} * 65536;
            const uint32_t ad = d < 0 ? 0u - static_cast<uint32_t>(d) : static_cast<uint32_t>(d);
            const int64_t q = fx::detail::div_round_portable(d < 0 ? -n : n, ad);
            const int32_t s = q > INT32_MAX ? INT32_MAX : (q < INT32_MIN ? INT32_MIN : static_cast<int32_t>(q));
            ASSERT_EQ(s, reference_div(x, d)) << x << " / " << d;
        }
}

template <bool Native>
void divisor_matches() {
    const auto vals = interesting();
    for (int32_t d : vals) {
        const fx::detail::Divisor<Native> div(d);
        for (int32_t x : vals) ASSERT_EQ(div.quotient_q16(x), reference_div(x, d)) << x << " / " << d;
    }
    // Divisors the geometry meets (Sf of an edge: about 0.3 .. 4), dense numerators.
    std::mt19937 rng(88);
    for (int i = 0; i < 2000; ++i) {
        const int32_t d = static_cast<int32_t>(rng() % (4 << 16)) + 1;
        const fx::detail::Divisor<Native> div(d);
        for (int j = 0; j < 200; ++j) {
            const int32_t x = static_cast<int32_t>(rng() % (8 << 16)) - (4 << 16);
            ASSERT_EQ(div.quotient_q16(x), reference_div(x, d)) << x << " / " << d;
        }
    }
}
TEST(FastPaths, DivisorNative) { divisor_matches<true>(); }
TEST(FastPaths, DivisorReciprocal) { divisor_matches<false>(); }
TEST(FastPaths, DivisorOfFixed) {
    for (int32_t d : interesting())
        for (int32_t x : {0, 1, -1, 12345, -98765, INT32_MAX, INT32_MIN})
            ASSERT_EQ(fx::divisor(fixed::from_raw(d))(fixed::from_raw(x)).raw(), reference_div(x, d));
}

TEST(FastPaths, QuotientAndQuarterAreOperatorDivide) {
    const auto vals = interesting();
    for (int32_t x : vals) {
        ASSERT_EQ(fx::quarter(fixed::from_raw(x)).raw(), reference_div(x, 4 << 16)) << x;
        for (int32_t d : vals) ASSERT_EQ(fx::quotient(fixed::from_raw(x), fixed::from_raw(d)).raw(), reference_div(x, d));
    }
}

// atan2's tangent num 2^32 / den (num <= den) and the like: the reciprocal gives the floor.
TEST(FastPaths, FloorDivisionByReciprocal) {
    std::mt19937_64 rng(32);
    for (int i = 0; i < 400000; ++i) {
        uint32_t den = static_cast<uint32_t>(rng() >> (32 + rng() % 32));
        if (den == 0) den = 1;
        const uint32_t num = static_cast<uint32_t>(rng() % (uint64_t{den} + 1));
        const uint64_t n = uint64_t{num} << 32;
        ASSERT_EQ(fx::detail::udiv_floor_reciprocal(n, den), n / den) << num << " / " << den;
    }
    for (uint32_t den : {1u, 2u, 3u, 0xFFFFFFFFu, 0x80000000u, 0x7FFFFFFFu, 65536u})
        for (uint32_t num : {0u, 1u, den / 2, den - 1, den}) {
            const uint64_t n = uint64_t{num} << 32;
            ASSERT_EQ(fx::detail::udiv_floor_reciprocal(n, den), n / den) << num << " / " << den;
        }
}

}  // namespace
