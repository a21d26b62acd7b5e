// A geodesic edge of the three-dimensional world cut into pieces for the screen (docs/space.md),
// in either view, as the 2D engine cuts its edges: each piece within 0.35 px of the edge's true
// image, and short enough in depth that one brightness serves it (nearer is brighter).
//
// In the inhabitant's view an edge's image is straight: the eye and the edge lie in one totally
// geodesic plane, and the directions from the eye into that plane fill one plane of directions,
// which the perspective maps to a line. It is still cut: for its depth, and where it passes
// behind the eye (a piece whose points are not all in front is halved until what is left is at
// most 1/65536 of the edge, then left out: its image there lies far off the screen). In the map
// the edge's image is a curve (the 3D azimuthal equidistant view bends geodesics as the 2D one
// does), cut until flat; the map shows what lies within the limit sphere.
#pragma once

#include <cmath>

#include "space/view.hpp"

namespace noneuclid::space {

// A point on the screen, px: x right, y down; its depth (world units, or the map camera's
// distance) and whether it is shown at all.
struct Seen {
    double x = 0, y = 0, depth = 0;
    bool shown = false;
};

// The screen's centre and focal length in px: a direction (x, y, 1) in the eye's frame is
// drawn at (cx + focal x, cy - focal y).
struct Lens {
    double cx = 0, cy = 0, focal = 1;
};

// The least cosine between a shown direction and the eye's forward: nearer the eye's side, a
// point's image lies 50 focal lengths out, far off any screen.
inline constexpr double kNearCosine = 0.02;

// The inhabitant's view: q where the eye at `eye`, facing `frame`, sees it directly, or (around)
// the other way round S³.
template <class T>
struct InhabitantView {
    T K{};
    Point<T> eye;
    Frame<T> frame;
    Lens lens;
    bool around = false;

    Seen operator()(const Point<T>& q) const {
        const Sight<T> s = around ? sight_around(K, eye, frame, q) : sight(K, eye, frame, q);
        Seen out;
        const double x = static_cast<double>(s.x), y = static_cast<double>(s.y);
        // (The direction is a unit vector: its forward part is 1 / sqrt(1 + x^2 + y^2).)
        out.shown = s.front && 1 + x * x + y * y <= 1 / (kNearCosine * kNearCosine);
        out.x = lens.cx + lens.focal * x, out.y = lens.cy - lens.focal * y, out.depth = static_cast<double>(s.depth);
        return out;
    }
};

// The map: the ball of radius `limit` (the 3D azimuthal equidistant view, map_position) seen by a
// camera outside it at `camera`, facing `frame`. Points past the limit sphere are not shown.
template <class T>
struct MapView {
    T limit{};
    V3<double> camera;
    Frame<double> frame;
    Lens lens;

    Seen operator()(const Point<T>& q) const {
        Seen out;
        const V3<T> m = map_position(q);
        const V3<double> v = V3<double>{static_cast<double>(m.x), static_cast<double>(m.y), static_cast<double>(m.z)} - camera;
        const double z = dot(v, frame.forward);
        out.shown = q.r <= limit && z > 0;
        if (!out.shown) return out;
        out.x = lens.cx + lens.focal * dot(v, frame.right) / z, out.y = lens.cy - lens.focal * dot(v, frame.up) / z;
        out.depth = norm(v);
        return out;
    }
};

// A camera orbiting the map's ball: at `distance` from its centre, `yaw` radians about the up
// axis (z, as a Frame's default up) from the +x side, `pitch` above the equator, facing the
// centre, upright.
inline MapView<double> orbit_camera(double limit, double distance, double yaw, double pitch, Lens lens) {
    MapView<double> v;
    v.limit = limit, v.lens = lens;
    v.camera = distance * V3<double>{std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)};
    v.frame.forward = -1.0 * unit(v.camera);
    v.frame.right = unit(cross(v.frame.forward, V3<double>{0, 0, 1}), V3<double>{0, -1, 0});
    v.frame.up = cross(v.frame.right, v.frame.forward);
    return v;
}

namespace detail {

// The distance of m from the segment a-b, px.
inline double off_chord(const Seen& a, const Seen& b, const Seen& m) {
    const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((m.x - a.x) * dx + (m.y - a.y) * dy) / l2 : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    return std::hypot(m.x - (a.x + t * dx), m.y - (a.y + t * dy));
}

inline constexpr double kTolerancePx = 0.35;  // as the 2D engine's chords (geo::kChordTolerance)
inline constexpr int kFlatLevels = 12, kClipLevels = 16;

// Halves [t0, t1] of the geodesic from p along v (length `length`) until each piece is flat.
template <class T, class View, class Piece>
void refine(const View& see, T K, const Point<T>& p, const V3<T>& v, T length, double t0, const Seen& a, double t1,
            const Seen& b, int level, double depth_step, Piece& piece) {
    const double tm = (t0 + t1) / 2;
    const Seen m = see(walk(K, p, v, T(tm) * length).end);
    if (a.shown && b.shown && m.shown) {
        const bool flat = off_chord(a, b, m) <= kTolerancePx && std::fabs(b.depth - a.depth) <= depth_step;
        if (flat || level >= kFlatLevels) return piece(a, b);
    } else if (level >= kClipLevels || (!a.shown && !b.shown && !m.shown && level >= 4)) {
        return;  // behind the eye, past the limit: left out
    }
    refine(see, K, p, v, length, t0, a, tm, m, level + 1, depth_step, piece);
    refine(see, K, p, v, length, tm, m, t1, b, level + 1, depth_step, piece);
}

}  // namespace detail

// Calls piece(a, b) (two Seen, both shown) for each piece of the geodesic from p to q, walked
// at curvature K, in the view `see` (InhabitantView, MapView), depth varying at most depth_step
// along a piece.
template <class T, class View, class Piece>
void edge_pieces(const View& see, T K, const Point<T>& p, const Point<T>& q, double depth_step, Piece&& piece) {
    const T length = distance(K, p, q);
    if (!(length > T(0))) return;
    const V3<T> v = bearing(K, p, q);
    constexpr int kStart = 4;  // (a first cut: a long edge's midpoint alone could look flat)
    Seen prev = see(p);
    for (int i = 1; i <= kStart; ++i) {
        const double t = static_cast<double>(i) / kStart;
        const Seen next = see(i == kStart ? q : walk(K, p, v, T(t) * length).end);
        detail::refine(see, K, p, v, length, t - 1.0 / kStart, prev, t, next, 1, depth_step, piece);
        prev = next;
    }
}

}  // namespace noneuclid::space
