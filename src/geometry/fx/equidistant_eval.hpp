// The fixed engine's equidistant view, the kiosk's hot path: a point of the 3-vector model
// straight to sub-pixels, with no floating point and no division per point (FixedEquidistant),
// its companion past the sphere's equator (FixedFarSide), and the evaluator edge_curve
// (geometry/edge_curve.hpp) takes for this view (FixedEquidistantEval): each slerp point
// computed from its Q30 weights as 64-bit sums, unsaturated, and given to the kernels; points
// outside their domains go to the general path (project_vec), out of line. The exact engine's
// outline (geometry/engine.hpp) takes this path for the fixed scalar's equidistant view.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>

#include "fixed/math.hpp"
#include "geometry/edge_curve.hpp"
#include "geometry/fx/equidistant.hpp"
#include "geometry/geometry.hpp"
#include "geometry/screen_map.hpp"

namespace noneuclid::geo {

// One point of the equidistant view, from the 3-vector model straight to sub-pixels: a point
// (w, x, y) is shown at (x, y) E(w) (fx::equidistant_ratio_q30: one table lookup, no reciprocal
// and no ATf) times the screen scale, E(w) and the scale in one product per point, the gain G.
// Its domain: 0 <= w < 32 with |x|, |y| <= 100 (as project_vec's fast path), and past the
// sphere's equator -1/2 <= w < 0 with |x|, |y| <= 16 (E <= 2.42); and a scale below 2^14 px per
// unit. There every product fits in 64 bits (|x| G < 2^(22.6 + 39.7) and 2^(20 + 40.3)) and
// every result in 32 bits (|x| E scale < 100 pi/2 2^14 px < 2^21.3 px). project_vec takes the
// rest.
struct FixedEquidistant {
    static constexpr int kGainFrac = 25;                           // G = E scale, in Q25 px per unit
    static constexpr int kGainShift = 16 + 30 - kGainFrac;         // Q16 scale x Q30 E -> Q25
    static constexpr int kPointShift = 16 + kGainFrac - kSubBits;  // Q16 x Q25 -> 1/256 px
    int32_t cx = 0, cy = 0;  // the canvas centre, 1/256 px
    int64_t scale = 0;       // px per unit, Q16
    int64_t flat_gain = 0;   // G at E = 1, the plane's: kept, one instruction fewer per point
    // fx::tables::equi_q30's address, as a value: a loop's copy of this struct then keeps it in a
    // register, where GCC otherwise reloads it from the GOT for every point.
    const int32_t* equi = nullptr;
    static bool make(const ScreenMap<fx::fixed>& m, FixedEquidistant& e) {
        const int32_t sc = m.scale.raw();
        if (sc <= 0 || sc >= (int32_t{1} << 30)) return false;
        e.cx = m.cx.raw() >> 8, e.cy = m.cy.raw() >> 8, e.scale = sc;
        e.flat_gain = (int64_t{1} << 30) * e.scale >> kGainShift;
        e.equi = fx::tables::equi_q30.data();
        return true;
    }
    // The point of Q16.16 coordinates held in 64 bits (a slerp's sums, unsaturated); false
    // outside the domain. Flat: K = 0, where every point has w = C_0(r) = 1 and E(1) = 1: w is
    // not looked at (nor, inlined, computed) and the gain is the same for every point; the
    // domain is |x|, |y| <= 100.
    template <bool Flat = false>
    [[gnu::always_inline]] bool point(int64_t w, int64_t x, int64_t y, SubPoint& p) const {
        auto within = [&](int64_t lim) {
            return static_cast<uint64_t>(x + lim) <= static_cast<uint64_t>(2 * lim) &&
                   static_cast<uint64_t>(y + lim) <= static_cast<uint64_t>(2 * lim);
        };
        if constexpr (Flat) {
            if (!within(int64_t{100} << 16)) return false;
            p = {cx + static_cast<int32_t>((x * flat_gain) >> kPointShift),
                 cy - static_cast<int32_t>((y * flat_gain) >> kPointShift)};
            return true;
        }
        int64_t E;  // Q30
        if (static_cast<uint64_t>(w) < (uint64_t{fx::tables::kEquiRange} << 16)) [[likely]] {
            if (!within(int64_t{100} << 16)) return false;
            E = fx::equidistant_ratio_q30(equi, static_cast<uint32_t>(w));
        } else if (static_cast<uint64_t>(w - fx::tables::kEquiSouthRaw) < uint64_t{-fx::tables::kEquiSouthRaw} &&
                   within(int64_t{16} << 16)) {
            E = int64_t{fx::equidistant_ratio_south_q29(static_cast<int32_t>(w))} * 2;
        } else {
            return false;
        }
        const int64_t gain = (E * scale) >> kGainShift;
        p = {cx + static_cast<int32_t>((x * gain) >> kPointShift), cy - static_cast<int32_t>((y * gain) >> kPointShift)};
        return true;
    }
};
// The sphere's far side past w = -1/2 (K > 0, distance r > 2 pi / 3 sqrt K), where E(w) grows
// without bound toward the antipode and Q16.16's w cannot tell points apart: S = |(x, y)| =
// S_K(r) from (x, y), r = pi / sqrt K - 2 AT_K(S / (1 - w)) (the polar reading past the equator,
// arc_K, whose 1 - w in [3/2, 2] loses nothing), and the point at r along the unit direction
// (x, y) / S. A square root from its table seed (2^-17: the direction and radius it gives are off
// by 2^-17 of the point's distance from the centre, 0.002 px on a 1080-px disc), two
// reciprocals and one ATf lookup: no atan2 and no division instruction. Points within 2^-10 of
// the antipode are left to project_vec (far outside any clip circle: kAntipodeMarginPx is more
// than 2^-10 times any scale in px).
struct FixedFarSide {
    int32_t cx = 0, cy = 0;  // the canvas centre, 1/256 px
    int64_t scale = 0;       // px per unit, Q16
    int32_t K = 0;           // Q16
    int64_t antipode = 0;    // pi / sqrt K, Q16
    static FixedFarSide make(const FixedEquidistant& fe, fx::fixed K) {
        FixedFarSide f;
        f.cx = fe.cx, f.cy = fe.cy, f.scale = fe.scale, f.K = K.raw();
        if (K.raw() > 0) f.antipode = (pi_v<fx::fixed> / sqrt(K)).raw();
        return f;
    }
    // 2^62 / d for d > 0 of any size below 2^32, from recip_q62 on d scaled into [2^31, 2^32).
    static uint64_t reciprocal(uint32_t d, int& shift) {
        shift = std::countl_zero(d);
        return fx::detail::recip_q62(d << shift);  // 2^62 / (d 2^shift)
    }
    // Whether (w, x, y) lies within 2^-10 of the antipode (S < 2^-10 past the equator), where
    // Q16.16's x and y no longer tell its direction: project_vec would put it at theta = 0, on
    // the east rim. Such a point lies outside the clip circle (kAntipodeMarginPx inside the rim
    // is more than 2^-10 times any scale in px) and is not shown: the polyline breaks there.
    bool near_antipode(int64_t w, int64_t x, int64_t y) const {
        constexpr int64_t lim = int64_t{1} << 6;  // 2^-10 in Q16
        return K > 0 && w < 0 && x < lim && x > -lim && y < lim && y > -lim && x * x + y * y < (int64_t{1} << 12);
    }
    // The unit vector along (dx, dy) (any scale, not both 0) in Q30: (dx, dy) scaled to 30 bits
    // (the table seed's square root is good to 2^-17 of its value only for such large ones),
    // then divided by its length.
    static void direction(int64_t dx, int64_t dy, int64_t& ux, int64_t& uy) {
        const uint64_t m = static_cast<uint64_t>(dx < 0 ? -dx : dx) | static_cast<uint64_t>(dy < 0 ? -dy : dy);
        const int k = 34 - std::countl_zero(m);  // the larger of |dx|, |dy| in [2^29, 2^30) once shifted
        const int64_t hx = k >= 0 ? dx >> k : dx * (int64_t{1} << -k), hy = k >= 0 ? dy >> k : dy * (int64_t{1} << -k);
        const uint32_t h = fx::detail::sqrt_seed(static_cast<uint64_t>(hx * hx + hy * hy));
        int sh = 0;
        const uint64_t r_h = reciprocal(h, sh);
        const int64_t inv = static_cast<int64_t>(r_h << sh);  // 2^62 / h
        ux = (hx * inv) >> 32, uy = (hy * inv) >> 32;
    }
    // False outside the domain: K <= 0, w >= -1/2, or within 2^-10 of the antipode. (dx, dy):
    // (x, y) before rounding to Q16, at any scale, when the caller has it: near the antipode
    // (x, y) is small and its rounding alone would turn the point's direction by up to
    // 2^-17 / S (a pixel at S = 2^-8 on a 1080-px disc); the sums it was rounded from are exact
    // to 2^-30.
    bool point(int64_t w, int64_t x, int64_t y, SubPoint& p) const { return point(w, x, y, p, x, y); }
    bool point(int64_t w, int64_t x, int64_t y, SubPoint& p, int64_t dx, int64_t dy) const {
        if (K <= 0 || w >= -(int64_t{1} << 15)) return false;
        constexpr int64_t lim = int64_t{1} << 20;  // |x|, |y| < 16 (S <= 1 / sqrt K, K >= 1/256)
        if (x >= lim || x <= -lim || y >= lim || y <= -lim || w < -(int64_t{1} << 16)) return false;
        const uint64_t s2 = static_cast<uint64_t>(x * x + y * y);  // Q32
        if (s2 < (uint64_t{1} << 12)) return false;                 // S < 2^-10
        const uint32_t s = fx::detail::sqrt_seed(s2 << 16);          // S in Q24, < 2^28
        // t = S / (1 - w) in Q24: 1 - w in (3/2, 2] is (1 - w) 2^16 in Q16; 2^62 / (that 2^15)
        // is 1 / (1 - w) in Q31.
        const uint32_t d = static_cast<uint32_t>(std::min<int64_t>(((int64_t{1} << 16) - w) << 15, 0xFFFFFFFF));
        const uint64_t inv_w = fx::detail::recip_q62(d);
        const fx::fixed t = fx::fixed::from_raw(static_cast<int32_t>((uint64_t{s} * inv_w) >> 39));  // Q16
        const fx::fixed u = fx::fixed::from_raw(static_cast<int32_t>((int64_t{K} * t.raw() * t.raw()) >> 32));
        const int64_t r = antipode - 2 * int64_t{fx::mul_ATf(t, u).raw()};  // Q16
        const int64_t R = (r * scale) >> 24;                                 // px, Q8
        int64_t ux = 0, uy = 0;  // Q30
        direction(dx, dy, ux, uy);
        p = {cx + static_cast<int32_t>((ux * R) >> 30), cy - static_cast<int32_t>((uy * R) >> 30)};
        return true;
    }
};

// What FixedEquidistant leaves: project_vec, out of the hot path.
[[gnu::noinline]] inline Spot general_spot(fx::fixed K, const ScreenMap<fx::fixed>& m, const Vec3<fx::fixed>& v) {
    const ProjectedPoint<fx::fixed> pp = project_vec(K, v, Projection::azimuthal_equidistant);
    if (!pp.visible) return {};
    return spot_at(m, to_pixels(ScreenPoint<fx::fixed>{m.cx + m.scale * pp.X, m.cy - m.scale * pp.Y}));
}

// edge_curve's evaluator for the fixed engine's equidistant view. Flat: K = 0 (FixedEquidistant).
template <bool Flat>
struct FixedEquidistantEval {
    using Math = SlerpMath<fx::fixed>;
    FixedEquidistant fe;
    fx::fixed K;
    const ScreenMap<fx::fixed>& m;
    int64_t pw = 0, px = 0, py = 0, qw = 0, qx = 0, qy = 0;  // the edge's ends, Q16.16

