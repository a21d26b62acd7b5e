// Fixed-point numbers for noneuclid: a signed 32-bit integer with a compile-time number of
// fractional bits (a "Q" format).
//
// Formats used in the project
//   fixed  = Q16.16  lengths, curvature, screen coordinates, radians. Range [-32768, 32768),
//                    step 2^-16 = 1.53e-5 (half a step, 7.6e-6, is the rounding error floor).
//   unit   = Q2.30   values in [-2, 2): sines, cosines, unit vectors. Step 9.3e-10.
// Tables inside the library use other Q formats; each says which next to its declaration.
//
// Overflow: every operation saturates to the representable range [min(), max()] instead of
// wrapping. Nothing is undefined behaviour: no signed overflow, no shift of a negative value
// by more than its width, no division by zero. Conversions from double round to nearest,
// saturate, and map NaN to 0. Division by zero returns max() or min() with the sign of the
// dividend (0/0 is 0). A saturated value is a visible error (a body pinned to the rim), never
// silent garbage.
//
// No OS headers, no heap: this header is usable on a microcontroller.
#pragma once

#include <compare>
#include <cstdint>
#include <type_traits>

namespace noneuclid::fx {

namespace detail {
constexpr int32_t saturate32(int64_t v) noexcept {
    return v > INT32_MAX ? INT32_MAX : (v < INT32_MIN ? INT32_MIN : static_cast<int32_t>(v));
}
// n / d rounded to nearest (ties away from zero) for d > 0 and |n| < 2^62, exact, without a
// 64-bit divide instruction (fixed/division.hpp; out of line in tables.cpp).
// 32-bit ARM has no such instruction: there operator/ uses this instead of gcc's
// __aeabi_ldivmod (~400 instructions); the results are the same bit for bit.
int64_t div_round_portable(int64_t n, uint32_t d) noexcept;
inline constexpr bool kNativeDivide64 = sizeof(void*) >= 8;
// Arithmetic shift right with rounding to nearest (ties toward +infinity). s in [1, 62].
constexpr int64_t round_shift(int64_t v, int s) noexcept {
    return (v + (int64_t{1} << (s - 1))) >> s;
}
}  // namespace detail

template <int Frac>
class Fixed {
    static_assert(Frac >= 1 && Frac <= 30, "Q format must keep a sign bit and one integer bit");

public:
    static constexpr int frac_bits = Frac;
    static constexpr int32_t one_raw = int32_t{1} << Frac;

    constexpr Fixed() noexcept = default;
    // From an integer: exact when in range, saturating otherwise.
    constexpr explicit Fixed(int v) noexcept
        : raw_(detail::saturate32(static_cast<int64_t>(v) * one_raw)) {}
    // From a double: round to nearest, saturate, NaN -> 0. Usable at compile time.
    constexpr explicit Fixed(double v) noexcept : raw_(from_double_raw(v)) {}

    static constexpr Fixed from_raw(int32_t r) noexcept {
        Fixed f;
        f.raw_ = r;
        return f;
    }
    static constexpr Fixed max() noexcept { return from_raw(INT32_MAX); }
    static constexpr Fixed min() noexcept { return from_raw(INT32_MIN); }
    static constexpr Fixed epsilon() noexcept { return from_raw(1); }

    constexpr int32_t raw() const noexcept { return raw_; }
    constexpr double to_double() const noexcept { return static_cast<double>(raw_) / one_raw; }
    constexpr float to_float() const noexcept { return static_cast<float>(to_double()); }
    constexpr explicit operator double() const noexcept { return to_double(); }
    constexpr explicit operator float() const noexcept { return to_float(); }
    // Truncates toward negative infinity (floor), like an arithmetic shift.
    constexpr int floor_int() const noexcept { return raw_ >> Frac; }

    // Change of Q format: rounds to nearest when bits are dropped, saturates when the
    // target cannot hold the value.
    template <int F2>
    constexpr Fixed<F2> as() const noexcept {
        if constexpr (F2 >= Frac)
            return Fixed<F2>::from_raw(
                detail::saturate32(static_cast<int64_t>(raw_) * (int64_t{1} << (F2 - Frac))));
        else
            return Fixed<F2>::from_raw(
                detail::saturate32(detail::round_shift(raw_, Frac - F2)));
    }

