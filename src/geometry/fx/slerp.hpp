// The fixed engine's slerp weights along a geodesic edge (geo::SlerpWeights, geometry/edges.hpp):
// sigma_k = S_K(k delta) / delta at n + 1 evenly spaced points, by the recurrence of
// docs/design.md, in Q30, with no trigonometry per point.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "fixed/division.hpp"
#include "fixed/fixed.hpp"

namespace noneuclid::fx {

// The slerp's sigma_k = S_K(k delta) / delta for delta = d / n, k = 0 .. n, in Q30 (int64),
// by sigma_{k+1} = 2 C_K(delta) sigma_k - sigma_{k-1} from sigma_1 = Sf(K delta^2)
// (docs/design.md; geo::SlerpWeights). C_K(delta) and Sf are summed from their series in Q30
// (|u| <= 2: the terms fall below 2^-34 by the ninth). False when |K delta^2| > 2 or d > 16.
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


}  // namespace noneuclid::fx
