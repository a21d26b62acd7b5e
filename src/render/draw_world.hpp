// Drawing a world into a Canvas, on the calling thread: the backdrop (render/backdrop.hpp),
// then each body in the world's order: its fill or texture, if it has one (render/fill.hpp),
// then its screen points (render/body_points.hpp) drawn as one polyline in the body's colour.
//
// The limit circle R fills the smaller side of the canvas, centred; the area outside it is
// shaded as in the paper's figures. Each body's edges are tessellated at the body's level; a
// point the projection cannot show breaks the polyline. With the fixed-point engine, screen
// points are computed in Q16.16 and handed to the rasteriser as sub-pixel integers: no floating
// point between the world and the pixels.
//
// render/parallel_frame.hpp draws the same frame, pixel for pixel, over a WorkerPool.
//
// Memory: a DrawScratch sized once for the world (prepare) holds every buffer; drawing a frame
// allocates nothing.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/geometry.hpp"
#include "render/backdrop.hpp"
#include "render/body_points.hpp"
#include "render/canvas.hpp"
#include "render/draw_options.hpp"
#include "render/fill.hpp"
#include "render/raster.hpp"
#include "render/screen_points.hpp"
#include "world/world.hpp"

namespace noneuclid::render {

// Buffers for drawing one body at a time (its points, vertices and 3-vectors), and every
// body's cache of its engine E (geometry/engine.hpp). Sized by prepare, for this world: prepare
// again for another world.
template <class T, class E = geo::Exact<T>>
struct DrawScratch {
    std::vector<SubPoint> points;
    std::vector<geo::Polar<T>> vertices;  // body_screen_points' verts and vecs
    std::vector<geo::Vec3<T>> vectors;
    std::vector<typename E::Cache> shapes;  // world.bodies[i]'s is shapes[i]
    FillScratch<T> fill;                  // filled and textured bodies (render/fill.hpp)
    // The backdrop's rows, kept from frame to frame where reserved for the canvas's height (the
    // firmware does: render/backdrop.hpp); otherwise computed as drawn.
    BackdropRows backdrop;
    // The view's scale for lines simplified to it (geometry/detail.hpp), if a body is one.
    geo::DetailScale detail;
    bool any_detail = false;
    // A frame drawn in bands (Canvas::band): each body's lowest reach (its points' largest y
    // and the lines' row margin, 1/256 px; INT32_MAX with a fill) found in the band at row 0 of
    // the world's frame `banded`, so that the later bands skip the bodies that end above them.
    std::vector<int32_t> lowest;
    long banded = -1;
    // keep_still: grid bodies' screen points kept for the frames in which they are still
    // (make_shape_caches; the firmware goes without).
    template <class W>
    void prepare(const W& world, bool keep_still = true) {
        std::size_t most = 1, most_v = 1;
        for (const auto& b : world.bodies) {
            most = std::max(most, body_point_capacity(world, b));
            most_v = std::max(most_v, b.local.size());
        }
        points.resize(most);
        vertices.resize(most_v);
        vectors.resize(most_v);
        make_shape_caches(world, shapes, keep_still);
        any_detail = render::any_detail(shapes);
        fill.prepare(world, 1);
        lowest.assign(world.bodies.size(), INT32_MAX);
        banded = -1;
    }
};

// The largest y of the points (breaks left out) plus `margin`, 1/256 px; INT32_MIN for none.
inline int32_t lowest_reach(const SubPoint* p, std::size_t count, int32_t margin) {
    int32_t low = INT32_MIN;
    for (std::size_t k = 0; k < count; ++k)
        if (!(p[k].x == kBreak.x && p[k].y == kBreak.y) && p[k].y > low) low = p[k].y;
    return low == INT32_MIN ? low : low + margin;  // (y is at most to_sub's 2^30: no overflow)
}

// World.bodies[i]: its fill, then its outline; its lowest reach into `lowest` if given.
template <class W>
void draw_body(const Canvas& c, const W& world, std::size_t i, const ScreenMap<typename W::scalar>& m, const DrawOptions& o,
               DrawScratch<typename W::scalar, typename W::engine>& s, int32_t* lowest = nullptr) {
    const auto& b = world.bodies[i];
    const FillJob* j = s.fill.plan(world, i, m, o, c.width(), c.height());
    if (j) fill_rows(c, *j, c.top(), std::min(c.bottom(), c.height()), s.fill.work[0]);
    const std::size_t count =
        body_screen_points(world, b, s.shapes[i], m, o, s.vertices.data(), s.vectors.data(), s.points.data());
    const LineStyle line{o.antialias, o.line_width};
    draw_screen_points(c, s.points.data(), count, body_color(b, o), line, held_rows(c));
    if (lowest) *lowest = j ? INT32_MAX : lowest_reach(s.points.data(), count, row_margin(line));
}

// The whole frame: the backdrop (left out when `backdrop` is false: the bodies are drawn over
// what the canvas holds), then every body the options show. In a band of the frame
// (Canvas::band) its rows alone, exactly as the whole frame has them: a frame's bands drawn top
// to bottom, the first at row 0, the world not changed between them (the later bands leave out
// the bodies the first found to end above them).
template <class W>
void draw_world(const Canvas& c, const W& world, const DrawOptions& o, DrawScratch<typename W::scalar, typename W::engine>& s,
                bool backdrop = true) {
    using T = typename W::scalar;
    ScreenMap<T> m = ScreenMap<T>::of(c, world.K, world.R, o.projection, o.disc);
    if (s.any_detail) set_detail(m, s.detail, world.K, world.R, o.projection);
    if (backdrop) draw_backdrop(c, m, o, &s.backdrop);
    s.fill.begin_frame(c);
    // In bands, top to bottom: the first finds the bodies' reach, the later ones skip by it.
    const bool first = !c.whole() && c.top() <= 0 && s.lowest.size() == world.bodies.size();
    const bool later = !c.whole() && c.top() > 0 && s.banded == world.frame;
    const int32_t above = later ? c.top() * kSub : INT32_MIN;  // (a band's top row: far below 2^23)
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        if (!body_shown(world.bodies[i], o) || (later && s.lowest[i] < above)) continue;
        draw_body(c, world, i, m, o, s, first ? &s.lowest[i] : nullptr);
    }
    if (first) s.banded = world.frame;
}

}  // namespace noneuclid::render
