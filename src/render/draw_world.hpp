// Drawing a world: vertices -> tessellated edges -> projection -> lines, into a Canvas.
//
// The limit circle R fills the smaller side of the canvas, centred; the area outside it is
// shaded as in the paper's figures. Each body's edges are tessellated at the body's level and
// drawn as one polyline in the body's colour; a point the projection cannot show breaks the
// polyline. With the fixed-point engine, screen points are computed in Q16.16 and handed to
// the rasteriser as sub-pixel integers: no floating point between the world and the pixels.
//
// A frame is three kinds of work: the backdrop (background, shaded outside, written row by row
// as spans), each body's geometry (vertices, tessellated edges, projection: body_screen_points,
// into SubPoints with kBreak where the projection cannot show a point) and each body's raster
// (draw_screen_points). draw_world does them in turn on the calling thread; the overload taking
// a render::WorkerPool (worker_pool.hpp) spreads all three over threads started once: first every
// body's geometry, then bands of rows, each band drawn whole by one thread (its backdrop, then
// every body clipped to its rows, in the world's order), so every pixel sees the same writes in
// the same order and the pixels are the same, bit for bit.
//
// Memory: a DrawScratch (or ParallelScratch) sized once for the world (prepare) holds every
// buffer; drawing a frame allocates nothing.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

#include "geometry/geometry.hpp"
#include "render/canvas.hpp"
#include "render/worker_pool.hpp"
#include "render/raster.hpp"
#include "world/world.hpp"

