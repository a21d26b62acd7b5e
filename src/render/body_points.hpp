// One body's screen points and their raster. body_screen_points asks the world's engine
// (geometry/engine.hpp) for the body's outline (its vertices, its edges tessellated on the
// screen, projected and mapped to sub-pixels) and clips it to the clip circle (ClipSink) into
// one polyline of sub-pixel points, with kBreak where it leaves the clip circle or the projection
// cannot show a point; draw_screen_points draws such a list.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "geometry/engine.hpp"
#include "render/canvas.hpp"
#include "render/clip_sink.hpp"
#include "render/draw_options.hpp"
#include "render/raster.hpp"
#include "render/screen_points.hpp"
#include "render/still_points.hpp"
#include "world/world.hpp"

namespace noneuclid::render {

// The room a body's screen points need: a first point, and for every chord of its outline at
// most three entries (ClipSink: two points where a chord crosses the clip circle twice, and a
// break).
template <class W>
std::size_t body_point_capacity(const W&, const world::Body<typename W::scalar>& b) {
    return 3 * W::engine::chords(b) + 2;
}

// A cache of the engine's for each of a world's bodies (Cache), made for them.
// With keep_still, a grid body's cache also keeps its screen points, for the frames in which
// it is still (body_screen_points): room for them, which a machine short of RAM (the
// firmware) goes without.
template <class W>
void make_shape_caches(const W& world, std::vector<typename W::engine::Cache>& caches, bool keep_still = true) {
    caches.resize(world.bodies.size());
    std::size_t recorded = 0;  // (the room of the records made so far)
    for (std::size_t i = 0; i < caches.size(); ++i) {
        caches[i].make(world.bodies[i]);
        if constexpr (requires { caches[i].still; }) {
            using Still = typename W::engine::Cache::Still;
            caches[i].still.reset();
            if (!keep_still || !world.bodies[i].desc || !world.bodies[i].desc->grid) continue;
            caches[i].still = std::make_unique<Still>();
            caches[i].still->screen.reserve(body_point_capacity(world, world.bodies[i]));
            if (!caches[i].tree) continue;
            // The records dealt out to the phases (record_phase) in turn by kRecordPhaseRoom of
            // their room: whatever part of the bodies is shown (a zoom level), its lines spread
            // over all phases.
            const std::size_t n = record_capacity(world, world.bodies[i]);
            caches[i].still->record.reserve(n);
            caches[i].still->record_phase = static_cast<uint32_t>((recorded + n / 2) / kRecordPhaseRoom % kRecordPhases);
            recorded += n;
        }
    }
}

// Whether any of the caches is of a line simplified for the view (geometry/detail.hpp).
template <class C>
bool any_detail(const std::vector<C>& caches) {
    if constexpr (requires(const C& c) { c.tree; })
        for (const C& c : caches)
            if (c.tree) return true;
    return false;
}

// The screen map m told the view's scale for such lines (d, updated if the view changed).
template <class T>
void set_detail(geo::ScreenMap<T>& m, geo::DetailScale& d, T K, T R, geo::Projection p) {
    d.update(static_cast<double>(K), static_cast<double>(R), p, static_cast<double>(m.scale));
    m.detail = &d;
}

// One body's outline, clipped, into out (room for body_point_capacity(b)) as one polyline with
// kBreak where it leaves the clip circle or a point cannot be shown. Returns the number of
// entries written. Writes only shape (the body's cache, made for it), verts, vecs (room for
// b.local.size() each: the engine's scratch) and out: bodies can be done on different threads
// at once.
template <class W>
std::size_t body_screen_points(const W& world, const world::Body<typename W::scalar>& b,
                               typename W::engine::Cache& shape, const ScreenMap<typename W::scalar>& m,
                               const DrawOptions& o, geo::Polar<typename W::scalar>* verts,
                               geo::Vec3<typename W::scalar>* vecs, SubPoint* out) {
    if (b.local.empty()) return 0;
    using Cache = typename W::engine::Cache;
    if constexpr (requires(Cache& c) { c.still; }) {
        if (shape.still) return still_screen_points(world, b, shape, *shape.still, m, o, verts, vecs, out);
    }
    ClipSink sink(m, out);
    W::engine::outline(world.K, b, shape, m, o.projection, verts, vecs, sink);
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
    const Rgb own{b.desc->color.r, b.desc->color.g, b.desc->color.b};
    if (o.palette == Palette::scene) return own;
    static_assert(static_cast<int>(LineRole::instrument) == static_cast<int>(world::BodyKind::instrument) &&
                  static_cast<int>(LineRole::grid) == static_cast<int>(world::BodyKind::grid) &&
                  static_cast<int>(LineRole::ship) == static_cast<int>(world::BodyKind::ship));
    return palette_line(o.palette, static_cast<LineRole>(b.desc->kind()), own);
}

}  // namespace noneuclid::render
