// The curvature functions of docs/design.md in fixed point:
//   Sf(u) = sum (-u)^n/(2n+1)! = sin(sqrt u)/sqrt u (u > 0), sinh(sqrt -u)/sqrt -u (u < 0)
//   Cf(u) = sum (-u)^n/(2n)!   = cos(sqrt u) (u > 0),       cosh(sqrt -u) (u < 0)
//   ASf(u) = asin(sqrt u)/sqrt u (0 < u <= 1), asinh(sqrt -u)/sqrt -u (u < 0), 1 at 0
//   ATf(u) = atan(sqrt u)/sqrt u (u > 0), atanh(sqrt -u)/sqrt -u (-1 < u < 0), 1 at 0
// so that S_K(x) = x Sf(K x^2), C_K(x) = Cf(K x^2), AS_K(y) = y ASf(K y^2) and
// AT_K(t) = t ATf(K t^2) for every K; with them the products the geometry takes rounded once
// (mul_Sf, mul_ASf, mul_ATf, dot2, dot3, mul_carry).
// Q16.16 in and out, integer arithmetic only, found by argument-dependent lookup as the
// <cmath> set (fixed/cmath.hpp) is.
//
// Domains, and what happens outside them (the measured errors: docs/accuracy.md, asserted by
// tests/accuracy):
//   Sf, Cf   u in [-123, 32768): tables on |u| <= 10, closed forms beyond; saturate
//   ASf      u <= 1; ASf(u > 1) = ASf(1) = pi/2
//   ATf      u > -1; ATf(u <= -1) (infinite) saturates to max()
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "fixed/cmath.hpp"
#include "fixed/division.hpp"
#include "fixed/fixed.hpp"
#include "fixed/tables.hpp"

namespace noneuclid::fx {

namespace detail {

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

}  // namespace noneuclid::fx
