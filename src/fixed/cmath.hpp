// The fixed-point <cmath>: the elementary functions on Q16.16 (`fixed`), from lookup tables
// with linear interpolation (the paper's lookup-table idea), integer arithmetic only, no OS, no
// heap, no floating point. Each takes and returns Q16.16 unless it says otherwise, and is
// found by argument-dependent lookup from code templated on the scalar:
//     template <class T> T f(T x) { using std::sin; return sin(x); }
// calls std::sin for double and fx::sin for fixed.
//
// Domains, and what happens outside them (the measured errors: docs/accuracy.md, asserted by
// tests/accuracy):
//   sin, cos (angle)     any angle
//   sin, cos (fixed)     any x, radians (|x| < 32768 wraps exactly)
//   atan2 -> angle       any (y, x); atan2(0, 0) = 0
//   atan2 -> fixed       any (y, x), result in (-pi, pi]
//   asin, acos           [-1, 1]; outside: clamped to +-1. Near +-1 (|x| > 1/2)
//                        asin(x) = pi/2 - 2 asin(sqrt((1-x)/2)), so the steep ends are as
//                        accurate as the middle.
//   sqrt                 [0, 32768), correctly rounded; negative x returns 0
//   exp                  [-11.1, 10.39]; saturates above
//   log                  (0, 32768); log(x <= 0) returns min()
//   sinh, cosh           |x| <= 10.4 (11.09 cosh); saturate beyond
//   asinh                any x
//   acosh                [1, 32768); acosh(x < 1) returns 0
//   hypot                any (x, y), correctly rounded; saturates
#pragma once

#include <cstdint>

#include "fixed/angle.hpp"
#include "fixed/division.hpp"
#include "fixed/fixed.hpp"
#include "fixed/tables.hpp"

