// One body's screen points and their raster. body_screen_points computes a body's geometry
// (vertices, edges tessellated at the body's level, projection, screen mapping) into one
// polyline of sub-pixel points, with kBreak where the projection cannot show a point;
// draw_screen_points draws such a list. The fixed engine's equidistant view takes its own loop
// (render/fixed_points.hpp); every other engine and projection the general one below.
#pragma once

#include <cstddef>
#include <type_traits>

#include "geometry/geometry.hpp"
#include "render/canvas.hpp"
#include "render/draw_options.hpp"
#include "render/fixed_points.hpp"
#include "render/raster.hpp"
#include "render/screen_points.hpp"
#include "render/shape_cache.hpp"
#include "world/world.hpp"

namespace noneuclid::render {

// The room a body's screen points need: every tessellated point, plus a break after each.
template <class B>
std::size_t body_point_capacity(const B& b) {
    return 2 * (b.local.size() * static_cast<std::size_t>(b.desc->tessellation > 0 ? b.desc->tessellation : 1) + 2);
}

// One body's geometry: its vertices, its edges tessellated at the body's level, projected and
// mapped to the screen, into out (room for body_point_capacity(b)) as one polyline with kBreak
// where a point cannot be shown. Returns the number of entries written. Writes only shape (the
// body's cache, made for it: refreshed if K changed), verts, vecs and out: bodies can be done
// on different threads at once. vecs (room for b.local.size()) receives the vertices'
// 3-vectors; verts (room for b.local.size()) their polar positions with the paper's engine,
// and is scratch otherwise.
template <class W>
std::size_t body_screen_points(const W& world, const world::Body<typename W::scalar>& b,
                               ShapeCache<typename W::scalar>& shape, const ScreenMap<typename W::scalar>& m,
                               const DrawOptions& o, geo::Polar<typename W::scalar>* verts,
                               geo::Vec3<typename W::scalar>* vecs, SubPoint* out) {
    using T = typename W::scalar;
    const std::size_t n = b.local.size();
    if (n == 0) return 0;
    const int level = b.desc->tessellation;
    const std::size_t edges = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
    detail::Cursor cur;
    auto add_xy = [&](bool visible, T X, T Y) { detail::put_point(out, cur, m, visible, X, Y); };
    auto add = [&](geo::Polar<T> p) {
        const geo::ProjectedPoint<T> pp = geo::project_polar(world.K, p, o.projection);
        add_xy(pp.visible, pp.X, pp.Y);
    };
    if constexpr (std::is_same_v<typename W::engine, world::Engine<T, false>>) {
        // In the 3-vector model throughout (geometry/geometry.hpp): the vertices are the body's
        // motion applied to its local 3-vectors, each edge's points its cached slerp weights
        // applied to its ends, and every point goes straight to the projection plane. An edge's
        // first point is the previous edge's last.
        const ShapeCache<T>& sh = shape.refresh(world.K, b);
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
            return cur.count;
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
        return cur.count;
    }
    world.vertices(b, verts);
    if (edges == 0) {
        add(verts[0]);
        return cur.count;
    }
    for (std::size_t e = 0; e < edges; ++e)  // the paper's engine: its formulas, in polar
        W::engine::edge_points(world.K, verts[e], verts[(e + 1) % n], level, [&](int k, geo::Polar<T> p) {
            if (k == 0 && e > 0) return;
            add(p);
        });
    return cur.count;
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

// A body's colour, as the rasteriser takes it.
template <class B>
Rgb body_color(const B& b) {
    return {b.desc->color.r, b.desc->color.g, b.desc->color.b};
}

}  // namespace noneuclid::render
