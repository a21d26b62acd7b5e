// Division in fixed point, exact, with or without a 64-bit divide instruction: the reciprocal
// kernels (recip_q62, udiv_approx), rounded and floored quotients (div_round,
// udiv_floor_reciprocal), many quotients by one divisor (Divisor; fx::divisor, quotient,
// quarter, the same bits as fixed's operator/), and the integer square root (isqrt64).
#pragma once

#include <bit>
#include <cstdint>

#include "fixed/fixed.hpp"
#include "fixed/tables.hpp"

namespace noneuclid::fx {

namespace detail {

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
// hardware's 64-bit divide where there is one (faster there than the reciprocal), else the
// reciprocal (table seed, Newton step, an exact correction on the remainder). Both give the
// same bits.
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

// sqrt(v) for v > 0 from the table seed alone, to within 2^-17 of it (relative): isqrt64 without
// its Newton step and exact fix-up, for where a few digits are enough.
inline uint32_t sqrt_seed(uint64_t v) noexcept {
    const int sh = std::countl_zero(v) & ~1;
    const uint64_t m = v << sh;  // in [2^62, 2^64)
    const uint32_t i = static_cast<uint32_t>(m >> 56) - 64;
    const uint64_t f = (m >> 24) & 0xFFFFFFFFu;
    const uint32_t t0 = tables::sqrt_q31[i], t1 = tables::sqrt_q31[i + 1];
    uint64_t r = (uint64_t{t0} + (((uint64_t{t1} - t0) * f) >> 32)) << 1;  // sqrt(m), in [2^31, 2^32]
    if (r > 0xFFFFFFFFu) r = 0xFFFFFFFFu;
    return static_cast<uint32_t>(r >> (sh / 2));
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

}  // namespace detail

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