namespace noneuclid::render {

struct DrawOptions {
    geo::Projection projection = geo::Projection::azimuthal_equidistant;
    bool antialias = false;
    int32_t line_width = kSub;  // 1/256 px
    bool shade_outside = true;
    Rgb background{6, 8, 14};
    Rgb outside{26, 30, 44};
    Rgb rim{90, 100, 130};
    bool grids = true;   // draw grid bodies
    bool bodies = true;  // draw the other bodies
};

// A point the projection cannot show: the polyline breaks there. No screen point is ever this
// (to_sub saturates at +-2^30, to_sub_q16 gives at most +-2^23).
inline constexpr SubPoint kBreak{INT32_MIN, INT32_MIN};

// The room a body's screen points need: every tessellated point, plus a break after each.
template <class B>
std::size_t body_point_capacity(const B& b) {
    return 2 * (b.local.size() * static_cast<std::size_t>(b.desc->tessellation > 0 ? b.desc->tessellation : 1) + 2);
}

template <class T>
struct DrawScratch {
    std::vector<SubPoint> points;
    std::vector<geo::Polar<T>> vertices;  // the body's vertices, then their 3-vectors:
    std::vector<geo::Vec3<T>> vectors;    // body_screen_points uses vectors[vertices.size() ...]
    template <class W>
    void prepare(const W& world) {
        std::size_t most = 1, most_v = 1;
        for (const auto& b : world.bodies) {
            most = std::max(most, body_point_capacity(b));
            most_v = std::max(most_v, b.local.size());
        }
        points.resize(most);
        vertices.resize(most_v);
        vectors.resize(most_v);
    }
};

// The screen mapping of the canvas: centre and pixels per unit of projected radius.
template <class T>
struct ScreenMap {
    T cx, cy, scale;
    static ScreenMap of(int width, int height, T R) {
        const int side = width < height ? width : height;
        return {T(width) / T(2), T(height) / T(2), T(side) / T(2) / R};
    }
    static ScreenMap of(const Canvas& c, T R) { return of(c.width(), c.height(), R); }
};

template <class T>
SubPoint to_pixels(const geo::ScreenPoint<T>& p) {
    if constexpr (std::is_same_v<T, fx::fixed>)
        return to_sub_q16(p.x.raw(), p.y.raw());
    else
        return to_sub(static_cast<double>(p.x), static_cast<double>(p.y));
}

namespace detail {
// One colour as 12 bytes of pixels held in three 32-bit words (4 pixels of 3 bytes, 6 of 2, 3
// of 4: whole pixels in any format, little-endian as set_word). A span is written from these
// words in registers as blocks the compiler turns into 16-byte vector stores, then the last
// words and bytes: no call and no load from memory per block. With 2 or 4 bytes per pixel the
// three words are one and the same (`single`), written 128 bytes per block.
struct SpanPattern {
    uint32_t w[3] = {};
    int bpp;
    bool single;
    SpanPattern(uint32_t word, int bytes_per_pixel) : bpp(bytes_per_pixel > 0 ? bytes_per_pixel : 1) {
        uint8_t bytes[12];
        for (int i = 0; i < 12; ++i) bytes[i] = static_cast<uint8_t>(word >> (8 * (i % bpp)));
        std::memcpy(w, bytes, 12);
        single = w[0] == w[1] && w[1] == w[2];
    }
};
inline void store_word(uint8_t* p, uint32_t v) { std::memcpy(p, &v, 4); }
// The last rest < 12 bytes of a span, starting at word a of the pattern (a, b, c).
inline void fill_tail(uint8_t* p, std::size_t rest, uint32_t a, uint32_t b, uint32_t c) {
    uint32_t next = a;  // the pattern word the remaining bytes start in
    if (rest >= 4) store_word(p, a), p += 4, rest -= 4, next = b;
    if (rest >= 4) store_word(p, b), p += 4, rest -= 4, next = c;
    if (rest & 2) {
        const uint16_t half = static_cast<uint16_t>(next);
        std::memcpy(p, &half, 2);
        p += 2, next >>= 16;
    }
    if (rest & 1) *p = static_cast<uint8_t>(next);
}
// n pixels of the pattern's colour from p on.
inline void fill_span(uint8_t* p, int n, const SpanPattern& pat) {
    if (n <= 0) return;
    std::size_t rest = static_cast<std::size_t>(n) * static_cast<std::size_t>(pat.bpp);
    const uint32_t a = pat.w[0], b = pat.w[1], c = pat.w[2];
    if (pat.single) {
        for (std::size_t k = rest / 128; k > 0; --k, p += 128)
            for (int i = 0; i < 128; i += 4) store_word(p + i, a);
        rest %= 128;
        for (; rest >= 16; rest -= 16, p += 16) store_word(p, a), store_word(p + 4, a), store_word(p + 8, a), store_word(p + 12, a);
        for (; rest >= 4; rest -= 4, p += 4) store_word(p, a);
        return fill_tail(p, rest, a, a, a);
    }
    for (std::size_t k = rest / 48; k > 0; --k, p += 48)
        for (int i = 0; i < 48; i += 12) store_word(p + i, a), store_word(p + i + 4, b), store_word(p + i + 8, c);
    rest %= 48;
    for (; rest >= 12; rest -= 12, p += 12) store_word(p, a), store_word(p + 4, b), store_word(p + 8, c);
    fill_tail(p, rest, a, b, c);
}

// The fixed engine's equidistant view from the 3-vector model straight to sub-pixels, for the
// draw's inner loop: a point (w, x, y) is shown at (x, y) E(w) (fx::equidistant_ratio_q30: one
// table lookup, no reciprocal and no ATf) times the screen scale, E(w) and the scale in one
// product G per point. Its domain: 0 <= w < 32 with |x|, |y| <= 100 (as project_vec's fast
// path), and past the sphere's equator -1/2 <= w < 0 with |x|, |y| <= 16 (E <= 2.42); and a
// scale below 2^14 px per unit. There every product fits in 64 bits (|x| G < 2^(22.6 + 39.7)
// and 2^(20 + 40.3)) and every result in 32 bits (|x| E scale < 100 pi/2 2^14 px < 2^21.3 px).
// project_vec takes the rest.
struct FixedEquidistant {
    static constexpr int kG = 25;                   // G = E scale in Q25 px per unit
    static constexpr int kGs = 16 + 30 - kG;        // Q16 scale x Q30 E -> Q25
    static constexpr int kXs = 16 + kG - kSubBits;  // Q16 x Q25 -> 1/256 px
    int32_t cx = 0, cy = 0;  // the canvas centre, 1/256 px
    int64_t scale = 0;       // px per unit, Q16
    int64_t flat_G = 0;      // G at E = 1, the plane's: kept, since scale << 9 per point cost 24 -> 25 aarch64 insns
    // fx::tables::equi_q30's address, as a value: a loop's copy of this struct then keeps it in a
    // register, where GCC otherwise loads it from the GOT again for every point (2 instructions).
    const int32_t* equi = nullptr;
    static bool make(const ScreenMap<fx::fixed>& m, FixedEquidistant& e) {
        const int32_t sc = m.scale.raw();
        if (sc <= 0 || sc >= (int32_t{1} << 30)) return false;
        e.cx = m.cx.raw() >> 8, e.cy = m.cy.raw() >> 8, e.scale = sc;
        e.flat_G = (int64_t{1} << 30) * e.scale >> kGs;
        e.equi = fx::tables::equi_q30.data();
        return true;
    }
    // The point of Q16.16 coordinates held in 64 bits (a slerp's sums, unsaturated); false
    // outside the domain. Flat: K = 0, where every point has w = C_0(r) = 1 and E(1) = 1: w is
    // not looked at (nor, inlined, computed) and G is the same for every point; the domain is
    // |x|, |y| <= 100.
    template <bool Flat = false>
    [[gnu::always_inline]] bool point(int64_t w, int64_t x, int64_t y, SubPoint& p) const {
        auto within = [&](int64_t lim) {
            return static_cast<uint64_t>(x + lim) <= static_cast<uint64_t>(2 * lim) &&
                   static_cast<uint64_t>(y + lim) <= static_cast<uint64_t>(2 * lim);
        };
        if constexpr (Flat) {
            if (!within(int64_t{100} << 16)) return false;
            p = {cx + static_cast<int32_t>((x * flat_G) >> kXs), cy - static_cast<int32_t>((y * flat_G) >> kXs)};
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
        const int64_t G = (E * scale) >> kGs;
        p = {cx + static_cast<int32_t>((x * G) >> kXs), cy - static_cast<int32_t>((y * G) >> kXs)};
        return true;
    }
};
}  // namespace detail

// Rows [y0, y1) of the backdrop: the background, the shaded outside of the limit circle. The
// same pixels as c.clear(background) then shade_outside_circle(...) (the same column range per
// row, computed the same way), written once each as spans.
template <class T>
void draw_backdrop_rows(const Canvas& c, const ScreenMap<T>& m, T R, const DrawOptions& o, int y0, int y1) {
    const int w = c.width(), bpp = c.format().bytes_per_pixel();
    const detail::SpanPattern bg(c.format().pack(o.background), bpp), out(c.format().pack(o.outside), bpp);
    const double r = static_cast<double>(m.scale) * static_cast<double>(R);
    const double cx = static_cast<double>(m.cx), cy = static_cast<double>(m.cy);
    y0 = std::max(y0, 0), y1 = std::min(y1, c.height());
    for (int y = y0; y < y1; ++y) {
        uint8_t* row = c.row(y);
        if (!o.shade_outside) {
            detail::fill_span(row, w, bg);
            continue;
        }
        const double dy = y + 0.5 - cy;
        int in0 = 0, in1 = -1;  // columns whose centre is inside: [in0, in1]
        if (std::fabs(dy) < r) {
            const double half = std::sqrt(r * r - dy * dy);
            in0 = static_cast<int>(std::fmax(-1.0, std::floor(cx - half - 0.5) + 1));
            in1 = static_cast<int>(std::fmin(w, std::ceil(cx + half - 0.5) - 1));
        }
        const int a = std::clamp(in0, 0, w), b = std::clamp(in1 + 1, 0, w);
        if (a >= b) {
            detail::fill_span(row, w, out);
            continue;
        }
        detail::fill_span(row, a, out);
        detail::fill_span(row + static_cast<std::ptrdiff_t>(a) * bpp, b - a, bg);
        detail::fill_span(row + static_cast<std::ptrdiff_t>(b) * bpp, w - b, out);
    }
}

// The background, the shaded outside and the rim of the limit circle.
template <class T>
void draw_backdrop(const Canvas& c, const ScreenMap<T>& m, T R, const DrawOptions& o) {
    draw_backdrop_rows(c, m, R, o, 0, c.height());
}

namespace detail {
// Where a body's screen points stand: entries written, and whether a run of visible points is
// under way (a hidden point then writes kBreak).
struct Cursor {
    std::size_t count = 0;
    bool open = false;
};
// One projected point (X, Y), or a break where it is hidden.
template <class T>
Cursor put_point(SubPoint* out, Cursor c, const ScreenMap<T>& m, bool visible, T X, T Y) {
    if (!visible) {
        if (c.open) out[c.count++] = kBreak, c.open = false;
        return c;
    }
    out[c.count++] = to_pixels(geo::ScreenPoint<T>{m.cx + m.scale * X, m.cy - m.scale * Y});
    c.open = true;
    return c;
}
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
    return out + put_point(out, cursor_at(out, at), m, pp.visible, pp.X, pp.Y).count;
}
// The same for the slerp's point a P + b Q, its 3-vector saturated as geo::edge_projected's.
[[gnu::noinline]] inline SubPoint* general_slerp_point(fx::fixed K, const ScreenMap<fx::fixed>& m, fx::fixed a, fx::fixed b,
                                                       const geo::Vec3<fx::fixed>& P, const geo::Vec3<fx::fixed>& Q,
                                                       SubPoint* out, SubPoint* at) {
    return general_point(K, m, {dot2(a, P.w, b, Q.w), dot2(a, P.x, b, Q.x), dot2(a, P.y, b, Q.y)}, out, at);
}
// An edge whose ends are antipodal on the sphere: walked from its polar end points.
[[gnu::noinline]] inline SubPoint* antipodal_points(fx::fixed K, const ScreenMap<fx::fixed>& m, const geo::Vec3<fx::fixed>& P,
                                                    const geo::Vec3<fx::fixed>& Q, int level, bool with_start,
                                                    geo::Polar<fx::fixed>* verts, SubPoint* out, SubPoint* at) {
    Cursor c = cursor_at(out, at);
    verts[0] = geo::to_polar(K, P), verts[1] = geo::to_polar(K, Q);
    geo::edge_projected(K, verts[0], verts[1], P, Q, level, geo::Projection::azimuthal_equidistant, with_start,
                        [&](int, bool vis, fx::fixed X, fx::fixed Y) { c = put_point(out, c, m, vis, X, Y); });
    return out + c.count;
}
// One coordinate of a slerp's point a P + b Q in Q16.16, rounded down (dot2 rounds to nearest:
// a bias of half a step, about 0.002 px at 1920x1080, for three fewer additions a point), not saturated,
// from its two products (each below 2^62 in magnitude): the sum wraps (defined, in unsigned)
// only when all four factors are -2^31, and then leaves FixedEquidistant's domain.
[[gnu::always_inline]] inline int64_t slerp_sum(int64_t p, int64_t q) {
    return static_cast<int64_t>(static_cast<uint64_t>(p) + static_cast<uint64_t>(q)) >> 16;
}
// The slerp's points a P + b Q for the weights [ab, end) of one edge, written from `at` on
// while FixedEquidistant shows them. Returns where it stopped: the weights of the first point
// it leaves (or end), and the next entry. A function of its own, so that the loop's values
// stay in registers.
struct Run {
    const fx::fixed* ab;
    SubPoint* at;
};
template <bool Flat>
[[gnu::noinline]] Run slerp_run(const FixedEquidistant& fe, const geo::Vec3<fx::fixed>& P, const geo::Vec3<fx::fixed>& Q,
                                const fx::fixed* ab, const fx::fixed* end, SubPoint* at) {
    const int64_t pw = P.w.raw(), px = P.x.raw(), py = P.y.raw();
    const int64_t qw = Q.w.raw(), qx = Q.x.raw(), qy = Q.y.raw();
    const FixedEquidistant f = fe;
    for (; ab < end; ab += 2, ++at) {
        const int64_t a = ab[0].raw(), b = ab[1].raw();
        if (!f.point<Flat>(slerp_sum(a * pw, b * qw), slerp_sum(a * px, b * qx), slerp_sum(a * py, b * qy), *at)) break;
    }
    return {ab, at};
}
// A body at level 2 (one slerp point per edge: the grid lines), edges [e, edges): each edge's
// point and end, from `at` on, while FixedEquidistant shows both and no edge is antipodal.
// Returns the first edge it leaves (or edges) and the next entry.
struct Level2Run {
    std::size_t e;
    SubPoint* at;
};
template <bool Flat>
[[gnu::noinline]] Level2Run level2_run(const FixedEquidistant& fe, const geo::Vec3<fx::fixed>* vecs,
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
// `at` on, while FixedEquidistant shows them all and no edge is antipodal. Returns the first
// edge it does not finish (or edges) and where that edge's entries begin: an edge it leaves
// halfway is done again by the caller's per-edge path, whose points are the same bits. One
// call per body; at level 1 (Points = false: an edge is its end alone) no call per edge at all.
struct EdgeRun {
    std::size_t e;
    SubPoint* at;
};
template <bool Flat, bool Points>
[[gnu::noinline]] EdgeRun edge_run(const FixedEquidistant& fe, const geo::Vec3<fx::fixed>* vecs, const uint8_t* antipodal,
                                   const fx::fixed* weights, std::size_t per_edge, std::size_t n, std::size_t edges,
                                   std::size_t e, SubPoint* at) {
    const FixedEquidistant f = fe;
    const fx::fixed* ab = weights + e * per_edge;
    // Edge e, ending at Q: false where it stops.
    auto edge = [&](std::size_t e, const geo::Vec3<fx::fixed>& Q) __attribute__((always_inline)) {
        SubPoint* p = at;
        if constexpr (Points) {  // the edge's own points: slerp_run's loop, which keeps its values in registers
            const fx::fixed* const end = ab + per_edge;
            const Run r = slerp_run<Flat>(f, vecs[e], Q, ab, end, at);
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
            const Level2Run r = level2_run<Flat>(fe, vecs, sh.antipodal.data(), sh.weights.data(), n, edges, e, at);
            e = r.e, at = r.at;
        } else {  // every edge in one call while all is shown
            const uint8_t* const antipodal = sh.any_antipodal ? sh.antipodal.data() : nullptr;
            const EdgeRun r = level == 1 ? edge_run<Flat, false>(fe, vecs, antipodal, sh.weights.data(), 0, n, edges, e, at)
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
        const fixed* ab = sh.weights_of(e);  // (at level 2, an edge level2_run left)
        const fixed* const end = ab + 2 * (level - 1);
        for (;;) {
            const Run r = slerp_run<Flat>(fe, P, Q, ab, end, at);
            at = r.at;
            if (r.ab >= end) break;
            at = general_slerp_point(K, m, r.ab[0], r.ab[1], P, Q, out, at);  // a point slerp_run leaves
            ab = r.ab + 2;
        }
        vertex(Q);
    }
    return static_cast<std::size_t>(at - out);
}
}  // namespace detail

// One body's geometry: its vertices, its edges tessellated at the body's level, projected and
// mapped to the screen, into out (room for body_point_capacity(b)) as one polyline with kBreak
// where a point cannot be shown. Returns the number of entries written. Writes only verts,
// vecs, out and the body's own shape cache (World::shape, refreshed if K changed): bodies can
// be done on different threads at once. vecs (room for b.local.size()) receives the vertices'
// 3-vectors; verts (room for b.local.size()) their polar positions with the paper's engine,
// and is scratch otherwise.
template <class W>
std::size_t body_screen_points(const W& world, const world::Body<typename W::scalar>& b,
                               const ScreenMap<typename W::scalar>& m, const DrawOptions& o,
                               geo::Polar<typename W::scalar>* verts, geo::Vec3<typename W::scalar>* vecs, SubPoint* out) {
    using T = typename W::scalar;
    const std::size_t n = b.local.size();
    if (n == 0) return 0;
    const int level = b.desc->tessellation;
    const std::size_t edges = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
    std::size_t count = 0;
    bool open = false;  // a run of visible points is under way
    auto add_xy = [&](bool visible, T X, T Y) {
        if (!visible) {
            if (open) out[count++] = kBreak, open = false;
            return;
        }
        out[count++] = to_pixels(geo::ScreenPoint<T>{m.cx + m.scale * X, m.cy - m.scale * Y});
        open = true;
    };
    auto add = [&](geo::Polar<T> p) {
        const geo::ProjectedPoint<T> pp = geo::project_polar(world.K, p, o.projection);
        add_xy(pp.visible, pp.X, pp.Y);
    };
    if constexpr (std::is_same_v<typename W::engine, world::Engine<T, false>>) {
        // In the 3-vector model throughout (geometry.hpp): the vertices are the body's motion
        // applied to its local 3-vectors, each edge's points its cached slerp weights applied to
        // its ends, and every point goes straight to the projection plane. An edge's first point
        // is the previous edge's last.
        const world::ShapeCache<T>& sh = world.shape(b);
        const geo::Motion<T> motion = geo::body_motion(world.K, b.centre, b.facing);
        const geo::MotionApply<T> apply(motion);
        apply(sh.local.data(), vecs, n);
        if constexpr (std::is_same_v<T, fx::fixed>) {
            detail::FixedEquidistant fe;
            if (edges > 0 && o.projection == geo::Projection::azimuthal_equidistant && detail::FixedEquidistant::make(m, fe))
                return world.K.raw() == 0 ? detail::fixed_equidistant_points<true>(world.K, sh, fe, m, vecs, verts, n, edges, level, out)
                                          : detail::fixed_equidistant_points<false>(world.K, sh, fe, m, vecs, verts, n, edges, level, out);
        }
        auto emit = [&](int, bool vis, T X, T Y) { add_xy(vis, X, Y); };
        if (edges == 0) {
            const geo::ProjectedPoint<T> pp = geo::project_vec(world.K, vecs[0], o.projection);
            add_xy(pp.visible, pp.X, pp.Y);
            return count;
        }
        for (std::size_t e = 0; e < edges; ++e) {
            const std::size_t f = (e + 1) % n;
            if (!sh.antipodal[e]) {
                geo::edge_projected(world.K, vecs[e], vecs[f], sh.weights_of(e), level, o.projection, e == 0, emit);
            } else {  // antipodal ends: walked from the polar end points (rare: K > 0, an edge of length pi / sqrt K)
                verts[0] = geo::to_polar(world.K, vecs[e]), verts[1] = geo::to_polar(world.K, vecs[f]);  // n >= 2
                geo::edge_projected(world.K, verts[0], verts[1], vecs[e], vecs[f], level, o.projection, e == 0, emit);
            }
        }
        return count;
    }
    world.vertices(b, verts);
    if (edges == 0) {
        add(verts[0]);
        return count;
    }
    for (std::size_t e = 0; e < edges; ++e)  // the paper's engine: its formulas, in polar
        W::engine::edge_points(world.K, verts[e], verts[(e + 1) % n], level, [&](int k, geo::Polar<T> p) {
            if (k == 0 && e > 0) return;
            add(p);
        });
    return count;
}

// One body's raster: each run between breaks as an open polyline (a single point as a dot).
// With `rows`, only those rows are written (exactly the pixels the whole body has there).
inline void draw_screen_points(const Canvas& c, const SubPoint* pts, std::size_t count, Rgb color, LineStyle line,
                               RowRange rows = {}) {
    std::size_t i = 0;
    while (i < count) {
        std::size_t j = i;
        while (j < count && !(pts[j].x == kBreak.x && pts[j].y == kBreak.y)) ++j;
        const std::size_t run = j - i;
        if (run >= 2) draw_polyline(c, pts + i, static_cast<int>(run), false, color, line, rows);
        if (run == 1) draw_line(c, pts[i], pts[i], color, line, true, rows);
        i = j + 1;
    }
}

template <class B>
Rgb body_color(const B& b) {
    return {b.desc->color.r, b.desc->color.g, b.desc->color.b};
}

// One body's outline.
template <class W>
void draw_body(const Canvas& c, const W& world, const world::Body<typename W::scalar>& b, const ScreenMap<typename W::scalar>& m,
               const DrawOptions& o, DrawScratch<typename W::scalar>& s) {
    const std::size_t count = body_screen_points(world, b, m, o, s.vertices.data(), s.vectors.data(), s.points.data());
    draw_screen_points(c, s.points.data(), count, body_color(b), LineStyle{o.antialias, o.line_width});
}

template <class W>
void draw_world(const Canvas& c, const W& world, const DrawOptions& o, DrawScratch<typename W::scalar>& s,
                bool backdrop = true) {
    using T = typename W::scalar;
    const ScreenMap<T> m = ScreenMap<T>::of(c, world.R);
    if (backdrop) draw_backdrop(c, m, world.R, o);
    for (const auto& b : world.bodies) {
        if (b.desc->grid ? !o.grids : !o.bodies) continue;
        draw_body(c, world, b, m, o, s);
    }
}

// ---- the threaded path --------------------------------------------------------------------

// With one band per thread (home mode): what a thread's geometry leaves for one band's raster,
// per body of its own that reaches the band, in a list only that thread writes
// (ParallelScratch::lists), in the world's order; an entry with idx kEnd closes the list. A
// band's raster merges the threads' lists for it by idx, so it reads nothing of the bodies that
// do not reach it, and nothing of the world: the colour is in the entry. With a BodyFrame per
// body instead, both rasters read every body's frame data, which the two cores then wrote in
// the next frame, interleaved as the bodies' homes are. Measured on stress, fixed, 800x480, two
// threads, two builds alternating in one process (both fetching each thread's next bodies
// ahead), while a cache line took 420-540 ns to go to the other core and back: the frame took
// 147-152 us with BodyFrames and 143-147 us with the lists (geometry -1.5 us, raster -2 us).
struct BandEntry {
    static constexpr uint32_t kEnd = UINT32_MAX;
    int32_t top = 0, bottom = 0;  // the points' smallest and largest y, 1/256 px
    uint32_t count = 0;           // entries at points
    uint32_t idx = kEnd;          // the body's index in World::bodies
    const SubPoint* points = nullptr;  // in the arena of the thread that did the body
    Rgb color{};
    std::atomic<uint32_t> ready{0};  // the frame generation this entry was written in
};

// Buffers for draw_world over a WorkerPool: every body's points at once, each thread's band
// lists and vertices. Sized by prepare.
//
// Each thread writes the points of the bodies it does one after the other into an arena of its
// own (points, thread t's from t * stride_points), so that a core's writes form one stream in
// memory no other core writes. Measured on stress, 800x480, fixed, 2 threads (median of 4000
// frames, rdtsc per phase): the geometry phase (steps included) takes 293 us on one thread; with
// a slice per body in one shared array (the two cores' slices interleaved) it took 222-226 us on
// each of two threads (1.3x), with the arenas 172-182 us (1.65x), and the frame went from 1.4x
// to 1.7x. Writing every body into one small buffer that stays in L1 would give 2x, but the
// raster needs all the points at once.
template <class T>
struct ParallelScratch {
    std::vector<SubPoint> points;
    std::size_t stride_points = 1;
    // Each thread's vertices and 3-vectors: thread t's start at t * stride, slices whole cache
    // lines apart (no line written by two threads).
    std::vector<geo::Polar<T>> vertices;
    std::vector<geo::Vec3<T>> vectors;
    std::size_t stride_v = 1, stride_vec = 1;
    std::size_t bodies = 0;
    uint32_t generation = 0;
    // One band per thread: thread t's band is rows [edge[t], edge[t + 1]) (rounded), moved after
    // each frame towards equal busy time (balance_bands) unless balance is false. Empty: equal
    // bands (set again whenever the canvas height or the pool changes).
    std::vector<double> edge;
    bool balance = true;
    struct alignas(64) Busy {
        double seconds = 0;   // the thread's time in the last frame, waits for other threads left out
        double geometry = 0;  // of which its geometry phase, for benchmarks
        double waited = 0;    // and the time it waited for another thread's bodies
    };
    std::unique_ptr<Busy[]> busy;
    std::vector<double> smoothed;  // busy time, smoothed over frames
    // With one band per thread, each body's geometry is done by the thread whose band holds the
    // middle of its points last frame ("home"), so that the raster mostly reads points its own
    // core wrote. home[g & 1] is read in frame g, home[(g + 1) & 1] written for the next.
    std::vector<uint8_t> home[2];
    // Home mode: thread u's list for band k is the bodies' + 1 entries from
    // lists[(u * threads + k) * stride_list]; between two lists lie at least 64 bytes, so no
    // line holds two threads' entries.
    std::unique_ptr<BandEntry[]> lists;
    std::size_t stride_list = 1, list_entries = 0;
    BandEntry* list(int thread, int band, int threads) const {
        return lists.get() + (static_cast<std::size_t>(thread) * static_cast<std::size_t>(threads) + static_cast<std::size_t>(band)) * stride_list;
    }

    template <class W>
    void prepare(const W& world, const WorkerPool& pool) {
        bodies = world.bodies.size();
        std::size_t most_v = 1, all = 0;
        for (std::size_t i = 0; i < bodies; ++i) {
            all += arena_step(body_point_capacity(world.bodies[i]));  // one thread may do every body
            most_v = std::max(most_v, world.bodies[i].local.size());
        }
        stride_points = all + 16;  // and two lines between arenas (their starts need not be on a line)
        points.resize(stride_points * static_cast<std::size_t>(pool.size()));
        // (most_v entries rounded up to whole lines, plus a line: the vector's start need not be
        // on a line boundary)
        auto stride = [most_v](std::size_t size) { return ((most_v * size + 63) / 64 + 1) * 64 / size + 1; };
        stride_v = stride(sizeof(geo::Polar<T>)), stride_vec = stride(sizeof(geo::Vec3<T>));
        vertices.resize(stride_v * static_cast<std::size_t>(pool.size()));
        vectors.resize(stride_vec * static_cast<std::size_t>(pool.size()));
        stride_list = bodies + 1 + (64 + sizeof(BandEntry) - 1) / sizeof(BandEntry);
        const std::size_t threads = static_cast<std::size_t>(pool.size());
        list_entries = stride_list * threads * threads;
        lists.reset(new BandEntry[list_entries]);
        for (auto& h : home) {
            h.resize(bodies);
            for (std::size_t i = 0; i < bodies; ++i) h[i] = static_cast<uint8_t>(i % static_cast<std::size_t>(pool.size()));
        }
        generation = 0;
        edge.clear();
        edge.reserve(static_cast<std::size_t>(pool.size()) + 1);  // (set by the first frame: no allocation there)
        busy.reset(new Busy[static_cast<std::size_t>(pool.size())]);
        smoothed.assign(static_cast<std::size_t>(pool.size()), 0.0);
    }
    // The next frame's generation, never 0. When the count wraps past 2^32 - 1, every ready
    // flag is cleared first: a list entry that went unwritten for 2^32 frames (a list shorter
    // all that time) would otherwise carry the new frame's number before its thread wrote it.
    uint32_t next_generation() {
        if (++generation == 0) {
            for (std::size_t i = 0; i < list_entries; ++i) lists[i].ready.store(0, std::memory_order_relaxed);
            generation = 1;
        }
        return generation;
    }
    // Room a body of n points takes in an arena: whole cache lines (8 points), so each body's
    // points start a line.
    static std::size_t arena_step(std::size_t n) { return (n + 7) / 8 * 8; }
};

// Moves the band edges after a frame so that the threads' busy times even out: each inner edge
// goes towards the busier of its two bands by `gain` times the relative difference of their
// (smoothed) times, times the two bands' rows. Every band keeps at least one row. busy[t] is
// thread t's time; smoothed carries the exponential average between calls (weight `keep` on
// the past). The pixels do not depend on the edges, only how the work is split does. The
// defaults are slow on purpose: on this shared machine one core is now and then much slower for
// a few milliseconds, and gain 0.5 with weight 0.75 chased those (stress fixed 2 threads, median
// frame 260-336 us against 257-305 with equal bands), while gain 0.1 with 0.95 settles and
// gains ~3% (249-255 us against 257-260, A/B in one process, 3000 frames each).
inline void balance_bands(std::vector<double>& edge, const double* busy, std::vector<double>& smoothed,
                          double gain = 0.1, double keep = 0.95) {
    const std::size_t bands = edge.size() - 1;
    for (std::size_t t = 0; t < bands; ++t)
        smoothed[t] = smoothed[t] > 0 ? keep * smoothed[t] + (1 - keep) * busy[t] : busy[t];
    for (std::size_t k = 1; k < bands; ++k) {
        const double a = smoothed[k - 1], b = smoothed[k];
        if (!(a + b > 0)) continue;
        const double lo = edge[k - 1] + 1, hi = edge[k + 1] - 1;
        if (lo > hi) continue;
        edge[k] = std::clamp(edge[k] - gain * (a - b) / (a + b) * (edge[k + 1] - edge[k - 1]), lo, hi);
    }
}

// The smallest and largest y of n screen points, breaks (kBreak) left out: {INT32_MAX,
// INT32_MIN} when there is no point. Both are maxima: the top is minus the largest -y, and a
// break's y, INT32_MIN, is its own negative (mod 2^32), the least of both, so no point needs a
// test and the loop vectorises (SSE2, NEON). A scalar loop with the break test was 4% of the
// threaded frame's instructions (x86, stress, 800x480, fixed). Negating any other y does not
// wrap. (A y of INT32_MIN is taken for a break whatever its x, as the bands always took it.)
struct RowSpan {
    int32_t top, bottom;
};
inline RowSpan row_span(const SubPoint* pts, std::size_t n) {
    static_assert(kBreak.y == INT32_MIN);
    int32_t up = INT32_MIN, down = INT32_MIN;  // the largest -y and y
    for (std::size_t k = 0; k < n; ++k) {
        const int32_t y = pts[k].y;
        up = std::max(up, static_cast<int32_t>(0u - static_cast<uint32_t>(y))), down = std::max(down, y);
    }
    return {up == INT32_MIN ? INT32_MAX : -up, down};
}

// The same frame as draw_world(c, world, o, DrawScratch), pixel for pixel, on pool.size()
// threads, in one pool.run, with one band of rows per thread (thread t draws band t):
//  1. geometry: each thread computes the screen points of its home bodies
//     (ParallelScratch::home) and the rows they span, and enters each body in its list for
//     every band it reaches (BandEntry). An entry's flag says it is ready;
//  2. raster: each thread draws its band whole: its backdrop, then every body's lines clipped
//     to the band (RowRange: exactly the pixels the whole line has there), in the world's
//     order (the threads' lists for the band merged), waiting (yielding) for what another
//     thread has not written yet. Bands are disjoint, so no two threads write one pixel, and
//     each pixel gets the same writes in the same order as on one thread.
// The bands' edges move frame by frame to even out the threads' times (balance_bands). A pool
// of more than 255 threads, or a canvas with fewer rows than threads, is drawn on the calling
// thread alone. The scratch must have been prepared for this world and this pool.
template <class W>
void draw_world(const Canvas& c, const W& world, const DrawOptions& o, ParallelScratch<typename W::scalar>& s,
                WorkerPool& pool, bool backdrop = true) {
    using T = typename W::scalar;
    const ScreenMap<T> m = ScreenMap<T>::of(c, world.R);
    const int threads = pool.size();
    const LineStyle line{o.antialias, o.line_width};
    const int nb = static_cast<int>(std::min(s.bodies, world.bodies.size()));
    if (threads > 255 || c.height() < threads) {
        if (backdrop) draw_backdrop(c, m, world.R, o);
        for (std::size_t i = 0; i < static_cast<std::size_t>(nb); ++i) {
            const auto& b = world.bodies[i];
            if (b.desc->grid ? !o.grids : !o.bodies) continue;
            const std::size_t n = body_screen_points(world, b, m, o, s.vertices.data(), s.vectors.data(), s.points.data());
            draw_screen_points(c, s.points.data(), n, body_color(b), line);
        }
        return;
    }
    if (s.edge.size() != static_cast<std::size_t>(threads) + 1 || s.edge.back() != c.height()) {
        s.edge.resize(static_cast<std::size_t>(threads) + 1);
        for (int t = 0; t <= threads; ++t) s.edge[static_cast<std::size_t>(t)] = double(c.height()) * t / threads;
    }
    int row[256];  // band t is rows [row[t], row[t + 1])
    for (int t = 0; t <= threads; ++t) row[t] = static_cast<int>(std::lround(s.edge[static_cast<std::size_t>(t)]));
    const uint32_t gen = s.next_generation();
    const int64_t margin = row_margin(line);  // a body's pixels lie within its points' rows widened by this
    // Whether a body whose points span rows [top, bottom] (1/256 px) can put pixels in rows [y0, y1).
    auto reaches = [margin](int y0, int y1, int32_t top, int32_t bottom) {
        return bottom >= int64_t{y0} * kSub - margin && top < int64_t{y1} * kSub + margin;
    };
    // Draws such a body's lines clipped to rows [y0, y1). A body wholly inside the band (margin
    // included) writes only there: drawn as on one thread, without the band's per-segment checks.
    auto draw_in_band = [&c, &line, margin](int y0, int y1, const SubPoint* pts, std::size_t n, Rgb color, int32_t top,
                                           int32_t bottom) {
        const bool inside = top - margin >= int64_t{y0} * kSub && bottom + margin < int64_t{y1} * kSub;
        draw_screen_points(c, pts, n, color, line, inside ? RowRange{} : RowRange{y0, y1});
    };

    using clock = std::chrono::steady_clock;
    auto job = [&](int tid) {
        const clock::time_point started = clock::now();
        clock::duration waited{0};
        geo::Polar<T>* verts = s.vertices.data() + s.stride_v * static_cast<std::size_t>(tid);
        geo::Vec3<T>* vecs = s.vectors.data() + s.stride_vec * static_cast<std::size_t>(tid);
        SubPoint* arena = s.points.data() + s.stride_points * static_cast<std::size_t>(tid);
        BandEntry* list[256];  // this thread's list for band k, and its length
        uint32_t listed[256];
        for (int k = 0; k < threads; ++k) list[k] = s.list(tid, k, threads), listed[k] = 0;
        auto do_body = [&](std::size_t idx) {
            const auto& b = world.bodies[idx];
            SubPoint* pts = arena;
            const std::size_t n = (b.desc->grid ? !o.grids : !o.bodies) ? 0 : body_screen_points(world, b, m, o, verts, vecs, pts);
            const RowSpan span = row_span(pts, n);
            const int32_t top = span.top, bottom = span.bottom;
            // next frame's home: the band of the points' middle row
            uint8_t h = s.home[gen & 1][idx];
            if (top <= bottom) {
                const int64_t mid = (int64_t{top} + bottom) / 2 / kSub;
                h = 0;
                while (h + 1 < threads && mid >= row[h + 1]) ++h;
            }
            // Written only when it changes (rarely): the threads' bodies share these lines.
            if (s.home[(gen + 1) & 1][idx] != h) s.home[(gen + 1) & 1][idx] = h;
            for (int k = 0; k < threads && n > 0; ++k) {  // the bands it reaches
                if (!reaches(row[k], row[k + 1], top, bottom)) continue;
                BandEntry& e = list[k][listed[k]++];
                e.top = top, e.bottom = bottom, e.count = static_cast<uint32_t>(n), e.idx = static_cast<uint32_t>(idx);
                e.points = pts, e.color = body_color(b);
                e.ready.store(gen, std::memory_order_release);
            }
            arena += ParallelScratch<T>::arena_step(n);
        };
        const uint8_t* home = s.home[gen & 1].data();
        auto next_home = [home, nb, tid](int i) {  // this thread's next body after i (nb: none)
            do ++i;
            while (i < nb && home[i] != tid);
            return i;
        };
        // The body two ahead is fetched, for writing, while this one is done. Each core's
        // hardware prefetchers, following its bodies' addresses, take lines of the other
        // core's bodies between them: a step found its body's first line (the state it
        // writes) gone to the other core for 15-25% of the bodies (stress, 800x480, while a
        // line took 400-600 ns to the other core and back; time stamps around a first read
        // of it), and for 1.3% with the prefetch.
        constexpr int kAhead = 2;
        int ahead = -1;
        for (int k = 0; k <= kAhead; ++k) ahead = next_home(ahead);
        for (int i = next_home(-1); i < nb; i = next_home(i)) {
            if (ahead < nb) {
                WorkerPool::prefetch_for_write(&world.bodies[static_cast<std::size_t>(ahead)]);
                ahead = next_home(ahead);
            }
            do_body(static_cast<std::size_t>(i));
        }
        for (int k = 0; k < threads; ++k) {  // close the lists
            BandEntry& e = list[k][listed[k]];
            e.idx = BandEntry::kEnd;
            e.ready.store(gen, std::memory_order_release);
        }
        const clock::time_point geometry_done = clock::now();
        // thread t draws band t, the one whose bodies it did: the threads' lists merged
        const int y0 = row[tid], y1 = row[tid + 1];
        if (backdrop) draw_backdrop_rows(c, m, world.R, o, y0, y1);
        const BandEntry* head[256];
        for (int u = 0; u < threads; ++u) head[u] = s.list(u, tid, threads);
        for (;;) {
            int first = -1;  // the thread whose next entry has the least idx
            uint32_t least = BandEntry::kEnd;
            for (int u = 0; u < threads; ++u) {
                const BandEntry& e = *head[u];
                if (e.ready.load(std::memory_order_acquire) != gen) {
                    const clock::time_point w0 = clock::now();
                    while (e.ready.load(std::memory_order_acquire) != gen) WorkerPool::pause();
                    waited += clock::now() - w0;
                }
                if (e.idx < least) least = e.idx, first = u;
            }
            if (first < 0) break;  // every list closed
            const BandEntry& e = *head[first]++;
            draw_in_band(y0, y1, e.points, e.count, e.color, e.top, e.bottom);
        }
        auto seconds = [](clock::duration d) { return std::chrono::duration<double>(d).count(); };
        auto& mine = s.busy[static_cast<std::size_t>(tid)];
        mine.seconds = seconds(clock::now() - started - waited);
        mine.geometry = seconds(geometry_done - started), mine.waited = seconds(waited);
    };
    pool.run(job);
    if (s.balance) {
        double busy[256];
        for (int t = 0; t < threads; ++t) busy[t] = s.busy[t].seconds;
        balance_bands(s.edge, busy, s.smoothed);
    }
}

}  // namespace noneuclid::render
