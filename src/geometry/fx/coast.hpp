// The fixed engine's coast (world::Coast; docs/accuracy.md, "The long run"): where a body that
// left a start point P = (r0, theta0) at heading chi0 is after walking distance D along its
// geodesic, and how far the frame carried from O has turned on the way, in finer numbers than
// Q16.16 (r in Q24, angles to 2^-32 turn; its accuracy is in docs/accuracy.md). The world walks
// a coast from its start at every step, so these errors are not summed over the steps, and
// keeps the start's angles as binary angles, so that the limit circle's wrap (theta + pi)
// rounds nothing.
//
// The triangle O - P - Q (Q the end), delta = chi0 - theta0 the heading against P's outward
// radial, a = r0, b = D (docs/design.md, "The 3-vector model"):
//  - Q in the frame where P lies on +x:
//        (C_a C_b - K S_a S_b cos delta,  S_a C_b + C_a S_b cos delta,  S_b sin delta).
//    Toward O (cos delta < 0) the first two are written
//        C_K(a - b) - K S_a S_b e,  S_K(a - b) + C_a S_b e,   e = 1 + cos delta = 2 cos^2(delta/2),
//    where no term is larger than Q: at K = -1 the products are e^(a+b)/4 while Q is e^r/2.
//  - Q's bearing from P's is atan2(Q_y, Q_x); its distance r = 2 AT_K(S / (1 + C)) for
//    S = |(Q_x, Q_y)|, C = Q_w (geo::arc_K; past the sphere's equator pi/sqrt K - 2 AT_K(S / (1 - C))).
//  - the carried frame turns by K times the triangle's area (Gauss-Bonnet), and the area of a
//    triangle from two sides and the angle gamma = pi - delta between them is
//        tan(K A / 2) = K T_K(a/2) T_K(b/2) sin gamma / (1 + K T_K(a/2) T_K(b/2) cos gamma),
//    so turn = 2 atan2(K s s' sin delta, c c' - K s s' cos delta) with s, c = S_K, C_K of a/2
//    and s', c' of b/2: a small angle computed directly, exactly 0 at K = 0.
//
// The numbers: S_K and C_K in Q26 from the Sf and Cf tables at u = K x^2 in Q48, sines and
// cosines in Q30 from the sine table, angles from the atan table, each table read by quadratic
// interpolation (the central second difference corrects linear interpolation's h^2 f''/8 to
// O(h^3): 2e-9 for the sine); ATf in Q30 at u in Q28; atanh from two logarithms beyond
// ATf's tables. 64-bit integers throughout, divisions exact (fx::detail::div_round,
// udiv_floor_reciprocal): the same bits on every machine, with or without a divide instruction.
//
// Domain: |K| <= 1 and 0 <= r0, D <= kCoastMax (sqrt 10: K x^2 within the Sf and Cf tables).
// coast_walk returns false outside it, and the world walks with geo::walk there instead.
#pragma once

#include <bit>
#include <cstdint>

#include "fixed/angle.hpp"
#include "fixed/cmath.hpp"
#include "fixed/division.hpp"
#include "fixed/fixed.hpp"
#include "fixed/tables.hpp"

