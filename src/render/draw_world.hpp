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
    template <class W>
    void prepare(const W& world) {
        std::size_t most = 1, most_v = 1;
        for (const auto& b : world.bodies) {
            most = std::max(most, body_point_capacity(world, b));
            most_v = std::max(most_v, b.local.size());
        }
        points.resize(most);
        vertices.resize(most_v);
        vectors.resize(most_v);
        make_shape_caches(world, shapes);
        fill.prepare(world, 1);
    }
};

// World.bodies[i]: its fill, then its outline.
template <class W>
void draw_body(const Canvas& c, const W& world, std::size_t i, const ScreenMap<typename W::scalar>& m, const DrawOptions& o,
               DrawScratch<typename W::scalar, typename W::engine>& s) {
    const auto& b = world.bodies[i];
    if (const FillJob* j = s.fill.plan(world, i, m, o, c.width(), c.height())) fill_rows(c, *j, 0, c.height(), s.fill.work[0]);
    const std::size_t count =
        body_screen_points(world, b, s.shapes[i], m, o, s.vertices.data(), s.vectors.data(), s.points.data());
    draw_screen_points(c, s.points.data(), count, body_color(b, o), LineStyle{o.antialias, o.line_width});
}

// The whole frame: the backdrop (left out when `backdrop` is false: the bodies are drawn over
// what the canvas holds), then every body the options show.
template <class W>
void draw_world(const Canvas& c, const W& world, const DrawOptions& o, DrawScratch<typename W::scalar, typename W::engine>& s,
                bool backdrop = true) {
    using T = typename W::scalar;
    const ScreenMap<T> m = ScreenMap<T>::of(c, world.K, world.R, o.projection);
    if (backdrop) draw_backdrop(c, m, o);
    s.fill.begin_frame(c);
    for (std::size_t i = 0; i < world.bodies.size(); ++i)
        if (body_shown(world.bodies[i], o)) draw_body(c, world, i, m, o, s);
}

}  // namespace noneuclid::render
