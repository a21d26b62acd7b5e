// A binary angle: an unsigned 32-bit integer where a full turn is 2^32.
//
// Adding and subtracting wrap around the circle for free (unsigned arithmetic is modular), and
// the top bits index the sine table directly. Resolution 2^-32 turn = 1.46e-9 rad. Read as a
// signed number the same bits are the angle in [-pi, pi); to_radians() uses that reading.
//
// Angles in noneuclid run counter-clockwise from east as seen on screen (docs/design.md).
#pragma once

#include <cstdint>

#include "fixed/fixed.hpp"

namespace noneuclid::fx {

class angle {
public:
    static constexpr uint32_t quarter_turn = 0x40000000u;
    static constexpr uint32_t half_turn = 0x80000000u;

    constexpr angle() noexcept = default;
    static constexpr angle from_raw(uint32_t r) noexcept {
        angle a;
        a.raw_ = r;
        return a;
    }
    // Compile-time / reference conversions from double. Any finite value; wraps.
    static constexpr angle from_turns(double turns) noexcept {
        if (!(turns == turns) || turns > 1e15 || turns < -1e15) return angle{};
        const double frac = turns - static_cast<double>(static_cast<int64_t>(turns));
        const double units = frac * 4294967296.0;
        const int64_t r = static_cast<int64_t>(units >= 0 ? units + 0.5 : units - 0.5);
        return from_raw(static_cast<uint32_t>(static_cast<uint64_t>(r)));
    }
    static constexpr angle from_radians(double rad) noexcept {
        return from_turns(rad / 6.283185307179586476925);
    }
    static constexpr angle from_degrees(double deg) noexcept { return from_turns(deg / 360.0); }

    // Radians in Q16.16 (any value; wraps modulo 2*pi) to a binary angle. Exact to about one
    // unit of 2^-32 turn for |x| < 32768: the constant 2^32/(2*pi) is carried in 62 bits.
    static constexpr angle from_radians(fixed x) noexcept {
        // units = raw * (2^32 / 2pi) / 2^16, with 2^32/2pi = kMi + kMf / 2^32.
        constexpr int64_t kMi = 683565275;       // floor(2^32 / (2 pi))
        constexpr int64_t kMf = 2475754826;      // frac(2^32 / (2 pi)) * 2^32
        const int64_t raw = x.raw();
        const int64_t hi = raw * kMi;            // |.| < 2^61
        const int64_t lo = (raw * kMf) >> 32;    // |.| < 2^31
        const int64_t units = (hi + lo + (int64_t{1} << 15)) >> 16;
        return from_raw(static_cast<uint32_t>(static_cast<uint64_t>(units)));
    }

    constexpr uint32_t raw() const noexcept { return raw_; }
    // The same bits read as a signed angle in [-2^31, 2^31): [-pi, pi).
    constexpr int32_t signed_raw() const noexcept { return static_cast<int32_t>(raw_); }
    // Radians in [-pi, pi) as Q16.16, rounded to nearest.
    constexpr fixed to_radians() const noexcept {
        // Q16 = s * 2 pi / 2^16 = s * (2 pi * 2^29) / 2^45, |s * kC| < 2^62.7.
        constexpr int64_t kC = 3373259426;  // 2 pi * 2^29
        return fixed::from_raw(
            static_cast<int32_t>(detail::round_shift(int64_t{signed_raw()} * kC, 45)));
    }
    constexpr double to_radians_double() const noexcept {
        return signed_raw() * (6.283185307179586476925 / 4294967296.0);
    }
    constexpr double to_degrees_double() const noexcept {
        return signed_raw() * (360.0 / 4294967296.0);
    }

    friend constexpr angle operator+(angle a, angle b) noexcept { return from_raw(a.raw_ + b.raw_); }
    friend constexpr angle operator-(angle a, angle b) noexcept { return from_raw(a.raw_ - b.raw_); }
    friend constexpr angle operator-(angle a) noexcept { return from_raw(0u - a.raw_); }
    friend constexpr angle operator*(angle a, int32_t k) noexcept {
        return from_raw(a.raw_ * static_cast<uint32_t>(k));
    }
    friend constexpr angle operator*(int32_t k, angle a) noexcept { return a * k; }
    // Arithmetic shift of the signed reading: halves the angle toward zero within [-pi, pi).
    constexpr angle half() const noexcept {
        return from_raw(static_cast<uint32_t>(signed_raw() >> 1));
    }
    constexpr angle& operator+=(angle b) noexcept { return *this = *this + b; }
    constexpr angle& operator-=(angle b) noexcept { return *this = *this - b; }
    friend constexpr bool operator==(angle a, angle b) noexcept = default;

private:
    uint32_t raw_ = 0;
};

}  // namespace noneuclid::fx