namespace noneuclid::fx {

// sqrt 10 in Q16.16, rounded down: |K| x^2 <= 10 for |K| <= 1.
inline constexpr int32_t kCoastMaxRaw = 207243;

namespace detail::coast {

inline constexpr int kF = 26;  // fraction bits of S, C and Q

inline int64_t rshift_round(int64_t v, int s) noexcept { return (v + (int64_t{1} << (s - 1))) >> s; }

// f at a point of a table of f at lo + i h: off is (point - lo) / h in Q32 (the index above
// the low 32 bits, the fraction in them). Linear interpolation corrected by the central second
// difference (at i = 1 for i = 0; at the very end the fraction is 0 and the correction
// vanishes): in the table's format, to O(h^3).
template <class V>
inline int64_t quad(const V* t, uint64_t off) noexcept {
    const uint64_t i = off >> 32;
    const int64_t f = static_cast<int64_t>(off & 0xFFFFFFFFu);
    const int64_t t0 = static_cast<int64_t>(t[i]), t1 = static_cast<int64_t>(t[i + 1]);
    const uint64_t c = i == 0 ? 1 : i;
    const int64_t d2 = static_cast<int64_t>(t[c + 1]) - 2 * static_cast<int64_t>(t[c]) + static_cast<int64_t>(t[c - 1]);
    const int64_t g = (f * ((int64_t{1} << 32) - f)) >> 32;  // f (1 - f), Q32; f (1 - f) <= 2^62
    return t0 + (((t1 - t0) * f) >> 32) - ((g * d2) >> 33);
}

// sin and cos of a binary angle, Q30.
inline int64_t sin30(angle a) noexcept {
    const uint32_t r = a.raw();
    constexpr int low = 32 - tables::kSinBits;
    return quad(tables::sin_q30.data(), (uint64_t{r >> low} << 32) | (uint64_t{r & ((1u << low) - 1)} << (32 - low)));
}
inline int64_t cos30(angle a) noexcept { return sin30(a + angle::from_raw(angle::quarter_turn)); }

// The direction of (x, y) as a binary angle; atan2_angle's octants, its tangent an exact
// quotient, the atan table read quadratically. atan2(0, 0) = 0.
inline angle atan2_precise(int64_t y, int64_t x) noexcept {
    if (x == 0 && y == 0) return angle{};
    uint64_t ax = x < 0 ? 0 - static_cast<uint64_t>(x) : static_cast<uint64_t>(x);
    uint64_t ay = y < 0 ? 0 - static_cast<uint64_t>(y) : static_cast<uint64_t>(y);
    const int width = std::bit_width(ax > ay ? ax : ay);  // both below 2^32 after the shift
    if (width > 32) ax >>= width - 32, ay >>= width - 32;
    const bool steep = ay > ax;
    const uint64_t num = steep ? ax : ay, den = steep ? ay : ax;  // num <= den < 2^32, den > 0
    if (den == 0) return angle{};
    uint64_t t;  // num / den in Q32, floor
    if constexpr (kNativeDivide64)
        t = (num << 32) / den;
    else
        t = udiv_floor_reciprocal(num << 32, static_cast<uint32_t>(den));
    constexpr int low = 32 - tables::kAtanBits;
    uint32_t a = static_cast<uint32_t>(
        quad(tables::atan_units.data(), ((t >> low) << 32) | ((t & ((uint64_t{1} << low) - 1)) << (32 - low))));
    if (steep) a = angle::quarter_turn - a;
    if (x < 0) a = angle::half_turn - a;
    if (y < 0) a = 0u - a;
    return angle::from_raw(a);
}

// S_K(x) and C_K(x) in Q26 for x = x_raw / 2^xfrac (xfrac 24 or 25: x or x/2 for x in Q24),
// |K x^2| <= 10.
struct SC {
    int64_t s, c;
};
inline SC sk_ck(int64_t k, int64_t x_raw, int xfrac) noexcept {
    using namespace tables;
    // u = K x^2 in Q48 (|u| <= 10: below 2^52), from x^2 in Q32
    const int64_t u = k * rshift_round(x_raw * x_raw, 2 * xfrac - 32);
    const uint64_t from_lo = static_cast<uint64_t>(u + (int64_t{kSfCfRange} << 48));
    const int64_t sf = quad(sf_q28.data(), from_lo >> (16 - kSfStepBits));  // Q28
    const int64_t cf = quad(cf_q27.data(), from_lo >> (16 - kCfStepBits));  // Q27
    return {rshift_round(x_raw * sf, xfrac + 28 - kF), rshift_round(cf, 27 - kF)};
}

inline int64_t mul(int64_t a, int64_t b, int frac) noexcept { return rshift_round(a * b, frac); }

// ATf(u) for u = K t^2 in Q28, -15/16 <= u <= 1, Q30.
inline int64_t atf30(int64_t u) noexcept {
    using namespace tables;
    if (u >= -(int64_t{1} << 27)) {
        if (u > (int64_t{1} << 28)) u = int64_t{1} << 28;
        return quad(atf_q30.data(), static_cast<uint64_t>(u + (int64_t{1} << 27)) << (4 + kATfStepBits));
    }
    return 2 * quad(atf_low_q29.data(), static_cast<uint64_t>(u + (int64_t{15} << 24)) << (4 + kATfLowStepBits));
}

// sqrt|K| in Q31.
inline uint32_t root_k31(int64_t k) noexcept { return isqrt64(static_cast<uint64_t>(k < 0 ? -k : k) << 46); }

// The distance r of the point whose S_K is s >= 0 and C_K is c (Q26), Q24 (geo::arc_K).
inline int64_t arc(int64_t k, int64_t s, int64_t c) noexcept {
    const bool south = c < 0;  // past the sphere's equator (K > 0): from the antipode
    int64_t den = (int64_t{1} << kF) + (south ? -c : c), num = s;  // t = num / den
    const int sh = std::countl_zero(static_cast<uint64_t>(den)) - 32;  // den to [2^31, 2^32)
    if (sh >= 0)
        den <<= sh, num <<= sh;
    else
        den >>= -sh, num >>= -sh;
    const int64_t t = div_round(num << kF, static_cast<uint32_t>(den));          // Q26, t < 4
    const int64_t u = rshift_round(rshift_round(t * t, 2 * kF - 28) * k, 16);  // K t^2, Q28
    int64_t r;                                                                   // Q24
    if (u >= -(int64_t{15} << 24)) {
        r = rshift_round(t * atf30(u), kF + 30 - 24 - 1);  // 2 t ATf(u)
    } else {
        // At K < 0 beyond r = 4.13 / sqrt -K: r = 2 atanh(z) / sqrt -K, z = sqrt(-u) < 1, and
        // 2 atanh z = ln(1 + z) - ln(1 - z).
        const uint64_t z = isqrt64(static_cast<uint64_t>(-u) << 36);  // Q32
        const int64_t at2 = ln_q32((uint64_t{1} << 32) + z, 32) - ln_q32((uint64_t{1} << 32) - z, 32);
        r = div_round(at2 << 23, root_k31(k));
    }
    if (south) {
        constexpr int64_t kPiQ30 = 3373259426;  // pi 2^30
        r = div_round(kPiQ30 << 25, root_k31(k)) - r;
    }
    return r;
}

// |(x, y)|, floor, for Q26 values of any size.
inline int64_t hypot26(int64_t x, int64_t y) noexcept {
    uint64_t ax = x < 0 ? 0 - static_cast<uint64_t>(x) : static_cast<uint64_t>(x);
    uint64_t ay = y < 0 ? 0 - static_cast<uint64_t>(y) : static_cast<uint64_t>(y);
    const int width = std::bit_width(ax > ay ? ax : ay), sh = width > 30 ? width - 30 : 0;
    ax >>= sh, ay >>= sh;
    return static_cast<int64_t>(uint64_t{isqrt64(ax * ax + ay * ay)} << sh);
}

}  // namespace detail::coast

// Where a coast is after distance D: its distance r from O in Q24 (the world keeps a coast's
// start to these bits: the limit circle's 2R - r is then exact too), its bearing from O against
// the start's (theta_end - theta0), and the turn of its heading (chi_end - chi0).
struct CoastEnd {
    int64_t r24;
    angle bearing, turn;
};

// What every walk of one coast shares: K, the start's distance r0 (Q24) with S_K and C_K at r0
// and r0/2, and the heading against the outward radial, delta (cos, sin, 2 cos^2(delta/2)).
// a < 0: outside the domain above.
struct CoastStart {
    int64_t k = 0, a = -1;
    detail::coast::SC P{}, Ph{};
    int64_t cd = 0, sd = 0, e = 0;
};
inline CoastStart coast_start(fixed K, int64_t r0_q24, angle delta) noexcept {
    using namespace detail::coast;
    CoastStart s;
    const int64_t k = K.raw(), a = r0_q24;
    if (k < -65536 || k > 65536 || a < 0 || a > (int64_t{kCoastMaxRaw} << 8)) return s;
    const int64_t ch = cos30(delta.half());  // cos(delta/2) >= 0
    s.k = k, s.a = a, s.P = sk_ck(k, a, 24), s.Ph = sk_ck(k, a, 25);
    s.cd = cos30(delta), s.sd = sin30(delta), s.e = rshift_round(ch * ch, 29);
    return s;
}

// From the start at heading theta0 + delta, distance D along the geodesic (D in Q24: the world
// keeps a coast's distance walked to finer than Q16.16 too). False (out untouched) outside the
// domain above.
inline bool coast_walk(const CoastStart& s, int64_t d_q24, CoastEnd& out) noexcept {
    using namespace detail::coast;
    const int64_t k = s.k, a = s.a, b = d_q24, cd = s.cd, sd = s.sd;
    const SC& P = s.P;
    if (a < 0 || b < 0 || b > (int64_t{kCoastMaxRaw} << 8)) return false;
    const SC W = sk_ck(k, b, 24);
    const int64_t qy = mul(W.s, sd, 30);
    int64_t qx, qw;
    if (cd >= 0) {
        const int64_t sbcd = mul(W.s, cd, 30);
        qx = rshift_round(P.s * W.c + P.c * sbcd, kF);
        qw = rshift_round(P.c * W.c - rshift_round(k * P.s, 16) * sbcd, kF);
    } else {
        const SC A = sk_ck(k, a - b, 24);  // S_K(a - b), C_K(a - b)
        const int64_t sbe = mul(W.s, s.e, 30);
        qx = A.s + mul(P.c, sbe, kF);
        qw = A.c - mul(rshift_round(k * P.s, 16), sbe, kF);
    }
    const SC Wh = sk_ck(k, b, 25);  // at b/2; s.Ph at a/2
    const int64_t m = rshift_round(k * mul(s.Ph.s, Wh.s, kF), 16);  // K s s', Q26
    const int64_t tn = mul(m, sd, 30), td = mul(s.Ph.c, Wh.c, kF) - mul(m, cd, 30);
    out.r24 = arc(k, hypot26(qx, qy), qw);
    out.bearing = atan2_precise(qy, qx);
    out.turn = atan2_precise(tn, td) * 2;
    return true;
}

// One walk: coast_start and coast_walk together.
inline bool coast_walk(fixed K, int64_t r0_q24, angle delta, int64_t d_q24, CoastEnd& out) noexcept {
    return coast_walk(coast_start(K, r0_q24, delta), d_q24, out);
}

}  // namespace noneuclid::fx
