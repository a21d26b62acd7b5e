// The three-dimensional world's edges drawn (docs/space.md): each piece of an edge
// (space/edges.hpp) a line of the CPU rasteriser in the edge's colour dimmed by its depth, nearer
// brighter: full at `near` and nearer (the eye; the map's nearest side), 30% at `reach` and
// beyond. Allocates nothing.
#pragma once

#include <algorithm>

#include "render/raster.hpp"
#include "space/edges.hpp"

namespace noneuclid::space {

struct EdgeStyle {
    render::Rgb color{220, 225, 235};
    double near = 0;                        // the depth drawn brightest
    double reach = 3.14159265358979323846;  // the depth drawn dimmest
    render::LineStyle line{};
};

// `c` at the brightness of `depth`.
inline render::Rgb dimmed(render::Rgb c, double depth, double near, double reach) {
    const double b = 1 - 0.7 * std::clamp(reach > near ? (depth - near) / (reach - near) : 0.0, 0.0, 1.0);
    auto f = [b](uint8_t v) { return static_cast<uint8_t>(v * b + 0.5); };
    return {f(c.r), f(c.g), f(c.b)};
}

// Each piece a line, dimmed by its depth.
template <class Pieces>
void draw_pieces(const render::Canvas& c, const EdgeStyle& s, Pieces&& pieces) {
    pieces([&](const Seen& a, const Seen& b) {
        render::draw_line(c, geo::to_sub(a.x, a.y), geo::to_sub(b.x, b.y), dimmed(s.color, (a.depth + b.depth) / 2, s.near, s.reach),
                          s.line, true, render::held_rows(c));
    });
}
inline double depth_step(const EdgeStyle& s) { return (s.reach - s.near) / 16; }  // (16 brightness steps)

// The geodesic from p to q (4-vectors of the world) in the inhabitant's view or the map.
template <class T>
void draw_edge(const render::Canvas& c, const EyeCamera<T>& see, const V4<T>& p, const V4<T>& q, const EdgeStyle& s) {
    draw_pieces(c, s, [&](auto&& piece) { edge_pieces(see, p, q, depth_step(s), piece); });
}
template <class T>
void draw_edge(const render::Canvas& c, const MapView<T>& see, T K, const V4<T>& p, const V4<T>& q, const EdgeStyle& s) {
    draw_pieces(c, s, [&](auto&& piece) { edge_pieces(see, K, p, q, depth_step(s), piece); });
}
// The same, the edge given as two points.
template <class T, class View>
void draw_edge(const render::Canvas& c, const View& see, T K, const Point<T>& p, const Point<T>& q, const EdgeStyle& s) {
    draw_pieces(c, s, [&](auto&& piece) { edge_pieces(see, K, p, q, depth_step(s), piece); });
}

}  // namespace noneuclid::space
