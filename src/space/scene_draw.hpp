// The three-dimensional world drawn (docs/space.md), in its two views:
//  - the inhabitant's: what the ship's eye sees, 90 degrees across the disc (the layout's, as the
//    2D world's; outside it shaded), the other bodies and the grid (in S³ each seen both ways round);
//  - the map: the ball of the 3D azimuthal equidistant view, its limit sphere's outline, every
//    body and the ship, seen by a camera that orbits it once a minute.
// The grid is the 3D form of the paper's grid lines: three families of geodesics, each through
// the points of a square lattice (0.6 apart) on the plane of the other two axes, leaving them
// along its own axis's carried direction, 2.4 each way. Each edge a geodesic (space/draw.hpp),
// nearer brighter. Allocates nothing.
#pragma once

#include <array>
#include <cmath>

#include "render/backdrop.hpp"
#include "render/draw_options.hpp"
#include "space/draw.hpp"
#include "space/scene_world.hpp"

namespace noneuclid::space {

inline constexpr double kGridStep = 0.6, kGridReach = 2.4;
inline constexpr int kGridHalf = 2;  // lattice points -2..2 each way

// The map's camera at world time t: 2.6 limits out, 20 degrees up, a turn a minute; the ball
// 80% of the disc (`side`) across.
template <class T = double>
MapView<T> map_camera(double limit, int width, int height, double side, double t) {
    const double d = 2.6 * limit;
    const double tan_radius = 1 / std::sqrt(d * d / (limit * limit) - 1);  // tan of the ball's angular radius
    const Lens lens{width / 2.0, height / 2.0, 0.4 * side / tan_radius};
    const MapView<double> o = orbit_camera(limit, d, 2 * 3.14159265358979323846 * t / 60, 0.35, lens);
    return {T(limit), o.camera, o.frame, o.lens};
}

// The grid's edges: three families of geodesics through a square lattice. Family a's line
// through lattice point (i, j) starts at O, goes i steps along axis b, j along the carried axis c,
// then 2.4 each way along the carried axis a; composing the three translations (space/
// isometry.hpp) in closed form, with C_n, S_n the curvature's cosine and sine of n steps and
// C_L, S_L of the reach: the point is (C_i C_j, a: 0, b: S_i C_j, c: S_j) and the line's ends
// (C_i C_j C_L, a: +-S_L, b: S_i C_j C_L, c: S_j C_L).
template <class T, class Edge>
void grid_edges(T K, render::Rgb grid, Edge&& edge) {
    T C[kGridHalf + 1], S[kGridHalf + 1];
    for (int n = 0; n <= kGridHalf; ++n) C[n] = geo::C_K(K, T(kGridStep * n)), S[n] = geo::S_K(K, T(kGridStep * n));
    const T CL = geo::C_K(K, T(kGridReach)), SL = geo::S_K(K, T(kGridReach));
    const auto at = [](int a, T w, T xa, T xb, T xc) {
        T X[3];
        X[a] = xa, X[(a + 1) % 3] = xb, X[(a + 2) % 3] = xc;
        return V4<T>{w, X[0], X[1], X[2]};
    };
    for (int a = 0; a < 3; ++a)
        for (int i = -kGridHalf; i <= kGridHalf; ++i)
            for (int j = -kGridHalf; j <= kGridHalf; ++j) {
                const T ci = C[i < 0 ? -i : i], si = i < 0 ? T(-1) * S[-i] : S[i];
                const T cj = C[j < 0 ? -j : j], sj = j < 0 ? T(-1) * S[-j] : S[j];
                const V4<T> p = at(a, ci * cj, T(0), si * cj, sj);
                edge(p, at(a, ci * cj * CL, SL, si * cj * CL, sj * CL), grid);
                edge(p, at(a, ci * cj * CL, T(-1) * SL, si * cj * CL, sj * CL), grid);
            }
}

// The vertices of a solid of circumradius `size` placed by `to_world` (a body's or a cell's).
template <class T>
struct PlacedSolid {
    const Solid& s;
    Iso<T> to_world;
    T c{}, sn{}, size{}, K{};  // C_K and S_K of the size, for a solid of one length
    PlacedSolid(const Solid& solid, T k, const Point<T>& centre, const Frame<T>& f, T sz)
        : s(solid), to_world(placement(k, centre, f)), c(geo::C_K(k, sz)), sn(geo::S_K(k, sz)), size(sz), K(k) {}
    V4<T> vertex(int i) const {
        const double* v = s.vertices[i];
        const V3<T> d{T(v[0]), T(v[1]), T(v[2])};
        if (s.lengths) return to_world(out_from_origin(K, d, size * T(s.lengths[i])));
        return to_world(V4<T>{c, sn * d.x, sn * d.y, sn * d.z});
    }
};
// (Each vertex placed once, not once for each of its edges; a solid has at most 256: its edges'
// indices are bytes.)
template <class T, class Edge>
void solid_edges(const PlacedSolid<T>& p, render::Rgb rgb, Edge& edge) {
    V4<T> at[256];
    const int n = p.s.vertex_count < 256 ? p.s.vertex_count : 256;
    for (int i = 0; i < n; ++i) at[i] = p.vertex(i);
    for (int e = 0; e < p.s.edge_count; ++e) edge(at[p.s.edges[e][0]], at[p.s.edges[e][1]], rgb);
}

// Each body's edges (but the ship's when `ship` is false).
template <class T, class Edge>
void bodies_edges(const SceneWorldOf<T>& w, bool ship, Edge&& edge) {
    for (const Body<T>& body : w.bodies) {
        if (body.ship && !ship) continue;
        const render::Rgb rgb{body.color[0], body.color[1], body.color[2]};
        solid_edges(PlacedSolid<T>(w.solid(body), w.K, body.at, body.frame, body.size), rgb, edge);
    }
}

// Calls edge(p, q, rgb) for every edge of the world (p, q 4-vectors of the world: space/
// isometry.hpp): the grid's or the honeycomb's, then each body's (but the ship's when `ship` is
// false).
template <class T, class Edge>
void world_edges(SceneWorldOf<T>& w, bool ship, Edge&& edge) {
    const T K = w.K;
    const render::Rgb grid{70, 90, 120};
    if (w.honeycomb_as_set().kind) {
        const Honeycomb& h = w.honeycomb();
        const render::Rgb cube{150, 170, 230};
        for (int c = 0; c < h.count(); ++c) {
            Body<double> d;
            d.size = h.shape.circumradius, d.at = h.cell(c).centre, d.frame = h.cell(c).frame;
            const Body<T> cell = body_in<T>(d);
            solid_edges(PlacedSolid<T>(kSolids[1], K, cell.at, cell.frame, cell.size), cube, edge);
        }
    } else
        grid_edges(K, grid, edge);
    bodies_edges(w, ship, edge);
}

// The circle both views show through (the 2D disc's: the layout's, render/layout.hpp), its
// outside shaded and its rim drawn as the 2D limit circle is, over what was drawn.
inline void porthole(const render::Canvas& c, double r, const render::DrawOptions& o, const render::LineStyle& line) {
    if (o.shade_outside) render::shade_outside_circle(c, c.width() / 2.0, c.height() / 2.0, r, o.outside);
    if (!o.rim_line) return;
    std::array<geo::SubPoint, 97> rim;
    for (std::size_t i = 0; i < rim.size(); ++i) {
        const double a = 2 * 3.14159265358979323846 * static_cast<double>(i) / 96;
        rim[i] = geo::to_sub(c.width() / 2.0 + r * std::cos(a), c.height() / 2.0 + r * std::sin(a));
    }
    render::draw_polyline(c, rim.data(), 97, false, o.rim, line, render::held_rows(c));
}

// The world in the inhabitant's view (map false) or the map, within the disc of o.disc (0: the
// smaller side): over the backdrop (render/backdrop.hpp: the background inside the circle, the
// outside shaded, the rim; its rows kept in `kept` when given) with each line cut to the circle,
// or over what the canvas holds, shaded outside the circle afterwards.
template <class T>
void draw_space(const render::Canvas& c, SceneWorldOf<T>& w, const render::DrawOptions& o, bool map, bool backdrop,
                render::BackdropRows* kept = nullptr) {
    EdgeStyle style;
    style.line.antialias = o.antialias, style.line.width = o.line_width;
    const double limit = static_cast<double>(w.limit()), K = static_cast<double>(w.K);
    const double side = o.disc > 0 ? o.disc : (c.width() < c.height() ? c.width() : c.height());
    MapView<T> view;
    InhabitantView<T> eye;
    if (map) {
        view = map_camera<T>(limit, c.width(), c.height(), side, w.time);
        const double d = norm(view.camera);
        style.near = d - limit, style.reach = d + limit;
        style.circle.r = view.lens.focal / std::sqrt(d * d / (limit * limit) - 1);  // (the ball's outline)
    } else {
        const Body<T>& ship = w.bodies.front();
        eye.K = w.K, eye.eye = ship.at, eye.frame = ship.frame;
        eye.lens = {c.width() / 2.0, c.height() / 2.0, side / 2.0};  // (90 degrees across the disc)
        style.near = 0, style.reach = K > 0 ? 2 * 3.14159265358979323846 / std::sqrt(K) : 2 * limit;
        style.circle.r = side / 2;
    }
    style.circle.cx = c.width() / 2.0, style.circle.cy = c.height() / 2.0;
    const render::LimitCircle& circle = style.circle;
    if (backdrop) render::draw_backdrop_rows(c, circle, o, c.top(), c.bottom(), kept ? kept->rows(c, circle, o) : nullptr);
    if (map) {
        world_edges(w, true, [&](const V4<T>& p, const V4<T>& q, render::Rgb rgb) {
            style.color = rgb;
            draw_edge(c, view, w.K, p, q, style);
        });
    } else {
        const EyeCamera<T> direct = camera_of(eye);
        EyeCamera<T> around = direct;
        around.around = true;
        world_edges(w, false, [&](const V4<T>& p, const V4<T>& q, render::Rgb rgb) {
            style.color = rgb;
            draw_edge(c, direct, p, q, style);
            if (K > 0) draw_edge(c, around, p, q, style);
        });
    }
    if (!backdrop) porthole(c, circle.r, o, style.line);
}

}  // namespace noneuclid::space
