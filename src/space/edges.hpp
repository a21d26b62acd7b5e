// A geodesic edge of the three-dimensional world cut into pieces for the screen (docs/space.md),
// in either view: each piece within 0.35 px of the edge's true image, and short enough in depth
// that one brightness serves it (nearer is brighter). The edge is its two ends as 4-vectors
// (space/isometry.hpp); its points are their positive combinations.
//
// In the inhabitant's view an edge's image is straight: in the eye's coordinates a point is
// (C_K(d), S_K(d) times its direction), so the directions of the edge's points are those of the
// flat segment between its ends' spatial parts, which the perspective maps to a line. That
// segment is clipped by the planes through the eye that bound the screen (the screen's size
// beyond it each way): exactly, since each plane's side is linear along it. What passes behind
// the eye is cut off by the same planes. In S³ the view the other way round (light come through
// the antipode) is the same with the spatial parts negated. In the map the edge's image is a
// curve (the 3D azimuthal equidistant view bends geodesics as the 2D one does), halved until
// flat; the map shows what lies within the limit sphere.
#pragma once

#include <cmath>

#include "space/isometry.hpp"
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

// The inhabitant's view: what the eye at `eye`, facing `frame`, sees directly, or (around) the
// other way round S³.
template <class T>
struct InhabitantView {
    T K{};
    Point<T> eye;
    Frame<T> frame;
    Lens lens;
    bool around = false;
};

// An InhabitantView made ready to draw: the world's coordinates to the eye's (its trigonometry
// done once), and the screen's bounds as slopes from the forward axis.
template <class T>
struct EyeCamera {
    T K{};
    Iso<T> to_eye;
    Lens lens;
    bool around = false;
    double box_x = 1, box_y = 1;  // |right / forward| and |up / forward| shown
    double antipode = 0;          // 2 pi / sqrt K: the way round S³
};
template <class T>
EyeCamera<T> camera_of(const InhabitantView<T>& v) {
    EyeCamera<T> e;
    e.K = v.K, e.to_eye = eye_coordinates(v.K, v.eye, v.frame), e.lens = v.lens, e.around = v.around;
    e.box_x = 2 * v.lens.cx / v.lens.focal, e.box_y = 2 * v.lens.cy / v.lens.focal;
    const double K = static_cast<double>(v.K);
    e.antipode = K > 0 ? 2 * 3.14159265358979323846 / std::sqrt(K) : 0;
    return e;
}

// The map: the ball of radius `limit` (the 3D azimuthal equidistant view, map_position) seen by a
// camera outside it at `camera`, facing `frame`. Points past the limit sphere are not shown.
template <class T>
struct MapView {
    T limit{};
    V3<double> camera;
    Frame<double> frame;
    Lens lens;