    void ends(const Vec3<fx::fixed>& p, const Vec3<fx::fixed>& q) {
        pw = p.w.raw(), px = p.x.raw(), py = p.y.raw(), qw = q.w.raw(), qx = q.x.raw(), qy = q.y.raw();
    }
    FixedFarSide far = FixedFarSide::make(fe, K);

    Spot vertex(const Vec3<fx::fixed>& v) const {
        SubPoint s;
        if (fe.point<Flat>(v.w.raw(), v.x.raw(), v.y.raw(), s)) return spot_at(m, s);
        return other(v.w.raw(), v.x.raw(), v.y.raw(), v, v.x.raw(), v.y.raw());
    }
    // Past FixedEquidistant's domain: the far side, else project_vec.
    [[gnu::noinline]] Spot other(int64_t w, int64_t x, int64_t y, const Vec3<fx::fixed>& v, int64_t dx,
                                 int64_t dy) const {
        SubPoint s;
        if (far.point(w, x, y, s, dx, dy)) return spot_at(m, s);
        if (far.near_antipode(w, x, y)) return {};
        return general_spot(K, m, v);
    }
    // a P + b Q, without overflow: for K <= 0 the weights lie in [0, 1] (Q30) and every product
    // below 2^61; for K > 0 they lie in [0, 4] (the cache walks longer edges: SlerpMath::too_long)
    // and the coordinates, C_K and S_K, below 1 / sqrt K <= 256 (Q16.16: 2^24), the products below
    // 2^56.
    Spot point(int64_t a, int64_t b) const {
        constexpr int64_t half = int64_t{1} << (Math::kFrac - 1);
        const int64_t X = a * px + b * qx, Y = a * py + b * qy;
        const int64_t w = (a * pw + b * qw + half) >> Math::kFrac, x = (X + half) >> Math::kFrac, y = (Y + half) >> Math::kFrac;
        SubPoint s;
        if (fe.point<Flat>(w, x, y, s)) return spot_at(m, s);
        auto sat = [](int64_t v) { return fx::fixed::from_raw(fx::detail::saturate32(v)); };
        return other(w, x, y, {sat(w), sat(x), sat(y)}, X, Y);
    }
};

// The fixed scalar's view evaluator (geometry/edge_curve.hpp's with_view_eval): this kernel for
// the equidistant view within its scale, the general one otherwise.
template <class F>
void with_view_eval(fx::fixed K, const ScreenMap<fx::fixed>& m, Projection p, F&& f) {
    FixedEquidistant fe;
    if (p != Projection::azimuthal_equidistant || !FixedEquidistant::make(m, fe)) return f(VecEval<fx::fixed>{K, p, m});
    if (K.raw() == 0) return f(FixedEquidistantEval<true>{fe, K, m});
    f(FixedEquidistantEval<false>{fe, K, m});
}

}  // namespace noneuclid::geo
