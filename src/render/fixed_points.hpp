// The fixed engine's equidistant view of a body, the kiosk's hot loop: from the vertices'
// 3-vectors and the shape cache's slerp weights, each point's 3-vector as the slerp's 64-bit
// sums, straight to sub-pixels, with no floating point and no division per point
// (fixed_equidistant_points). Each piece is a function of its own so that its loop's values
// stay in registers; points outside the fast domain go to the general path (project_vec), out
// of line. body_screen_points (render/body_points.hpp) takes this path for the fixed engine's
// equidistant view.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "fixed/math.hpp"
#include "geometry/geometry.hpp"
#include "render/raster.hpp"
#include "render/screen_points.hpp"

namespace noneuclid::render::detail {

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
// In fixed_equidistant_points a run is open when the last entry written is a point: the first
// entry of a body is never a break, and a break is written only after a point.
inline Cursor cursor_at(const SubPoint* out, const SubPoint* at) {
    const std::size_t n = static_cast<std::size_t>(at - out);
    return {n, n > 0 && at[-1].x != kBreak.x};
}
// What FixedEquidistant leaves: project_vec, out of the inner loop. Returns where the next
// entry goes.
[[gnu::noinline]] inline SubPoint* general_point(fx::fixed K, const ScreenMap<fx::fixed>& m, geo::Vec3<fx::fixed> v,
                                                 SubPoint* out, SubPoint* at) {
    const geo::ProjectedPoint<fx::fixed> pp = geo::project_vec(K, v, geo::Projection::azimuthal_equidistant);
    Cursor c = cursor_at(out, at);
    put_point(out, c, m, pp.visible, pp.X, pp.Y);
    return out + c.count;
}
// The same for the slerp's point a P + b Q, its 3-vector saturated as geo::edge_projected's.
[[gnu::noinline]] inline SubPoint* general_slerp_point(fx::fixed K, const ScreenMap<fx::fixed>& m, fx::fixed a, fx::fixed b,
                                                       const geo::Vec3<fx::fixed>& P, const geo::Vec3<fx::fixed>& Q,
                                                       SubPoint* out, SubPoint* at) {
    return general_point(K, m, geo::slerp_point(a, P, b, Q), out, at);
}
// An edge whose ends are antipodal on the sphere: walked from its polar end points.
[[gnu::noinline]] inline SubPoint* antipodal_points(fx::fixed K, const ScreenMap<fx::fixed>& m, const geo::Vec3<fx::fixed>& P,
                                                    const geo::Vec3<fx::fixed>& Q, int level, bool with_start,
                                                    geo::Polar<fx::fixed>* verts, SubPoint* out, SubPoint* at) {
    Cursor c = cursor_at(out, at);
    verts[0] = geo::to_polar(K, P), verts[1] = geo::to_polar(K, Q);
    geo::edge_projected(K, verts[0], verts[1], P, Q, level, geo::Projection::azimuthal_equidistant, with_start,
                        [&](int, bool vis, fx::fixed X, fx::fixed Y) { put_point(out, c, m, vis, X, Y); });
    return out + c.count;
}
// One coordinate of a slerp's point a P + b Q in Q16.16, rounded down (dot2 rounds to nearest:
// a bias of half a step, about 0.002 px at 1920x1080, for three fewer additions a point), not
// saturated, from its two products (each below 2^62 in magnitude): the sum wraps (defined, in
// unsigned) only when all four factors are -2^31, and then leaves FixedEquidistant's domain.
[[gnu::always_inline]] inline int64_t slerp_sum(int64_t p, int64_t q) {
    return static_cast<int64_t>(static_cast<uint64_t>(p) + static_cast<uint64_t>(q)) >> 16;
}
// The slerp's points a P + b Q for the weights [ab, end) of one edge, written from `at` on
// while FixedEquidistant shows them. Returns where it stopped: the weights of the first point
// it leaves (or end), and the next entry. A function of its own, so that the loop's values
// stay in registers.
struct SlerpRunEnd {
    const fx::fixed* ab;
    SubPoint* at;
};
template <bool Flat>
[[gnu::noinline]] SlerpRunEnd slerp_run(const FixedEquidistant& fe, const geo::Vec3<fx::fixed>& P,
                                        const geo::Vec3<fx::fixed>& Q, const fx::fixed* ab, const fx::fixed* end,
                                        SubPoint* at) {
    const int64_t pw = P.w.raw(), px = P.x.raw(), py = P.y.raw();
    const int64_t qw = Q.w.raw(), qx = Q.x.raw(), qy = Q.y.raw();
    const FixedEquidistant f = fe;
    for (; ab < end; ab += 2, ++at) {
        const int64_t a = ab[0].raw(), b = ab[1].raw();
        if (!f.point<Flat>(slerp_sum(a * pw, b * qw), slerp_sum(a * px, b * qx), slerp_sum(a * py, b * qy), *at)) break;
    }
    return {ab, at};
}
// Where a run of whole edges stopped: the first edge it did not finish (or the edge count), and
// the next entry.
struct EdgeRunEnd {
    std::size_t e;
    SubPoint* at;
};
// A body at level 2 (one slerp point per edge, its midpoint: the grid lines), edges [e, edges):
// each edge's midpoint and end, from `at` on, while FixedEquidistant shows both and no edge is
// antipodal.
template <bool Flat>
[[gnu::noinline]] EdgeRunEnd midpoint_run(const FixedEquidistant& fe, const geo::Vec3<fx::fixed>* vecs,
                                          const uint8_t* antipodal, const fx::fixed* weights, std::size_t n,
                                          std::size_t edges, std::size_t e, SubPoint* at) {
    const FixedEquidistant f = fe;
    for (; e < edges; ++e, at += 2) {
        const geo::Vec3<fx::fixed>&P = vecs[e], &Q = vecs[e + 1 == n ? 0 : e + 1];
        const int64_t a = weights[2 * e].raw(), b = weights[2 * e + 1].raw();
        const int64_t qw = Q.w.raw(), qx = Q.x.raw(), qy = Q.y.raw();
        if (antipodal[e]) break;
        if (!f.point<Flat>(slerp_sum(a * P.w.raw(), b * qw), slerp_sum(a * P.x.raw(), b * qx),
                           slerp_sum(a * P.y.raw(), b * qy), at[0]))
            break;
        if (!f.point<Flat>(qw, qx, qy, at[1])) break;
    }
    return {e, at};
}
// Whole edges [e, edges) of a body at any level: each edge's slerp points and its end, from
// `at` on, while FixedEquidistant shows them all and no edge is antipodal. The entry it returns
// is where the unfinished edge's entries begin: an edge it leaves halfway is done again by the
// caller's per-edge path, whose points are the same bits. One call per body; at level 1
// (Points = false: an edge is its end alone) no call per edge at all.
template <bool Flat, bool Points>
[[gnu::noinline]] EdgeRunEnd edge_run(const FixedEquidistant& fe, const geo::Vec3<fx::fixed>* vecs, const uint8_t* antipodal,
                                      const fx::fixed* weights, std::size_t per_edge, std::size_t n, std::size_t edges,
                                      std::size_t e, SubPoint* at) {
    const FixedEquidistant f = fe;
    const fx::fixed* ab = weights + e * per_edge;
    // Edge e, ending at Q: false where it stops.
    auto edge = [&](std::size_t e, const geo::Vec3<fx::fixed>& Q) __attribute__((always_inline)) {
        SubPoint* p = at;
        if constexpr (Points) {  // the edge's own points: slerp_run's loop, which keeps its values in registers
            const fx::fixed* const end = ab + per_edge;
            const SlerpRunEnd r = slerp_run<Flat>(f, vecs[e], Q, ab, end, at);
            if (r.ab < end) return false;
            ab = end, p = r.at;
        }
        if (!f.point<Flat>(Q.w.raw(), Q.x.raw(), Q.y.raw(), *p)) return false;
        at = p + 1;
        return true;
    };
    std::size_t stop = edges;  // the first antipodal edge from e on (antipodal: null if there is none)
    if (antipodal)
        for (stop = e; stop < edges && !antipodal[stop];) ++stop;
    const std::size_t open = std::min(stop, edges < n ? edges : n - 1);  // edges that end at vecs[e + 1]
    for (; e < open; ++e)
        if (!edge(e, vecs[e + 1])) return {e, at};
    if (e < stop && e < edges) {  // a closed body's last edge, which ends at vecs[0]
        if (!edge(e, vecs[0])) return {e, at};
        ++e;
    }
    return {e, at};
}
// The fixed engine's equidistant view of one body (edges > 0), from its vertices' 3-vectors
// and the shape cache's slerp weights: each point's 3-vector as the slerp's 64-bit sums,
// straight to sub-pixels (FixedEquidistant), general_point for the rest. Returns the count.
template <bool Flat, class Cache>
[[gnu::noinline]] std::size_t fixed_equidistant_points(fx::fixed K, const Cache& sh, const FixedEquidistant& fe0,
                                                       const ScreenMap<fx::fixed>& m, const geo::Vec3<fx::fixed>* vecs,
                                                       geo::Polar<fx::fixed>* verts, std::size_t n, std::size_t edges,
                                                       int level, SubPoint* out) {
    using fx::fixed;
    const FixedEquidistant fe = fe0;
    SubPoint* at = out;  // the next entry
    auto vertex = [&](const geo::Vec3<fixed>& v) __attribute__((always_inline)) {
        if (fe.point<Flat>(v.w.raw(), v.x.raw(), v.y.raw(), *at))
            ++at;
        else
            at = general_point(K, m, v, out, at);
    };
    if (!sh.antipodal[0]) vertex(vecs[0]);  // else antipodal_points writes it
    for (std::size_t e = 0; e < edges; ++e) {
        if (level == 2) {  // grid lines: every edge in one call while all is shown
            const EdgeRunEnd r = midpoint_run<Flat>(fe, vecs, sh.antipodal.data(), sh.weights.data(), n, edges, e, at);
            e = r.e, at = r.at;
        } else {  // every edge in one call while all is shown
            const uint8_t* const antipodal = sh.any_antipodal ? sh.antipodal.data() : nullptr;
            const EdgeRunEnd r = level == 1 ? edge_run<Flat, false>(fe, vecs, antipodal, sh.weights.data(), 0, n, edges, e, at)
                                         : edge_run<Flat, true>(fe, vecs, antipodal, sh.weights.data(), sh.per_edge, n, edges, e, at);
            e = r.e, at = r.at;
        }
        if (e == edges) break;
        const std::size_t f = e + 1 == n ? 0 : e + 1;
        const geo::Vec3<fixed>&P = vecs[e], &Q = vecs[f];
        if (sh.antipodal[e]) {
            at = antipodal_points(K, m, P, Q, level, e == 0, verts, out, at);
            continue;
        }
        const fixed* ab = sh.weights_of(e);  // (at level 2, an edge midpoint_run left)
        const fixed* const end = ab + 2 * (level - 1);
        for (;;) {
            const SlerpRunEnd r = slerp_run<Flat>(fe, P, Q, ab, end, at);
            at = r.at;
            if (r.ab >= end) break;
            at = general_slerp_point(K, m, r.ab[0], r.ab[1], P, Q, out, at);  // a point slerp_run leaves
            ab = r.ab + 2;
        }
        vertex(Q);
    }
    return static_cast<std::size_t>(at - out);
}

}  // namespace noneuclid::render::detail