    // The point at distance r from O in the direction u.
    Seen operator()(T r, V3<T> u) const {
        Seen out;
        const V3<T> m = r * u;
        const V3<double> v = V3<double>{static_cast<double>(m.x), static_cast<double>(m.y), static_cast<double>(m.z)} - camera;
        const double z = dot(v, frame.forward);
        out.shown = r <= limit && z > 0;
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
inline constexpr int kFlatLevels = 12, kClipLevels = 16, kDepthLevels = 6;

// The point (1 - t) p + t q of an edge, on the screen of `e` (p, q in the eye's coordinates).
template <class T>
Seen seen_by_eye(const EyeCamera<T>& e, const V4<T>& p, const V4<T>& q, double t) {
    const V4<T> y = T(1 - t) * p + T(t) * q;
    const double f = static_cast<double>(y.x), r = static_cast<double>(y.y), u = static_cast<double>(y.z);
    const double sign = e.around ? -1 : 1, to_screen = e.lens.focal / (sign * f);
    Seen s;
    s.shown = sign * f > 0;
    s.x = e.lens.cx + to_screen * sign * r, s.y = e.lens.cy - to_screen * sign * u;
    const double d = static_cast<double>(distance_of(e.K, y));
    s.depth = e.around ? e.antipode - d : d;
    return s;
}

// The piece [t0, t1] of the edge, halved until its depth varies by at most depth_step.
template <class T, class Piece>
void depth_pieces(const EyeCamera<T>& e, const V4<T>& p, const V4<T>& q, double t0, const Seen& a, double t1,
                  const Seen& b, int level, double depth_step, Piece& piece) {
    const double tm = (t0 + t1) / 2;
    const Seen m = seen_by_eye(e, p, q, tm);
    const bool even = std::fabs(b.depth - a.depth) <= depth_step && std::fabs(m.depth - (a.depth + b.depth) / 2) <= depth_step;
    if (even || level >= kDepthLevels) return piece(a, b);
    depth_pieces(e, p, q, t0, a, tm, m, level + 1, depth_step, piece);
    depth_pieces(e, p, q, tm, m, t1, b, level + 1, depth_step, piece);
}

// Halves [t0, t1] of the curve `at` (t to a Seen) until each piece is flat.
template <class At, class Piece>
void refine(const At& at, double t0, const Seen& a, double t1, const Seen& b, int level, double depth_step, Piece& piece) {
    const double tm = (t0 + t1) / 2;
    const Seen m = at(tm);
    if (a.shown && b.shown && m.shown) {
        const bool flat = off_chord(a, b, m) <= kTolerancePx && std::fabs(b.depth - a.depth) <= depth_step;
        if (flat || level >= kFlatLevels) return piece(a, b);
    } else if (level >= kClipLevels || (!a.shown && !b.shown && !m.shown && level >= 4)) {
        return;  // past the limit, behind the map's camera: left out
    }
    refine(at, t0, a, tm, m, level + 1, depth_step, piece);
    refine(at, tm, m, t1, b, level + 1, depth_step, piece);
}

}  // namespace detail

// Calls piece(a, b) (two Seen, both shown) for each piece of the geodesic from p to q (4-vectors
// of the world) in the inhabitant's view, depth varying at most depth_step along a piece.
template <class T, class Piece>
void edge_pieces(const EyeCamera<T>& e, const V4<T>& world_p, const V4<T>& world_q, double depth_step, Piece&& piece) {
    const V4<T> p = e.to_eye(world_p), q = e.to_eye(world_q);
    // Each bound is a plane n . X >= 0 through the eye; along the edge n . X is linear in t.
    const double sign = e.around ? -1 : 1;
    const double fp = sign * static_cast<double>(p.x), rp = sign * static_cast<double>(p.y), up = sign * static_cast<double>(p.z);
    const double fq = sign * static_cast<double>(q.x), rq = sign * static_cast<double>(q.y), uq = sign * static_cast<double>(q.z);
    const double at_p[4] = {e.box_x * fp - rp, e.box_x * fp + rp, e.box_y * fp - up, e.box_y * fp + up};
    const double at_q[4] = {e.box_x * fq - rq, e.box_x * fq + rq, e.box_y * fq - uq, e.box_y * fq + uq};
    double t0 = 0, t1 = 1;
    for (int i = 0; i < 4; ++i) {
        if (at_p[i] < 0 && at_q[i] < 0) return;
        const double cut = at_p[i] / (at_p[i] - at_q[i]);  // (where this side's value is 0)
        if (at_p[i] < 0) t0 = cut > t0 ? cut : t0;
        else if (at_q[i] < 0) t1 = cut < t1 ? cut : t1;
    }
    if (!(t0 < t1)) return;
    const Seen a = detail::seen_by_eye(e, p, q, t0), b = detail::seen_by_eye(e, p, q, t1);
    if (!a.shown || !b.shown) return;  // (the edge passes through the eye itself)
    detail::depth_pieces(e, p, q, t0, a, t1, b, 1, depth_step, piece);
}

// The same in the map.
template <class T, class Piece>
void edge_pieces(const MapView<T>& see, T K, const V4<T>& p, const V4<T>& q, double depth_step, Piece&& piece) {
    const auto at = [&](double t) {
        const Polar4<T> y = polar_of(K, T(1 - t) * p + T(t) * q);
        return see(y.r, y.u);
    };
    constexpr int kStart = 4;  // (a first cut: a long edge's midpoint alone could look flat)
    Seen prev = at(0);
    for (int i = 1; i <= kStart; ++i) {
        const double t = static_cast<double>(i) / kStart;
        const Seen next = at(t);
        detail::refine(at, t - 1.0 / kStart, prev, t, next, 1, depth_step, piece);
        prev = next;
    }
}

// Either view, the edge given as two points.
template <class T, class Piece>
void edge_pieces(const InhabitantView<T>& see, T K, const Point<T>& p, const Point<T>& q, double depth_step, Piece&& piece) {
    edge_pieces(camera_of(see), to_v4(K, p), to_v4(K, q), depth_step, piece);
}
template <class T, class Piece>
void edge_pieces(const MapView<T>& see, T K, const Point<T>& p, const Point<T>& q, double depth_step, Piece&& piece) {
    edge_pieces(see, K, to_v4(K, p), to_v4(K, q), depth_step, piece);
}

}  // namespace noneuclid::space
