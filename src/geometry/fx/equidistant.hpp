// The fixed-point kernels of the azimuthal equidistant projection (the paper's view), from the
// 3-vector model: equidistant_xy for a point (w, x, y), and the ratio E(w) = r / S_K(r) that
// takes (x, y) to the projection plane in one product (equidistant_ratio_q30, and past the
// sphere's equator equidistant_ratio_south_q29). The geometry's project_vec and the draw's
// inner loop (render/fixed_points.hpp) use them.
#pragma once

#include <bit>
#include <cstdint>

#include "fixed/curvature.hpp"
#include "fixed/division.hpp"
#include "fixed/fixed.hpp"
#include "fixed/tables.hpp"

namespace noneuclid::fx {

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

}  // namespace noneuclid::fx
