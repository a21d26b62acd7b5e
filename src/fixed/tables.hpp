// The lookup tables behind the fixed-point functions. Each is computed at compile time
// (constexpr, from constexpr_math.hpp) in tables.cpp and lives in read-only memory. Every
// table carries one padding entry past its last interval so that an index at the very end of
// the domain can read entry i+1 without a branch.
//
// Sizes are chosen so that linear interpolation error stays well below the Q16.16 rounding
// step (7.6e-6) and the total stays small enough for a Cortex-A53's 32 KiB L1 data cache plus
// L2 (see table_bytes below; a static_assert keeps it <= 64 KiB).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace noneuclid::fx::tables {

// sin(2 pi i / 2048), i in [0, 2048] (+1 pad), Q1.30. Interpolation error <= 1.2e-6.
inline constexpr int kSinBits = 11;
extern const std::array<int32_t, (1 << kSinBits) + 2> sin_q30;

// atan(i / 512), i in [0, 512] (+1 pad), in binary-angle units (2^32 per turn).
// Interpolation error <= 3.1e-7 rad.
inline constexpr int kAtanBits = 9;
extern const std::array<uint32_t, (1 << kAtanBits) + 2> atan_units;

// asin(i / 512), i in [0, 256] (+1 pad) = x in [0, 0.5], Q2.30. Error <= 3.7e-7 rad.
inline constexpr int kAsinBits = 9;
extern const std::array<int32_t, (1 << (kAsinBits - 1)) + 2> asin_q30;

// sqrt(m), m = (64 + i) / 256, i in [0, 192] (+1 pad) = m in [1/4, 1], Q1.31. Seeds one
// Newton step; relative error of the seed <= 4.3e-6.
extern const std::array<uint32_t, 192 + 2> sqrt_q31;

// 1 / (1 + i / 256), i in [0, 256] (+1 pad), Q1.31: seeds the reciprocal that replaces
// division (32-bit ARM has no 64-bit divide). Seed error <= 3.8e-6, 2^-30 after Newton.
extern const std::array<uint32_t, 256 + 2> recip_q31;

// 2^(j / 256), j in [0, 256), Q2.30. A quadratic in the remainder finishes exp.
extern const std::array<uint32_t, 256> exp2_q30;

// log2(1 + i / 512), i in [0, 512] (+1 pad), Q1.31. Error <= 4.8e-7.
inline constexpr int kLog2Bits = 9;
extern const std::array<uint32_t, (1 << kLog2Bits) + 2> log2_q31;

// The curvature functions of docs/design.md on the range the geometry uses most, |u| <= 10
// (covers K r^2 for |K| <= 1 and r <= pi):
//   Sf(u), u = -10 + i/64,  i in [0, 1280] (+1 pad), Q3.28. Error <= 1.0e-6.
//   Cf(u), u = -10 + i/128, i in [0, 2560] (+1 pad), Q4.27. Error <= 1.6e-6.
// ASf(u), u = -4 + i/256, i in [0, 1152] (+1 pad) = u in [-4, 0.5], Q2.30. Error <= 9.5e-7.
inline constexpr int kSfStepBits = 6;
inline constexpr int kCfStepBits = 7;
inline constexpr int kASfStepBits = 8;
inline constexpr int kSfCfRange = 10;
inline constexpr int kASfLow = 4;
extern const std::array<int32_t, (kSfCfRange * 2 << kSfStepBits) + 2> sf_q28;
extern const std::array<int32_t, (kSfCfRange * 2 << kCfStepBits) + 2> cf_q27;
extern const std::array<int32_t, ((kASfLow << kASfStepBits) + (1 << (kASfStepBits - 1))) + 2>
    asf_q30;

// ATf(u) = atan(sqrt u)/sqrt u (u > 0), atanh(sqrt -u)/sqrt -u (u < 0), 1 at 0, the inverse
// of the tangent-half-angle T_K, on u = -1/2 + i/512, i in [0, 768] (+1 pad) = [-0.5, 1],
// Q2.30. Error <= 8.3e-7.
inline constexpr int kATfStepBits = 9;
extern const std::array<int32_t, (3 << (kATfStepBits - 1)) + 2> atf_q30;
// ATf below that, where atanh's logarithm steepens toward u = -1: u = -15/16 + i/4096,
// i in [0, 1792] (+1 pad) = [-15/16, -1/2], Q3.29 (ATf reaches 2.08). Error <= 9.3e-7. At K = -1 this is
// r <= 2 atanh(sqrt(15/16)) = 4.13 (the limit circles the scenes use are within 3.2), so the
// equidistant projection's points and every arc_K there stay in the tables, not in two
// logarithms and a division.
inline constexpr int kATfLowStepBits = 12;
inline constexpr int32_t kATfLowRaw = -(15 << 12);  // -15/16 in Q16.16
extern const std::array<int32_t, (7 << (kATfLowStepBits - 4)) + 2> atf_low_q29;

// The equidistant view straight from a 3-vector (w, x, y) of the model (geometry.hpp): a point at
// distance r has w = C_K(r) and (x, y) = S_K(r) (cos theta, sin theta), so its projection
// r (cos theta, sin theta) is (x, y) E(w) with E(w) = r / S_K(r), which depends on w alone,
// whatever K: acos(w) / sqrt(1 - w^2) below 1, 1 at 1, acosh(w) / sqrt(w^2 - 1) above
// (= 2 ATf(u) / (1 + w), u = (1 - w) / (1 + w)). One lookup instead of a reciprocal, a square
// and ATf. On w = i/128, i in [0, 4096] (+1 pad) = [0, 32] (at K = -1, r <= acosh 32 = 4.16),
// Q2.30. Relative error of the linear interpolation <= 7.6e-6, at w near 0 (tests/unit/test_tables.cpp).
inline constexpr int kEquiStepBits = 7;
inline constexpr int kEquiRange = 32;
extern const std::array<int32_t, (kEquiRange << kEquiStepBits) + 2> equi_q30;
// E past the sphere's equator (w < 0, where E grows toward pi/sqrt(1-w^2) at the antipode): on
// w = -1/2 + i/512, i in [0, 256] (+1 pad) = [-1/2, 0], Q3.29 (E(-1/2) = 2.42). Relative error
// of the linear interpolation <= 1.8e-6. Below -1/2 (r > 2/3 pi / sqrt K) the polar path is
// kept: it reads r off the sine, and E's slope there would turn w's rounding into 0.01 px.
inline constexpr int kEquiSouthStepBits = 9;
inline constexpr int32_t kEquiSouthRaw = -(1 << 15);  // -1/2 in Q16.16
extern const std::array<int32_t, (1 << (kEquiSouthStepBits - 1)) + 2> equi_south_q29;

// Total bytes of all tables.
inline constexpr std::size_t table_bytes =
    sizeof(sin_q30) + sizeof(atan_units) + sizeof(asin_q30) + sizeof(sqrt_q31) +
    sizeof(exp2_q30) + sizeof(recip_q31) + sizeof(log2_q31) + sizeof(sf_q28) + sizeof(cf_q27) + sizeof(asf_q30) +
    sizeof(atf_q30) + sizeof(atf_low_q29) + sizeof(equi_q30) + sizeof(equi_south_q29);
static_assert(table_bytes <= 64 * 1024, "lookup tables must fit in 64 KiB");

}  // namespace noneuclid::fx::tables
