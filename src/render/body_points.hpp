// One body's screen points and their raster. body_screen_points computes a body's geometry
// (vertices, edges tessellated adaptively on the screen, projection, screen mapping, clipping)
// into one polyline of sub-pixel points, with kBreak where it leaves the clip circle or the
// projection cannot show a point; draw_screen_points draws such a list. The fixed engine's
// equidistant view evaluates its points with its own kernel (render/fixed_points.hpp); every
// other engine and projection with the general one (VecEval).
#pragma once

#include <algorithm>
#include <cstddef>
#include <type_traits>

#include "geometry/geometry.hpp"
#include "render/canvas.hpp"
#include "render/clip_sink.hpp"
#include "render/draw_options.hpp"
#include "render/edge_curve.hpp"
#include "render/fixed_points.hpp"
#include "render/raster.hpp"
#include "render/screen_points.hpp"
#include "render/shape_cache.hpp"
#include "world/world.hpp"

namespace noneuclid::render {

// The room a body's screen points need: a first point, and for every chord of its curve at
// most three entries (ClipSink: two points where a chord crosses the clip circle twice, and a
// break); the chords are its edges (a walked edge two) and the halvings of its budget, or for
// the paper's engine its edges' points at its tessellation level.
template <class B>
std::size_t body_point_capacity(const B& b) {
    const long n = static_cast<long>(b.local.size()), edges = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
    const long level = b.desc->tessellation > 0 ? b.desc->tessellation : 1;
    const long chords = std::max(2 * edges + body_split_budget(edges), edges * level);
    return static_cast<std::size_t>(3 * chords + 2);
}

namespace detail {
// A walked edge P -> Q of length d: cut in two at its midpoint, found by a walk from P (along
// P's radial line when the ends are antipodal: every great circle through them is a geodesic,
// and the one through P's radial line is the convention; else toward Q), and each half drawn by
// edge_curve (halves still too long are cut again, three times at most, then drawn as chords).
template <class T, class Eval>
void walked_edge(const Eval& ev, const ScreenMap<T>& m, T K, const geo::Vec3<T>& P, const geo::Vec3<T>& Q,
                 const Spot& sp, const Spot& sq, T d, typename SlerpMath<T>::U u, bool straight, ClipSink& sink,
                 long& budget, int cuts = 0) {
    using Math = SlerpMath<T>;
    using geo::Sf;  // and fx::Sf by ADL for fixed
    if (cuts == 3 || budget <= 0) return sink.chord(sp, sq);
    --budget;
    const geo::Polar<T> p = geo::to_polar(K, P), q = geo::to_polar(K, Q);
    const T heading = geo::antipodal_edge(K, d, Sf(K * d * d)) ? (p.r > T(0) ? p.theta : q.theta) : geo::bearing(K, p, q);
    const geo::Vec3<T> M = geo::to_vec(K, geo::walk_end(K, p, heading, d / T(2)));
    const Spot sm = ev.vertex(M);
    const typename Math::U half_u = Math::quarter(u);
    Eval e = ev;
    for (int k = 0; k < 2; ++k) {
        const geo::Vec3<T>&A = k == 0 ? P : M, &B = k == 0 ? M : Q;
        const Spot &sa = k == 0 ? sp : sm, &sb = k == 0 ? sm : sq;
        if (Math::too_long(half_u)) {
            walked_edge(ev, m, K, A, B, sa, sb, d / T(2), half_u, straight, sink, budget, cuts + 1);
        } else {
            e.ends(A, B);
            edge_curve<T>(e, m, sa, sb, half_u, Math::half(half_u), straight, sink, budget);
        }
    }
}
// Every edge of a body whose vertices' 3-vectors are vecs (n of them), in the evaluator ev.
template <class T, class Eval>
void body_curve(Eval ev, const ScreenMap<T>& m, T K, const ShapeCache<T>& sh, const geo::Vec3<T>* vecs, std::size_t n,
                std::size_t edges, bool straight, ClipSink& sink) {
    long budget = body_split_budget(static_cast<long>(edges));
    const Spot first = ev.vertex(vecs[0]);
    sink.start(first);
    Spot sp = first;
    for (std::size_t e = 0; e < edges; ++e) {
        const std::size_t f = e + 1 == n ? 0 : e + 1;
        const Spot sq = f == 0 ? first : ev.vertex(vecs[f]);
        if (straight && sp.shown && sq.shown) {  // (edge_curve's first case, without ends())
            sink.chord(sp, sq);
        } else if (sh.walked[e]) {
            walked_edge(ev, m, K, vecs[e], vecs[f], sp, sq, sh.length[e], sh.u[e], straight, sink, budget);
        } else {
            ev.ends(vecs[e], vecs[f]);
            edge_curve<T>(ev, m, sp, sq, sh.u[e], sh.h[e], straight, sink, budget);
        }
        sp = sq;
    }
}
}  // namespace detail

// One body's geometry: its vertices, its edges tessellated adaptively on the screen
// (render/edge_curve.hpp), projected, mapped to the screen and clipped to the clip circle, into
// out (room for body_point_capacity(b)) as one polyline with kBreak where it leaves the circle
// or a point cannot be shown. Returns the number of entries written. Writes only shape (the
// body's cache, made for it: refreshed if K changed), verts, vecs and out: bodies can be done
// on different threads at once. vecs (room for b.local.size()) receives the vertices'
// 3-vectors; verts (room for b.local.size()) their polar positions with the paper's engine.
template <class W>
std::size_t body_screen_points(const W& world, const world::Body<typename W::scalar>& b,
                               ShapeCache<typename W::scalar>& shape, const ScreenMap<typename W::scalar>& m,
                               const DrawOptions& o, geo::Polar<typename W::scalar>* verts,
                               geo::Vec3<typename W::scalar>* vecs, SubPoint* out) {
    using T = typename W::scalar;
    const std::size_t n = b.local.size();
    if (n == 0) return 0;
    const std::size_t edges = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
    ClipSink sink(m, out);
    if constexpr (std::is_same_v<typename W::engine, world::Engine<T, false>>) {
        // In the 3-vector model throughout (geometry/geometry.hpp): the vertices are the body's
        // motion applied to its local 3-vectors, each edge's points slerps of its ends.
        const ShapeCache<T>& sh = shape.refresh(world.K, b);
        const geo::Motion<T> motion = geo::body_motion(world.K, b.centre, b.facing);
        const geo::MotionApply<T> apply(motion);
        apply(sh.local.data(), vecs, n);
        const bool straight = geo::straight_geodesics(world.K, o.projection);
        if constexpr (std::is_same_v<T, fx::fixed>) {
            detail::FixedEquidistant fe;
            if (o.projection == geo::Projection::azimuthal_equidistant && detail::FixedEquidistant::make(m, fe)) {
                if (world.K.raw() == 0)
                    detail::body_curve(detail::FixedEquidistantEval<true>{fe, world.K, m}, m, world.K, sh, vecs, n, edges,
                                       straight, sink);
                else
                    detail::body_curve(detail::FixedEquidistantEval<false>{fe, world.K, m}, m, world.K, sh, vecs, n, edges,
                                       straight, sink);
                return sink.count();
            }
        }
        detail::body_curve(VecEval<T>{world.K, o.projection, m}, m, world.K, sh, vecs, n, edges, straight, sink);
        return sink.count();
    }
    // The paper's engine: its formulas, in polar, at the body's tessellation level; each point
    // projected, the chords clipped alike.
    auto spot = [&](geo::Polar<T> p) {
        const geo::ProjectedPoint<T> pp = geo::project_polar(world.K, p, o.projection);
        if (!pp.visible) return Spot{};
        return spot_at(m, to_pixels(geo::ScreenPoint<T>{m.cx + m.scale * pp.X, m.cy - m.scale * pp.Y}));
    };
    world.vertices(b, verts);
    if (edges == 0) {
        sink.start(spot(verts[0]));
        return sink.count();
    }
    Spot prev;
    for (std::size_t e = 0; e < edges; ++e)
        W::engine::edge_points(world.K, verts[e], verts[(e + 1) % n], b.desc->tessellation, [&](int k, geo::Polar<T> p) {
            if (k == 0 && e > 0) return;
            const Spot s = spot(p);
            if (k == 0)
                sink.start(s);
            else
                sink.chord(prev, s);
            prev = s;
        });
    return sink.count();
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

// Whether the options draw this body (grid bodies and the others can each be left out; a
// game's spare slots and a blinking ship's dark frames are not drawn).
template <class B>
bool body_shown(const B& b, const DrawOptions& o) {
    return b.active && !b.hidden && (b.desc->grid ? o.grids : o.bodies);
}

// A body's colour as the options draw it, as the rasteriser takes it.
template <class B>
Rgb body_color(const B& b, const DrawOptions& o) {
    if (b.desc->grid && o.tint_grids) return o.grid_tint;
    return {b.desc->color.r, b.desc->color.g, b.desc->color.b};
}

}  // namespace noneuclid::render