    friend constexpr Fixed operator+(Fixed a, Fixed b) noexcept {
        return from_raw(detail::saturate32(int64_t{a.raw_} + b.raw_));
    }
    friend constexpr Fixed operator-(Fixed a, Fixed b) noexcept {
        return from_raw(detail::saturate32(int64_t{a.raw_} - b.raw_));
    }
    friend constexpr Fixed operator-(Fixed a) noexcept {
        return from_raw(detail::saturate32(-int64_t{a.raw_}));
    }
    friend constexpr Fixed operator+(Fixed a) noexcept { return a; }
    // Product rounded to nearest.
    friend constexpr Fixed operator*(Fixed a, Fixed b) noexcept {
        return from_raw(detail::saturate32(detail::round_shift(int64_t{a.raw_} * b.raw_, Frac)));
    }
    friend constexpr Fixed operator*(Fixed a, int k) noexcept {
        return from_raw(detail::saturate32(int64_t{a.raw_} * k));
    }
    friend constexpr Fixed operator*(int k, Fixed a) noexcept { return a * k; }
    // Quotient rounded to nearest; x/0 saturates with the sign of x, 0/0 = 0.
    friend constexpr Fixed operator/(Fixed a, Fixed b) noexcept {
        if (b.raw_ == 0) return a.raw_ > 0 ? max() : (a.raw_ < 0 ? min() : Fixed{});
        if constexpr (!detail::kNativeDivide64) {
            if (!std::is_constant_evaluated()) {
                const int64_t na = int64_t{a.raw_} * one_raw;
                const uint32_t d = b.raw_ < 0 ? 0u - static_cast<uint32_t>(b.raw_) : static_cast<uint32_t>(b.raw_);
                return from_raw(detail::saturate32(detail::div_round_portable(b.raw_ < 0 ? -na : na, d)));
            }
        }
        int64_t n = int64_t{a.raw_} * one_raw;
        int64_t d = b.raw_;
        if (d < 0) { n = -n; d = -d; }
        // Round half away from zero: (|n| + d/2) / d with the sign of n.
        int64_t q = n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d);
        return from_raw(detail::saturate32(q));
    }
    friend constexpr Fixed operator/(Fixed a, int k) noexcept { return a / Fixed(k); }

    constexpr Fixed& operator+=(Fixed b) noexcept { return *this = *this + b; }
    constexpr Fixed& operator-=(Fixed b) noexcept { return *this = *this - b; }
    constexpr Fixed& operator*=(Fixed b) noexcept { return *this = *this * b; }
    constexpr Fixed& operator/=(Fixed b) noexcept { return *this = *this / b; }

    friend constexpr bool operator==(Fixed a, Fixed b) noexcept = default;
    friend constexpr auto operator<=>(Fixed a, Fixed b) noexcept = default;

private:
    static constexpr int32_t from_double_raw(double v) noexcept {
        if (!(v == v)) return 0;  // NaN
        const double s = v * one_raw;
        if (s >= 2147483647.0) return INT32_MAX;
        if (s <= -2147483648.0) return INT32_MIN;
        const double r = s >= 0 ? s + 0.5 : s - 0.5;  // round half away from zero
        return static_cast<int32_t>(r);               // truncation toward zero after the shift
    }

    int32_t raw_ = 0;
};

using fixed = Fixed<16>;  // Q16.16: the scalar of the fixed-point engine
using unit = Fixed<30>;   // Q2.30: values known to lie in [-2, 2)

template <int F>
constexpr Fixed<F> abs(Fixed<F> x) noexcept {
    return x.raw() < 0 ? -x : x;
}
template <int F>
constexpr Fixed<F> min(Fixed<F> a, Fixed<F> b) noexcept {
    return b < a ? b : a;
}
template <int F>
constexpr Fixed<F> max(Fixed<F> a, Fixed<F> b) noexcept {
    return a < b ? b : a;
}
template <int F>
constexpr Fixed<F> clamp(Fixed<F> x, Fixed<F> lo, Fixed<F> hi) noexcept {
    return x < lo ? lo : (hi < x ? hi : x);
}

namespace literals {
// 1.5_fx: a Q16.16 constant, converted at compile time.
consteval fixed operator""_fx(long double v) { return fixed(static_cast<double>(v)); }
consteval fixed operator""_fx(unsigned long long v) { return fixed(static_cast<int>(v)); }
}  // namespace literals

}  // namespace noneuclid::fx