namespace noneuclid::fx {

namespace detail {

inline constexpr int32_t kPiQ16 = 205887;          // pi * 2^16
inline constexpr int64_t kHalfPiQ30 = 1686629713;  // pi/2 * 2^30
inline constexpr uint64_t kLn2Q32 = 2977044472;    // ln 2 * 2^32
inline constexpr uint64_t kLog2eM1Q32 = 1901360723;  // (log2 e - 1) * 2^32


// Rounded conversion of a Q32 value in int64 to Q16.16, saturating.
constexpr fixed q32_to_fixed(int64_t v) noexcept {
    if (v >= (int64_t{1} << 47)) return fixed::max();
    if (v < -(int64_t{1} << 47)) return fixed::min();
    return fixed::from_raw(saturate32(round_shift(v, 16)));
}

// sin of a binary angle in Q1.30.
inline int32_t sin_q30(uint32_t a) noexcept {
    const uint32_t i = a >> (32 - tables::kSinBits);
    const uint32_t f = (a >> (16 - tables::kSinBits)) & 0xFFFFu;
    const int32_t t0 = tables::sin_q30[i], t1 = tables::sin_q30[i + 1];
    return t0 + static_cast<int32_t>((int64_t{t1 - t0} * f) >> 16);
}

// Non-negative radians x in Q(frac) (x < 2^40) to a binary angle.
constexpr uint32_t radians_to_units(uint64_t x, int frac) noexcept {
    constexpr uint64_t kMi = 683565275, kMf = 2475754826;  // 2^32/(2 pi) = kMi + kMf/2^32
    const uint64_t units = x * kMi + ((x * kMf) >> 32);
    return static_cast<uint32_t>((units + (uint64_t{1} << (frac - 1))) >> frac);
}

// asin(x) for x in [0, 1/2] given as Q32, result Q2.30.
inline int32_t asin_small_q30(uint64_t x_q32) noexcept {
    constexpr int shift = 32 - tables::kAsinBits;
    const uint32_t i = static_cast<uint32_t>(x_q32 >> shift);
    const uint64_t f = x_q32 & ((uint64_t{1} << shift) - 1);
    const int32_t t0 = tables::asin_q30[i], t1 = tables::asin_q30[i + 1];
    return t0 + static_cast<int32_t>((int64_t{t1 - t0} * static_cast<int64_t>(f)) >> shift);
}

// asin(x) for x in [0, 1] given as Q32 (x_q32 <= 2^32), result Q2.30.
inline int32_t asin_q30(uint64_t x_q32) noexcept {
    if (x_q32 <= (uint64_t{1} << 31)) return asin_small_q30(x_q32);
    if (x_q32 >= (uint64_t{1} << 32)) return static_cast<int32_t>(kHalfPiQ30);
    // asin x = pi/2 - 2 asin(sqrt((1 - x)/2)); sqrt of ((1-x) * 2^31) is the Q32 root.
    const uint64_t s = isqrt64(((uint64_t{1} << 32) - x_q32) << 31);
    return static_cast<int32_t>(kHalfPiQ30 - 2 * int64_t{asin_small_q30(s)});
}

// Signed x * b / 2^32 for an unsigned 32-bit b, without a 128-bit product.
constexpr int64_t mul_q32(int64_t x, uint32_t b) noexcept {
    const int64_t hi = x >> 32;
    const uint64_t lo = static_cast<uint64_t>(x) & 0xFFFFFFFFu;
    return hi * static_cast<int64_t>(b) + static_cast<int64_t>((lo * b) >> 32);
}

// 2^y for y in Q32, result Q32, saturating at INT64_MAX (y >= 31); 0 for y < -33.
inline int64_t exp2_q32(int64_t y) noexcept {
    if (y >= (int64_t{31} << 32)) return INT64_MAX;
    if (y < -(int64_t{33} << 32)) return 0;
    const int k = static_cast<int>(y >> 32);  // floor
    const uint32_t f = static_cast<uint32_t>(y);
    const uint32_t j = f >> 24;
    const uint64_t r = f & 0xFFFFFFu;               // remainder < 2^-8, Q32
    const uint64_t t = (r * kLn2Q32) >> 32;         // r ln 2, Q32
    const uint64_t poly = (uint64_t{1} << 32) + t + ((t * t) >> 33);  // e^t, Q32
    const uint64_t mant = uint64_t{tables::exp2_q30[j]} * poly;     // Q62, in [1, 2.006)
    const int s = 30 - k;  // result Q32 = mant * 2^k / 2^30
    if (s <= 0) {
        const uint64_t v = mant << -s;
        return v > static_cast<uint64_t>(INT64_MAX) ? INT64_MAX : static_cast<int64_t>(v);
    }
    if (s >= 64) return 0;
    return static_cast<int64_t>((mant + (uint64_t{1} << (s - 1))) >> s);
}

// e^x for x in Q32, result Q32 (saturating, see exp2_q32).
inline int64_t exp_q32(int64_t x) noexcept {
    if (x > (int64_t{22} << 32)) return INT64_MAX;
    if (x < -(int64_t{23} << 32)) return 0;
    return exp2_q32(x + mul_q32(x, static_cast<uint32_t>(kLog2eM1Q32)));  // x log2 e
}

// e^x for x in Q16.16 (|raw| <= 2^31, so that -INT32_MIN can be passed), result Q32: one
// product for x log2 e instead of the two halves exp_q32 needs.
inline int64_t exp_q32_of_q16(int64_t raw) noexcept {
    constexpr int64_t kLog2eQ30 = 1549082005;  // log2(e) * 2^30
    return exp2_q32((raw * kLog2eQ30) >> 14);
}

// ln(v / 2^frac) for v > 0, result Q32.
inline int64_t ln_q32(uint64_t v, int frac) noexcept {
    const int n = 63 - std::countl_zero(v);
    const uint64_t m = v << (63 - n);  // Q63 mantissa in [1, 2)
    constexpr int ishift = 63 - tables::kLog2Bits;
    const uint32_t i = static_cast<uint32_t>(m >> ishift) & ((1u << tables::kLog2Bits) - 1);
    const uint64_t f = (m >> (ishift - 32)) & 0xFFFFFFFFu;
    const uint32_t t0 = tables::log2_q31[i], t1 = tables::log2_q31[i + 1];
    const uint64_t l = t0 + (((uint64_t{t1} - t0) * f) >> 32);  // log2 of mantissa, Q31
    return static_cast<int64_t>(n - frac) * static_cast<int64_t>(kLn2Q32) +
           static_cast<int64_t>((l * kLn2Q32) >> 31);
}

// ln(a + sqrt(V)) where a is Q16 and V = a'^2 +- 1 is Q32: the common tail of asinh/acosh.
// V is normalised before the root so that the root keeps as many bits as fit.
inline int64_t ln_a_plus_root_q32(uint64_t a, uint64_t v) noexcept {
    const int sh = std::countl_zero(v) & ~1;
    const uint64_t s = isqrt64(v << sh);  // Q(16 + sh/2)
    return ln_q32((a << (sh / 2)) + s, 16 + sh / 2);
}

}  // namespace detail

// ---- circular functions ----------------------------------------------------------------

// sin and cos of a binary angle in Q2.30 (more digits than Q16.16 for callers that want them).
inline unit sin_unit(angle a) noexcept { return unit::from_raw(detail::sin_q30(a.raw())); }
inline unit cos_unit(angle a) noexcept {
    return unit::from_raw(detail::sin_q30(a.raw() + angle::quarter_turn));
}
inline fixed sin(angle a) noexcept { return sin_unit(a).as<16>(); }
inline fixed cos(angle a) noexcept { return cos_unit(a).as<16>(); }
inline fixed sin(fixed x) noexcept { return sin(angle::from_radians(x)); }
inline fixed cos(fixed x) noexcept { return cos(angle::from_radians(x)); }
// sin(x/2) for x first brought into [-pi, pi): the halving is exact in the binary angle, where
// x / 2 in Q16.16 would round away half a step.
inline fixed sin_half(fixed x) noexcept { return sin(angle::from_radians(x).half()); }
// y sin(x/2), rounded once from the Q2.30 sine (y does not multiply sin's Q16.16 rounding), in
// two steps so that the sine can be kept (it often does not depend on K): sine_of_half(x), then
// mul_unit(y, that).
inline unit sine_of_half(fixed x) noexcept { return sin_unit(angle::from_radians(x).half()); }
inline fixed mul_unit(fixed y, unit s) noexcept {
    return fixed::from_raw(detail::saturate32(detail::round_shift(int64_t{y.raw()} * s.raw(), 30)));
}

// The direction of (x, y) as a binary angle, counter-clockwise from +x. Works on the raw
// integers, so any Q format (the same for both) gives the same answer. atan2(0, 0) = 0.
inline angle atan2_angle(int32_t y_raw, int32_t x_raw) noexcept {
    if (x_raw == 0 && y_raw == 0) return angle{};
    const uint32_t ax = x_raw < 0 ? 0u - static_cast<uint32_t>(x_raw) : static_cast<uint32_t>(x_raw);
    const uint32_t ay = y_raw < 0 ? 0u - static_cast<uint32_t>(y_raw) : static_cast<uint32_t>(y_raw);
    const bool steep = ay > ax;
    const uint32_t num = steep ? ax : ay, den = steep ? ay : ax;
    // tan of the octant angle, num / den in Q32 (<= 1; on 32-bit targets, through the
    // reciprocal of den normalised to [2^31, 2^32), within a few units of 2^-32).
    uint64_t t;
    if constexpr (detail::kNativeDivide64 && detail::kDivideInstruction) {
        t = (uint64_t{num} << 32) / den;
    } else if constexpr (detail::kNativeDivide64) {
        t = detail::udiv_floor_reciprocal(uint64_t{num} << 32, den);  // the same quotient
    } else {
        const int sh = std::countl_zero(den);
        t = (uint64_t{num << sh} * detail::recip_q62(den << sh)) >> 30;
    }
    constexpr int shift = 32 - tables::kAtanBits;
    const uint32_t i = static_cast<uint32_t>(t >> shift);
    const uint64_t f = t & ((uint64_t{1} << shift) - 1);
    const uint32_t t0 = tables::atan_units[i], t1 = tables::atan_units[i + 1];
    uint32_t a = t0 + static_cast<uint32_t>((uint64_t{t1 - t0} * f) >> shift);
    if (steep) a = angle::quarter_turn - a;
    if (x_raw < 0) a = angle::half_turn - a;
    if (y_raw < 0) a = 0u - a;
    return angle::from_raw(a);
}
template <int F>
inline angle atan2_angle(Fixed<F> y, Fixed<F> x) noexcept {
    return atan2_angle(y.raw(), x.raw());
}
// Radians in (-pi, pi], like std::atan2 (for y = +0).
inline fixed atan2(fixed y, fixed x) noexcept {
    const angle a = atan2_angle(y, x);
    return a.raw() == angle::half_turn ? fixed::from_raw(detail::kPiQ16) : a.to_radians();
}
inline fixed atan(fixed x) noexcept { return atan2(x, fixed(1)); }

inline fixed asin(fixed x) noexcept {
    const int32_t r = x.raw();
    const uint64_t a = r < 0 ? 0u - static_cast<uint32_t>(r) : static_cast<uint32_t>(r);
    const int32_t v = detail::asin_q30(a > 65536 ? uint64_t{1} << 32 : a << 16);
    const int32_t q16 = static_cast<int32_t>(detail::round_shift(v, 14));
    return fixed::from_raw(r < 0 ? -q16 : q16);
}
inline fixed acos(fixed x) noexcept {
    const int32_t r = x.raw();
    const uint64_t a = r < 0 ? 0u - static_cast<uint32_t>(r) : static_cast<uint32_t>(r);
    const int64_t v = detail::asin_q30(a > 65536 ? uint64_t{1} << 32 : a << 16);
    return fixed::from_raw(static_cast<int32_t>(
        detail::round_shift(r < 0 ? detail::kHalfPiQ30 + v : detail::kHalfPiQ30 - v, 14)));
}

// ---- roots, exponentials, logarithms -----------------------------------------------------

// Correctly rounded square root; sqrt(x < 0) = 0.
inline fixed sqrt(fixed x) noexcept {
    if (x.raw() <= 0) return fixed{};
    const uint64_t v = static_cast<uint64_t>(x.raw()) << 16;
    uint64_t r = detail::isqrt64(v);
    if (v - r * r > r) ++r;  // round to nearest: v >= (r + 1/2)^2
    return fixed::from_raw(static_cast<int32_t>(r));
}

inline fixed exp(fixed x) noexcept {
    return detail::q32_to_fixed(detail::exp_q32_of_q16(x.raw()));
}
// Natural logarithm; log(x <= 0) returns min() (-32768, "minus infinity").
inline fixed log(fixed x) noexcept {
    if (x.raw() <= 0) return fixed::min();
    return detail::q32_to_fixed(detail::ln_q32(static_cast<uint64_t>(x.raw()), 16));
}

inline fixed cosh(fixed x) noexcept {
    const int64_t e1 = detail::exp_q32_of_q16(x.raw());
    const int64_t e2 = detail::exp_q32_of_q16(-int64_t{x.raw()});
    return detail::q32_to_fixed(e1 / 2 + e2 / 2 + (e1 & e2 & 1));
}
inline fixed sinh(fixed x) noexcept {
    const int64_t e1 = detail::exp_q32_of_q16(x.raw());
    const int64_t e2 = detail::exp_q32_of_q16(-int64_t{x.raw()});
    return detail::q32_to_fixed((e1 - e2) / 2);
}
inline fixed asinh(fixed x) noexcept {
    const int32_t r = x.raw();
    const uint64_t a = r < 0 ? 0u - static_cast<uint32_t>(r) : static_cast<uint32_t>(r);
    const fixed v = detail::q32_to_fixed(detail::ln_a_plus_root_q32(a, a * a + (uint64_t{1} << 32)));
    return r < 0 ? -v : v;
}
// acosh(x < 1) returns 0.
inline fixed acosh(fixed x) noexcept {
    if (x.raw() <= 65536) return fixed{};
    const uint64_t a = static_cast<uint32_t>(x.raw());
    return detail::q32_to_fixed(detail::ln_a_plus_root_q32(a, (a - 65536) * (a + 65536)));
}

// sqrt(x^2 + y^2) without overflow in the squares (64-bit sum), correctly rounded.
inline fixed hypot(fixed x, fixed y) noexcept {
    const int64_t a = x.raw(), b = y.raw();
    const uint64_t v = static_cast<uint64_t>(a * a) + static_cast<uint64_t>(b * b);  // < 2^63
    uint64_t r = detail::isqrt64(v);
    if (v - r * r > r) ++r;
    return fixed::from_raw(detail::saturate32(static_cast<int64_t>(r)));
}

}  // namespace noneuclid::fx
