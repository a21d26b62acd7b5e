// Fixed-point elementary functions: lookup tables with linear interpolation (the paper's
// lookup-table idea), integer arithmetic only, no OS, no heap, no floating point.
//
// Every function takes and returns Q16.16 (`fixed`) unless it says otherwise, and is found by
// argument-dependent lookup from code templated on the scalar:
//     template <class T> T f(T x) { using std::sin; return sin(x); }
// calls std::sin for double and fx::sin for fixed.
//
// Domains, accuracy (max error against std:: double, measured by `noneuclid accuracy` and
// asserted by tests/accuracy; see README) and what happens outside the domain:
//   sin, cos (angle)     any angle                  abs 8.4e-6
//   sin, cos (fixed)     any x, radians             abs 8.4e-6 (|x| < 32768 wraps exactly)
//   atan2 -> angle       any (y, x)                 abs 3.5e-7 rad; atan2(0, 0) = 0
//   atan2 -> fixed       any (y, x)                 abs 7.9e-6 rad, in (-pi, pi]
//   asin, acos           [-1, 1]                    abs 8e-6 rad; outside: clamped to +-1.
//                        Near +-1 (|x| > 1/2) asin(x) = pi/2 - 2 asin(sqrt((1-x)/2)), so the
//                        steep ends are as accurate as the middle.
//   sqrt                 [0, 32768)                 within 1/2 step (correctly rounded);
//                                                   relative <= 2e-5 for x >= 0.15;
//                                                   negative x returns 0
//   exp                  [-11.1, 10.39]             relative 1e-6 above 0.1; saturates above
//   log                  (0, 32768)                 abs 8e-6; log(x <= 0) returns min()
//   sinh, cosh           |x| <= 10.4 (11.09 cosh)   relative 1e-6 where |result| >= 0.25;
//                                                   saturate beyond
//   asinh                any x                      abs 8e-6
//   acosh                [1, 32768)                 abs 8e-6; acosh(x < 1) returns 0
//   Sf, Cf               u in [-123, 32768)         abs 8e-6 on |u| <= 10 (the table);
//                                                   beyond, relative 2e-5; saturate
//   ASf                  u <= 1                     abs 8e-6; ASf(u > 1) = ASf(1) = pi/2
// (the figures above are rounded up from the accuracy report; the tests hold them.)
#pragma once

#include <array>
#include <bit>
#include <cstdint>

#include "fixed/angle.hpp"
#include "fixed/fixed.hpp"
#include "fixed/tables.hpp"

