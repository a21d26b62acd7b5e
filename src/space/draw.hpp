// The three-dimensional world's edges drawn (docs/space.md): each piece of an edge
// (space/edges.hpp) a line of the CPU rasteriser in the edge's colour dimmed by its depth, nearer
// brighter: full at `near` and nearer (the eye; the map's nearest side), 30% at `reach` and
// beyond. Allocates nothing.
#pragma once

#include <algorithm>

#include "render/backdrop.hpp"
#include "render/raster.hpp"
#include "space/edges.hpp"

namespace noneuclid::space {

struct EdgeStyle {
    render::Rgb color{220, 225, 235};
    double near = 0;                        // the depth drawn brightest
    double reach = 3.14159265358979323846;  // the depth drawn dimmest
    render::LineStyle line{};
    render::LimitCircle circle{};  // the circle the view shows through, px (radius 0: none)
};

// The part [t0, t1] of the segment a-b inside the circle o; false if none.
inline bool inside_circle(const Seen& a, const Seen& b, const render::LimitCircle& o, double& t0, double& t1) {
    const double dx = b.x - a.x, dy = b.y - a.y, ex = a.x - o.cx, ey = a.y - o.cy;
    const double A = dx * dx + dy * dy, B = ex * dx + ey * dy, C = ex * ex + ey * ey - o.r * o.r;
    t0 = 0, t1 = 1;
    if (A <= 0) return C <= 0;
    const double d = B * B - A * C;  // (|a + t (b - a) - c|^2 = r^2: A t^2 + 2 B t + C = 0)
    if (d <= 0) return false;
    const double root = std::sqrt(d);
    t0 = std::max(0.0, (-B - root) / A), t1 = std::min(1.0, (-B + root) / A);
    return t0 < t1;
}

// `c` at the brightness of `depth`.
inline render::Rgb dimmed(render::Rgb c, double depth, double near, double reach) {
    const double b = 1 - 0.7 * std::clamp(reach > near ? (depth - near) / (reach - near) : 0.0, 0.0, 1.0);
    auto f = [b](uint8_t v) { return static_cast<uint8_t>(v * b + 0.5); };
    return {f(c.r), f(c.g), f(c.b)};
}

// Each piece a line, dimmed by its depth, cut to the style's circle.
template <class Pieces>
void draw_pieces(const render::Canvas& c, const EdgeStyle& s, Pieces&& pieces) {
    pieces([&](const Seen& a, const Seen& b) {
        double t0 = 0, t1 = 1;
        if (s.circle.r > 0 && !inside_circle(a, b, s.circle, t0, t1)) return;
        const auto at = [&](double t) { return geo::to_sub(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)); };
        render::draw_line(c, at(t0), at(t1), dimmed(s.color, (a.depth + b.depth) / 2, s.near, s.reach), s.line, true,
                          render::held_rows(c));
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
