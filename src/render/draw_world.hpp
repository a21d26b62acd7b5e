// Drawing a world: vertices -> tessellated edges -> projection -> lines, into a Canvas.
//
// The limit circle R fills the smaller side of the canvas, centred; the area outside it is
// shaded as in the paper's figures. Each body's edges are tessellated at the body's level and
// drawn as one polyline in the body's colour; a point the projection cannot show breaks the
// polyline. With the fixed-point engine, screen points are computed in Q16.16 and handed to
// the rasteriser as sub-pixel integers: no floating point between the world and the pixels.
//
// Memory: a DrawScratch sized once for the world (prepare) holds every buffer; drawing a
// frame allocates nothing.
#pragma once

#include <algorithm>
#include <type_traits>
#include <vector>

#include "geometry/geometry.hpp"
#include "render/canvas.hpp"
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

template <class T>
struct DrawScratch {
    std::vector<SubPoint> points;
    std::vector<geo::Polar<T>> vertices;
    template <class W>
    void prepare(const W& world) {
        std::size_t most = 1, most_v = 1;
        for (const auto& b : world.bodies) {
            most = std::max(most, b.local.size() * static_cast<std::size_t>(b.desc->tessellation) + 2);
            most_v = std::max(most_v, b.local.size());
        }
        points.resize(most);
        vertices.resize(most_v);
    }
};

// The screen mapping of the canvas: centre and pixels per unit of projected radius.
template <class T>
struct ScreenMap {
    T cx, cy, scale;
    static ScreenMap of(const Canvas& c, T R) {
        const int side = c.width() < c.height() ? c.width() : c.height();
        return {T(c.width()) / T(2), T(c.height()) / T(2), T(side) / T(2) / R};
    }
};

template <class T>
SubPoint to_pixels(const geo::ScreenPoint<T>& p) {
    if constexpr (std::is_same_v<T, fx::fixed>)
        return to_sub_q16(p.x.raw(), p.y.raw());
    else
        return to_sub(static_cast<double>(p.x), static_cast<double>(p.y));
}

// The background, the shaded outside and the rim of the limit circle.
template <class T>
void draw_backdrop(const Canvas& c, const ScreenMap<T>& m, T R, const DrawOptions& o) {
    c.clear(o.background);
    if (!o.shade_outside) return;
    const double r = static_cast<double>(m.scale) * static_cast<double>(R);
    shade_outside_circle(c, static_cast<double>(m.cx), static_cast<double>(m.cy), r, o.outside);
}

// One body's outline.
template <class W>
void draw_body(const Canvas& c, const W& world, const world::Body<typename W::scalar>& b, const ScreenMap<typename W::scalar>& m,
               const DrawOptions& o, DrawScratch<typename W::scalar>& s) {
    using T = typename W::scalar;
    const std::size_t n = b.local.size();
    if (n == 0) return;
    geo::Polar<T>* verts = s.vertices.data();
    world.vertices(b, verts);
    const int level = b.desc->tessellation;
    const std::size_t edges = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
    std::size_t count = 0;
    const Rgb color{b.desc->color.r, b.desc->color.g, b.desc->color.b};
    const LineStyle line{o.antialias, o.line_width};
    auto flush = [&]() {
        if (count >= 2) draw_polyline(c, s.points.data(), static_cast<int>(count), false, color, line);
        if (count == 1) draw_line(c, s.points[0], s.points[0], color, line);
        count = 0;
    };
    auto add = [&](geo::Polar<T> p) {
        const geo::Projected<T> pr = geo::project(world.K, p.r, o.projection);
        if (!pr.visible) return flush();
        s.points[count++] = to_pixels(geo::to_screen(pr.rho, p.theta, m.cx, m.cy, m.scale));
    };
    if (edges == 0) {
        add(verts[0]);
        flush();
        return;
    }
    for (std::size_t e = 0; e < edges; ++e)
        W::engine::edge_points(world.K, verts[e], verts[(e + 1) % n], level, [&](int k, geo::Polar<T> p) {
            if (k == 0 && e > 0) return;  // shared with the previous edge
            add(p);
        });
    flush();
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

}  // namespace noneuclid::render