namespace noneuclid::fx {

namespace detail {

inline constexpr int32_t kPiQ16 = 205887;          // pi * 2^16
inline constexpr int64_t kHalfPiQ30 = 1686629713;  // pi/2 * 2^30
inline constexpr uint64_t kLn2Q32 = 2977044472;    // ln 2 * 2^32
inline constexpr uint64_t kLog2eM1Q32 = 1901360723;  // (log2 e - 1) * 2^32
inline constexpr int64_t kOneQ32 = int64_t{1} << 32;

// Rounded conversion of a Q32 value in int64 to Q16.16, saturating.
constexpr fixed q32_to_fixed(int64_t v) noexcept {
    if (v >= (int64_t{1} << 47)) return fixed::max();
    if (v < -(int64_t{1} << 47)) return fixed::min();
    return fixed::from_raw(saturate32(round_shift(v, 16)));
}

// Division. 64-bit targets (aarch64, x86-64) have a 64-bit divide instruction and use it.
// 32-bit ARM has none (gcc calls __aeabi_uldivmod, ~400 instructions), so there every
// division goes through a reciprocal: a table seed (18 bits) and one Newton step, all in
// 32x32->64 products. isqrt64 and div_round are exact either way, so both paths give the same
// results; the template parameter lets the tests run the portable path on any machine. (On
// 32-bit targets atan2's tangent comes within a few units of 2^-32 instead: 1e-9 rad.)
// (kNativeDivide64 is declared in fixed.hpp, where operator/ uses it too.)
//
// Where the geometry divides many times per frame (a quotient per tessellated point, a square
// root's Newton step, atan2's tangent), kDivideInstruction says which kernel to use: the
// hardware's 64-bit divide where there is one, else the reciprocal (table seed, Newton step,
// an exact correction on the remainder). Both give the same bits. (Measured on x86-64, AMD
// EPYC, with bench_geometry: the reciprocal was 20-50% slower per point than the divide
// instruction, so x86-64 keeps the instruction.)
inline constexpr bool kDivideInstruction = kNativeDivide64;

// 2^62 / d for d in [2^31, 2^32): result in (2^30, 2^31], relative error < 2^-30.
inline uint32_t recip_q62(uint32_t d) noexcept {
    const uint32_t i = (d >> 23) & 255u;  // d / 2^31 = 1 + (i + f) / 256
    const uint32_t f = (d >> 7) & 0xFFFFu;
    const uint32_t t0 = tables::recip_q31[i], t1 = tables::recip_q31[i + 1];
    uint32_t r = t0 - static_cast<uint32_t>((uint64_t{t0 - t1} * f) >> 16);
    // Newton: r += r * (2^62 - d r) / 2^62. |e| < 2^46, so e >> 24 keeps the product < 2^53.
    const int64_t e = static_cast<int64_t>((uint64_t{1} << 62) - uint64_t{d} * r);
    r = static_cast<uint32_t>(int64_t{r} + ((int64_t{r} * (e >> 24)) >> 38));
    return r;
}

// n / d for d > 0, to within a few units (relative error < 2^-29): n * (2^62/d') >> ...
template <bool Native = kNativeDivide64>
inline uint64_t udiv_approx(uint64_t n, uint32_t d) noexcept {
    if constexpr (Native) return n / d;
    const int sh = std::countl_zero(d);
    const uint64_t r = recip_q62(d << sh);  // ~ 2^(62 + sh) / d
    const uint64_t nr = (n >> 32) * r + (((n & 0xFFFFFFFFu) * r) >> 32);  // (n r) / 2^32
    return sh <= 30 ? nr >> (30 - sh) : nr << (sh - 30);
}

// n / d rounded to nearest (ties away from zero) for d > 0, exact; |n| < 2^62.
template <bool Native = kNativeDivide64>
inline int64_t div_round(int64_t n, uint32_t d) noexcept {
    const uint64_t a = n < 0 ? 0u - static_cast<uint64_t>(n) : static_cast<uint64_t>(n);
    if constexpr (Native) {
        const uint64_t q = a / d + (2 * (a % d) >= d);
        return n < 0 ? -static_cast<int64_t>(q) : static_cast<int64_t>(q);
    }
    uint64_t q = udiv_approx<false>(a, d);
    // One refinement on the remainder (error now a few units however large the quotient),
    // then at most a few exact steps to the floor.
    const int64_t rem = static_cast<int64_t>(a - q * d);
    if (rem >= 0)
        q += udiv_approx<false>(static_cast<uint64_t>(rem), d);
    else {
        const uint64_t down = udiv_approx<false>(static_cast<uint64_t>(-rem), d) + 1;
        q = down > q ? 0 : q - down;
    }
    while (q > 0 && q * d > a) --q;  // now floor or below
    while (a - q * d >= d) ++q;      // now the floor
    if (2 * (a - q * d) >= d) ++q;   // round
    return n < 0 ? -static_cast<int64_t>(q) : static_cast<int64_t>(q);
}

// Division of many numerators by one divisor, exactly as fixed::operator/ rounds (to nearest,
// ties away from zero, saturating): the reciprocal (table seed + Newton) is taken once, then
// each quotient costs a 32x32 -> 64 product or two and an exact correction on the remainder,
// instead of a 64-bit divide (x86: tens of cycles; 32-bit ARM: a ~400-instruction libcall).
// The geometry divides every tessellated point of an edge by the same Sf(K d^2).
template <bool Native = kDivideInstruction>
class Divisor {
public:
    explicit Divisor(int32_t d_raw) noexcept
        : neg_(d_raw < 0), d_(d_raw < 0 ? 0u - static_cast<uint32_t>(d_raw) : static_cast<uint32_t>(d_raw)) {
        if (d_ == 0 || Native) return;  // the divide instruction needs no reciprocal
        sh_ = std::countl_zero(d_);
        r_ = recip_q62(d_ << sh_);  // ~ 2^(62 + sh) / d
    }
    // (x_raw * 2^16) / d rounded to nearest, saturated to 32 bits: fixed(x) / fixed(d).
    int32_t quotient_q16(int32_t x_raw) const noexcept {
        if (d_ == 0) return x_raw > 0 ? INT32_MAX : (x_raw < 0 ? INT32_MIN : 0);
        const bool neg = (x_raw < 0) != neg_;
        const uint64_t a = static_cast<uint64_t>(x_raw < 0 ? 0 - int64_t{x_raw} : int64_t{x_raw}) << 16;  // < 2^47
        uint64_t q;
        if constexpr (Native) {
            q = a / d_ + (2 * (a % d_) >= d_);
        } else {
            const uint64_t nr = (a >> 32) * r_ + (((a & 0xFFFFFFFFu) * r_) >> 32);  // (a r) / 2^32
            q = sh_ <= 30 ? nr >> (30 - sh_) : nr << (sh_ - 30);
            // Relative error < 2^-29: within 8 units of a / d while it is below 2^32, and
            // beyond that the result saturates anyway.
            if (q >= (uint64_t{1} << 32)) return neg ? INT32_MIN : INT32_MAX;
            int64_t rem = static_cast<int64_t>(a) - static_cast<int64_t>(q * d_);
            while (rem < 0) --q, rem += d_;
            while (rem >= static_cast<int64_t>(d_)) ++q, rem -= d_;
            q += 2 * static_cast<uint64_t>(rem) >= d_;
        }
        const int64_t s = neg ? -static_cast<int64_t>(q) : static_cast<int64_t>(q);
        return saturate32(s);
    }

private:
    bool neg_;
    uint32_t d_;
    int sh_ = 0;
    uint64_t r_ = 0;
};

// floor(n / d) for d > 0 and a quotient below 2^33, exact: the reciprocal's estimate (within
// 16 units there) corrected on the remainder.
inline uint64_t udiv_floor_reciprocal(uint64_t n, uint32_t d) noexcept {
    uint64_t q = udiv_approx<false>(n, d);
    int64_t rem = static_cast<int64_t>(n - q * d);  // small: the estimate is close
    while (rem < 0) --q, rem += d;
    while (rem >= static_cast<int64_t>(d)) ++q, rem -= d;
    return q;
}

// floor(sqrt(v)) for any 64-bit v: table seed (18 bits), one Newton step taken on the small
// remainder (so the reciprocal's own error barely matters), exact fix-up.
template <bool Native = kDivideInstruction>
inline uint32_t isqrt64(uint64_t v) noexcept {
    if (v == 0) return 0;
    const int sh = std::countl_zero(v) & ~1;
    const uint64_t m = v << sh;  // in [2^62, 2^64)
    const uint32_t i = static_cast<uint32_t>(m >> 56) - 64;
    const uint64_t f = (m >> 24) & 0xFFFFFFFFu;
    const uint32_t t0 = tables::sqrt_q31[i], t1 = tables::sqrt_q31[i + 1];
    uint64_t r = (uint64_t{t0} + (((uint64_t{t1} - t0) * f) >> 32)) << 1;  // in [2^31, 2^32]
    if (r > 0xFFFFFFFFu) r = 0xFFFFFFFFu;
    if constexpr (Native) {
        r = (r + m / r) >> 1;  // Newton; from above, so never below the floor
    } else {
        // r += (m - r^2) / (2 r): |m - r^2| < 2^48, (m - r^2) / 2^17 fits 31 bits.
        const int64_t e = static_cast<int64_t>(m - r * r);
        const int64_t inv = recip_q62(static_cast<uint32_t>(r));  // 2^62 / r
        r = static_cast<uint64_t>(static_cast<int64_t>(r) + (((e >> 17) * inv) >> 46));
    }
    if (r > 0xFFFFFFFFu) r = 0xFFFFFFFFu;
    while (r * r > m) --r;
    while (r < 0xFFFFFFFFu && (r + 1) * (r + 1) <= m) ++r;
    return static_cast<uint32_t>(r >> (sh / 2));
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

// Linear interpolation in a table of Q(Frac) values at u = lo + i / 2^StepBits, for a
// Q16.16 argument u_raw in [lo, lo + (N - 2) / 2^StepBits]; the result is rounded to Q16.16.
// lerp_table_raw gives the interpolated value in the table's own Q(Frac), unrounded.
// (The pointer form is for loops that hold the table's address in a register.)
template <int StepBits>
[[gnu::always_inline]] inline int64_t lerp_table_raw(const int32_t* t, int32_t u_raw, int32_t lo_raw) noexcept {
    constexpr int shift = 16 - StepBits;
    const uint32_t off = static_cast<uint32_t>(u_raw - lo_raw);
    const uint32_t i = off >> shift, f = off & ((1u << shift) - 1);
    const int32_t t0 = t[i], t1 = t[i + 1];
    return t0 + ((int64_t{t1 - t0} * f) >> shift);
}
template <int StepBits, std::size_t N>
inline int64_t lerp_table_raw(const std::array<int32_t, N>& t, int32_t u_raw, int32_t lo_raw) noexcept {
    return lerp_table_raw<StepBits>(t.data(), u_raw, lo_raw);
}
template <int StepBits, int Frac, std::size_t N>
inline fixed lerp_table(const std::array<int32_t, N>& t, int32_t u_raw, int32_t lo_raw) noexcept {
    return fixed::from_raw(static_cast<int32_t>(round_shift(lerp_table_raw<StepBits>(t, u_raw, lo_raw), Frac - 16)));
}
// x times a table value, rounded once: x (Q16) * value (Q(Frac)) -> Q16.
template <int Frac>
inline fixed times_table_value(fixed x, int64_t value) noexcept {
    return fixed::from_raw(saturate32(round_shift(int64_t{x.raw()} * value, Frac)));
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

// For u < 0 beyond the tables: s = sqrt(-u) in Q27 and e^s, e^-s in Q32. The root carries 27
// fractional bits because cosh s amplifies its error by sinh s (~270 at u = -40). Callers
// saturate first for u <= -512 (Sf and Cf are far beyond Q16.16 there), so -u * 2^54 fits.
struct hyperbolic_parts {
    uint64_t s_q27;
    int64_t plus, minus;
};
inline hyperbolic_parts hyperbolic_of_root(int32_t u_raw) noexcept {
    const uint64_t v = static_cast<uint64_t>(-int64_t{u_raw});
    const uint64_t s = isqrt64(v << 38);
    const int64_t x = static_cast<int64_t>(s << 5);
    return {s, exp_q32(x), exp_q32(-x)};
}
inline constexpr int32_t kHyperbolicSaturate = -(512 << 16);

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

// ---- the curvature functions of design.md ------------------------------------------------
//   Sf(u) = sum (-u)^n/(2n+1)! = sin(sqrt u)/sqrt u (u > 0), sinh(sqrt -u)/sqrt -u (u < 0)
//   Cf(u) = sum (-u)^n/(2n)!   = cos(sqrt u) (u > 0),       cosh(sqrt -u) (u < 0)
//   ASf(u) = asin(sqrt u)/sqrt u (0 < u <= 1), asinh(sqrt -u)/sqrt -u (u < 0), 1 at 0
// so that S_K(x) = x Sf(K x^2), C_K(x) = Cf(K x^2) and AS_K(y) = y ASf(K y^2) for every K.

inline fixed Sf(fixed u) noexcept {
    using namespace tables;
    const int32_t r = u.raw();
    if (r >= -(kSfCfRange << 16) && r <= (kSfCfRange << 16))
        return detail::lerp_table<kSfStepBits, 28>(sf_q28, r, -(kSfCfRange << 16));
    if (r > 0) {  // sin(s)/s with s = sqrt(u) in Q24
        const uint64_t s = detail::isqrt64(static_cast<uint64_t>(r) << 32);
        const int64_t sn = detail::sin_q30(detail::radians_to_units(s, 24));
        return fixed::from_raw(static_cast<int32_t>(detail::div_round(sn << 10, static_cast<uint32_t>(s))));
    }
    if (r <= detail::kHyperbolicSaturate) return fixed::max();
    const detail::hyperbolic_parts e = detail::hyperbolic_of_root(r);  // sinh(s)/s
    const int64_t sh = e.plus / 2 - e.minus / 2;                         // Q32
    if (sh >= (int64_t{1} << 52)) return fixed::max();                   // > 2^20 / 22.7
    return fixed::from_raw(detail::saturate32(
        detail::div_round(sh << 11, static_cast<uint32_t>(e.s_q27))));
}

inline fixed Cf(fixed u) noexcept {
    using namespace tables;
    const int32_t r = u.raw();
    if (r >= -(kSfCfRange << 16) && r <= (kSfCfRange << 16))
        return detail::lerp_table<kCfStepBits, 27>(cf_q27, r, -(kSfCfRange << 16));
    if (r > 0) {  // cos(sqrt u)
        const uint64_t s = detail::isqrt64(static_cast<uint64_t>(r) << 32);
        const int32_t c = detail::sin_q30(detail::radians_to_units(s, 24) + angle::quarter_turn);
        return fixed::from_raw(static_cast<int32_t>(detail::round_shift(c, 14)));
    }
    if (r <= detail::kHyperbolicSaturate) return fixed::max();
    const detail::hyperbolic_parts e = detail::hyperbolic_of_root(r);  // cosh(s)
    return detail::q32_to_fixed(e.plus / 2 + e.minus / 2);
}

inline fixed ASf(fixed u) noexcept {
    using namespace tables;
    const int32_t r = u.raw();
    if (r >= 65536) return fixed::from_raw(static_cast<int32_t>(detail::round_shift(detail::kHalfPiQ30, 14)));
    if (r >= -(kASfLow << 16) && r <= (1 << 15))
        return detail::lerp_table<kASfStepBits, 30>(asf_q30, r, -(kASfLow << 16));
    if (r > 0) {  // asin(s)/s, s = sqrt(u) in Q32 (u < 1 so u * 2^64 fits)
        const uint64_t s = detail::isqrt64(static_cast<uint64_t>(r) << 48);
        const int64_t as = detail::asin_q30(s);
        return fixed::from_raw(static_cast<int32_t>(detail::div_round(as << 18, static_cast<uint32_t>(s))));
    }
    // asinh(s)/s, s = sqrt(-u) in Q24; sqrt(s^2 + 1) = sqrt(1 - u).
    const uint64_t v = static_cast<uint64_t>(-int64_t{r});
    const uint64_t s = detail::isqrt64(v << 32);
    const uint64_t h = detail::isqrt64((v + 65536) << 32);
    const int64_t ash = detail::ln_q32(s + h, 24);  // Q32
    return fixed::from_raw(static_cast<int32_t>(detail::div_round(ash << 8, static_cast<uint32_t>(s))));
}

// ATf(u) = atan(sqrt u)/sqrt u (u > 0), atanh(sqrt -u)/sqrt -u (-1 < u < 0), 1 at 0, so that
// AT_K(t) = t ATf(K t^2) inverts the tangent T_K(x) = S_K(x)/C_K(x) for every K. The table
// covers [-1/2, 1] and a finer one [-15/16, -1/2]; beyond them atan2 (u > 1) or two logarithms
// (u < -15/16). ATf(u <= -1) is
// +infinity: it saturates to max().
inline fixed ATf(fixed u) noexcept {
    using namespace tables;
    const int32_t r = u.raw();
    if (r >= -(1 << 15) && r <= 65536)
        return detail::lerp_table<kATfStepBits, 30>(atf_q30, r, -(1 << 15));
    if (r >= kATfLowRaw && r < 0) return detail::lerp_table<kATfLowStepBits, 29>(atf_low_q29, r, kATfLowRaw);
    if (r <= -65536) return fixed::max();
    if (r > 0) {  // atan(s)/s, s = sqrt(u) in Q16 (s > 1): angle of (s, 1) in Q32 radians
        const fixed s = sqrt(u);
        const angle a = atan2_angle(s.raw(), 65536);
        const int64_t rad_q32 = static_cast<int64_t>((uint64_t{a.raw()} * 3373259426ull) >> 29);  // 2 pi 2^29
        return fixed::from_raw(detail::saturate32(detail::div_round(rad_q32, static_cast<uint32_t>(s.raw()))));
    }
    // atanh(z)/z = (ln(1 + z) - ln(1 - z)) / (2 z), z = sqrt(-u) in Q32, 1/sqrt 2 < z < 1.
    const uint64_t z = detail::isqrt64(static_cast<uint64_t>(-int64_t{r}) << 48);
    const int64_t at2 = detail::ln_q32((uint64_t{1} << 32) + z, 32) - detail::ln_q32((uint64_t{1} << 32) - z, 32);
    return fixed::from_raw(detail::saturate32(detail::div_round(at2 << 15, static_cast<uint32_t>(z))));
}

// a b + c d with a single rounding (the products are summed in 64 bits, like a DSP's
// multiply-accumulate): half the rounding error of (a * b) + (c * d). Saturates.
inline fixed dot2(fixed a, fixed b, fixed c, fixed d) noexcept {
    const int64_t p = int64_t{a.raw()} * b.raw(), q = int64_t{c.raw()} * d.raw();  // |.| <= 2^62
    int64_t sum;
    if (__builtin_add_overflow(p, q, &sum)) return p > 0 ? fixed::max() : fixed::min();
    if (sum >= (int64_t{1} << 62) - (int64_t{1} << 15)) return fixed::max();
    return fixed::from_raw(detail::saturate32(detail::round_shift(sum, 16)));
}

// a b + c d + e f with a single rounding, as dot2. Saturates.
inline fixed dot3(fixed a, fixed b, fixed c, fixed d, fixed e, fixed f) noexcept {
    const int64_t p = int64_t{a.raw()} * b.raw(), q = int64_t{c.raw()} * d.raw(), r = int64_t{e.raw()} * f.raw();
    int64_t sum;
    if (__builtin_add_overflow(p, q, &sum) || __builtin_add_overflow(sum, r, &sum))
        return (p > 0) + (q > 0) + (r > 0) >= 2 ? fixed::max() : fixed::min();
    if (sum >= (int64_t{1} << 62) - (int64_t{1} << 15)) return fixed::max();
    return fixed::from_raw(detail::saturate32(detail::round_shift(sum, 16)));
}

// x Sf(u), x ASf(u), x ATf(u) (that is S_K, AS_K, AT_K) with one rounding: inside the tables
// the product is taken from the table's Q28/Q30 value, so x does not multiply the Q16.16
// rounding of f(u) (worth a step or two of accuracy for x of a few units). Outside the tables,
// the product of the rounded values.
inline fixed mul_Sf(fixed x, fixed u) noexcept {
    using namespace tables;
    const int32_t r = u.raw();
    if (r >= -(kSfCfRange << 16) && r <= (kSfCfRange << 16))
        return detail::times_table_value<28>(x, detail::lerp_table_raw<kSfStepBits>(sf_q28, r, -(kSfCfRange << 16)));
    return x * Sf(u);
}
inline fixed mul_ASf(fixed x, fixed u) noexcept {
    using namespace tables;
    const int32_t r = u.raw();
    if (r >= -(kASfLow << 16) && r <= (1 << 15))
        return detail::times_table_value<30>(x, detail::lerp_table_raw<kASfStepBits>(asf_q30, r, -(kASfLow << 16)));
    return x * ASf(u);
}
inline fixed mul_ATf(fixed x, fixed u) noexcept {
    using namespace tables;
    const int32_t r = u.raw();
    if (r >= -(1 << 15) && r <= 65536)
        return detail::times_table_value<30>(x, detail::lerp_table_raw<kATfStepBits>(atf_q30, r, -(1 << 15)));
    if (r >= kATfLowRaw && r < 0)
        return detail::times_table_value<29>(x, detail::lerp_table_raw<kATfLowStepBits>(atf_low_q29, r, kATfLowRaw));
    return x * ATf(u);
}

// a b rounded down, with the part below one step carried in `carry` (Q32, in [0, 2^16)) to
// the next call: over many calls the sum of the results is the floor of the exact sum of the
// products. A body moving speed * dt per step this way covers exactly the distance its speed
// says, instead of gaining or losing up to half a step every step.
inline fixed mul_carry(fixed a, fixed b, int64_t& carry) noexcept {
    const int64_t p = int64_t{a.raw()} * b.raw() + carry;
    const int64_t q = p >> 16;  // floor
    carry = p - (q << 16);
    return fixed::from_raw(detail::saturate32(q));
}

// sqrt(x^2 + y^2) without overflow in the squares (64-bit sum), correctly rounded.
inline fixed hypot(fixed x, fixed y) noexcept {
    const int64_t a = x.raw(), b = y.raw();
    const uint64_t v = static_cast<uint64_t>(a * a) + static_cast<uint64_t>(b * b);  // < 2^63
    uint64_t r = detail::isqrt64(v);
    if (v - r * r > r) ++r;
    return fixed::from_raw(detail::saturate32(static_cast<int64_t>(r)));
}

// The slerp's sigma_k = S_K(k delta) / delta for delta = d / n, k = 0 .. n, in Q30 (int64),
// by sigma_{k+1} = 2 C_K(delta) sigma_k - sigma_{k-1} from sigma_1 = Sf(K delta^2) (design.md;
// geo::SlerpWeights). C_K(delta) and Sf are summed from their series in Q30 (|u| <= 2: the
// terms fall below 2^-34 by the ninth). False when |K delta^2| > 2 or d > 16.
inline bool slerp_sigmas(fixed K, fixed d, int n, int64_t* sigma) noexcept {
    const int64_t dr = d.raw() < 0 ? -int64_t{d.raw()} : d.raw();
    if (dr > (int64_t{1} << 20) || n < 2) return false;
    // u = K d^2 / n^2 in Q30: K d^2 is Q48 (|.| <= 2^56), / 2^18 to Q30, then / n^2.
    const int64_t kd2 = int64_t{K.raw()} * (dr * dr);
    const int64_t u = detail::div_round(detail::round_shift(kd2, 18), static_cast<uint32_t>(n * n));
    if (u > (int64_t{2} << 30) || u < -(int64_t{2} << 30)) return false;
    constexpr int64_t one = int64_t{1} << 30;
    auto mul30 = [](int64_t a, int64_t b) { return detail::round_shift(a * b, 30); };  // |a|, |b| < 2^32
    // Horner: Cf(u) = 1 - u/(1 2) (1 - u/(3 4) (1 - ...)), Sf(u) = 1 - u/(2 3) (1 - u/(4 5) (...)),
    // dividing by the constants as products with their Q30 reciprocals (no 64-bit division:
    // 32-bit ARM would call a library routine for each).
    constexpr auto inverses = [](int first) {  // round(2^30 / (j (j + 1))) for j = first, first + 2, ...
        std::array<int64_t, 10> t{};
        for (int m = 1; m < 10; ++m) {
            const int64_t j = 2 * m - 2 + first, den = j * (j + 1);
            t[static_cast<std::size_t>(m)] = ((int64_t{1} << 30) + den / 2) / den;
        }
        return t;
    };
    constexpr std::array<int64_t, 10> kC = inverses(1), kS = inverses(2);
    int64_t c = one, s = one;
    // Terms needed: the first left out, |u|^m / (2m)!, below 2^-34 (at u = 0, none: K = 0).
    const int64_t au = u < 0 ? -u : u;
    const int terms = au == 0 ? 0 : au <= (one >> 6) ? 4 : au <= (one >> 2) ? 6 : 9;
    for (int m = terms; m >= 1; --m) {
        c = one - mul30(mul30(u, c), kC[static_cast<std::size_t>(m)]);
        s = one - mul30(mul30(u, s), kS[static_cast<std::size_t>(m)]);
    }
    sigma[0] = 0, sigma[1] = s;
    const int64_t c2 = 2 * c;  // < 2^32.2 for u >= -2 (2 cosh sqrt 2 = 4.36)
    for (int k = 1; k < n; ++k) {
        // c2 sigma_k / 2^30 without overflow: sigma = hi 2^30 + lo.
        const int64_t hi = sigma[k] >> 30, lo = sigma[k] & (one - 1);
        sigma[k + 1] = c2 * hi + detail::round_shift(c2 * lo, 30) - sigma[k - 1];
    }
    return true;
}

// The azimuthal equidistant projection of the 3-vector (w, x, y) = (C_K(r), S_K(r) cos theta,
// S_K(r) sin theta): (X, Y) = r (cos theta, sin theta), in Q16.16, for w >= 0 and |x|, |y| <= 100
// (geo::project_vec checks both). With g = 2 / (1 + w) and t = (x, y) g / 2 = T_K(r/2) (cos, sin),
//   (X, Y) = 2 t ATf(K |t|^2)
// (r = 2 AT_K(T_K(r/2))). Every intermediate is kept finer than Q16.16: g in Q29 from the
// reciprocal (no divide instruction: 32-bit ARM has none, and on x86 it is the slowest step),
// t in Q24, K |t|^2 in Q28, the table interpolated on all of those bits. (Rounded to Q16.16 at
// each step instead, g = 0.07 far out at K = -0.6 kept 4 digits, and the projected point
// moved by a quarter of a pixel.) All products are 32 x 32 -> 64 bits. False, with nothing
// written, where K |t|^2 falls outside ATf's tables (beyond r = 4.1 at K = -1): the caller takes
// the general path.
[[gnu::always_inline]] inline bool equidistant_xy(fixed K, fixed w, fixed x, fixed y, fixed& X, fixed& Y) noexcept {
    const uint32_t d = static_cast<uint32_t>(int64_t{w.raw()} + 65536);  // 1 + w in Q16, >= 2^16
    const int sh = std::countl_zero(d);                                   // <= 15
    const int32_t g = static_cast<int32_t>(detail::recip_q62(d << sh) >> (16 - sh));  // 2^46 / d: g in Q29
    // t = x g / 2: Q16 * Q29 = Q45, halved and rounded to Q24 (|t| < 128 for |x| <= 100, g <= 2).
    const int32_t tx = static_cast<int32_t>(detail::round_shift(int64_t{x.raw()} * g, 22));
    const int32_t ty = static_cast<int32_t>(detail::round_shift(int64_t{y.raw()} * g, 22));
    const int64_t t2 = int64_t{tx} * tx + int64_t{ty} * ty;  // Q48, < 2^62
    // u = K t^2 in Q28: (t2 / 2^20) * K / 2^16 (Q28 * Q16 = Q44 -> Q28).
    const int64_t u = detail::round_shift(detail::round_shift(t2, 20) * K.raw(), 16);
    int64_t atf;  // ATf(u), Q30 (or Q29 below -1/2: `frac`)
    int frac = 30;
    using namespace tables;
    if (u >= -(int64_t{1} << 27) && u <= (int64_t{1} << 28)) {  // [-1/2, 1], step 2^-9: 19 bits of fraction
        const uint32_t off = static_cast<uint32_t>(u + (int64_t{1} << 27));
        const uint32_t i = off >> (28 - kATfStepBits), f = off & ((1u << (28 - kATfStepBits)) - 1);
        atf = atf_q30[i] + ((int64_t{atf_q30[i + 1] - atf_q30[i]} * f) >> (28 - kATfStepBits));
    } else if (u < 0 && u >= -(int64_t{15} << 24)) {  // [-15/16, -1/2), step 2^-12: 16 bits
        const uint32_t off = static_cast<uint32_t>(u + (int64_t{15} << 24));
        const uint32_t i = off >> (28 - kATfLowStepBits), f = off & ((1u << (28 - kATfLowStepBits)) - 1);
        atf = atf_low_q29[i] + ((int64_t{atf_low_q29[i + 1] - atf_low_q29[i]} * f) >> (28 - kATfLowStepBits));
        frac = 29;
    } else {
        return false;
    }
    // X = 2 t ATf: Q24 * Q(frac), doubled, to Q16.
    const int s = 24 + frac - 16 - 1;
    X = fixed::from_raw(detail::saturate32(detail::round_shift(int64_t{tx} * atf, s)));
    Y = fixed::from_raw(detail::saturate32(detail::round_shift(int64_t{ty} * atf, s)));
    return true;
}

// E(w) = r / S_K(r) for a point whose 3-vector has w = C_K(r) (tables::equi_q30): its
// equidistant projection is (x, y) E(w). w in Q16.16 within [0, 32); Q2.30.
// (equi_q30: tables::equi_q30.data(), for a caller that holds it in a register.)
[[gnu::always_inline]] inline int32_t equidistant_ratio_q30(const int32_t* equi_q30, uint32_t w) noexcept {
    return static_cast<int32_t>(detail::lerp_table_raw<tables::kEquiStepBits>(equi_q30, static_cast<int32_t>(w), 0));
}
[[gnu::always_inline]] inline int32_t equidistant_ratio_q30(uint32_t w) noexcept {
    return equidistant_ratio_q30(tables::equi_q30.data(), w);
}
// E(w) past the sphere's equator (tables::equi_south_q29), w in Q16.16 within [-1/2, 0); Q3.29.
[[gnu::always_inline]] inline int32_t equidistant_ratio_south_q29(int32_t w) noexcept {
    return static_cast<int32_t>(
        detail::lerp_table_raw<tables::kEquiSouthStepBits>(tables::equi_south_q29, w, tables::kEquiSouthRaw));
}

// x / d for many x and one d, bit for bit the same as operator/ (detail::Divisor). Found by
// argument-dependent lookup: geometry code writes `const auto by_d = divisor(d); by_d(x)`.
struct fixed_divisor {
    detail::Divisor<> div;
    fixed operator()(fixed x) const noexcept { return fixed::from_raw(div.quotient_q16(x.raw())); }
};
inline fixed_divisor divisor(fixed d) noexcept { return {detail::Divisor<>(d.raw())}; }
// One quotient, a / b, the same bits as operator/ (through the reciprocal where that is faster).
inline fixed quotient(fixed a, fixed b) noexcept { return fixed::from_raw(detail::Divisor<>(b.raw()).quotient_q16(a.raw())); }
// x / 4, rounded as operator/ rounds (to nearest, ties away from zero).
inline fixed quarter(fixed x) noexcept {
    const int32_t r = x.raw();
    return fixed::from_raw(r >= 0 ? static_cast<int32_t>((int64_t{r} + 2) >> 2) : static_cast<int32_t>(-((2 - int64_t{r}) >> 2)));
}

}  // namespace noneuclid::fx
