// Moving through the three-dimensional space (space/model.hpp): a walk along a geodesic, and a
// frame carried along it by parallel transport (a body's orientation, docs/space.md).
//
// The geodesic leaving p in the carried direction v lies in the totally geodesic plane through O
// spanned by u_p and v, so the 2D walk (geometry/walk.hpp) in that plane gives its end and its
// carried direction there. Parallel transport along a geodesic in a totally geodesic plane turns
// every in-plane carried vector by the same angle (the 2D walk's `turn`, 0 in flat space) and
// leaves the plane's normal as it is; so a whole frame is carried by one rotation.
#pragma once

#include "space/model.hpp"

namespace noneuclid::space {

// A right-handed orthonormal frame of carried vectors: where a body faces, its up and its right.
template <class T>
struct Frame {
    V3<T> forward{T(1), T(0), T(0)}, up{T(0), T(0), T(1)}, right{T(0), T(-1), T(0)};
};

// Where a walk ends, the direction of travel there, and the rotation that carries other vectors
// (about the plane's normal n, by `turn`, in the plane (a, b)).
template <class T>
struct Walk {
    Point<T> end;
    V3<T> heading;
    Plane<T> plane;
    T turn{};
};

// From p, distance s along the geodesic leaving p in the carried unit direction v.
template <class T>
Walk<T> walk(T K, const Point<T>& p, V3<T> v, T s) {
    const Plane<T> pl = plane_of(p.u, v);
    const geo::Walk<T> w = geo::walk(K, geo::Polar<T>{p.r, T(0)}, angle_in(pl, v), s);
    return {{w.end.r, at_angle(pl, w.end.theta)}, at_angle(pl, w.heading), pl, w.turn};
}

// A carried vector f at the walk's start, carried to its end: its part in the walk's plane turned
// by the walk's turn, its part across the plane kept.
template <class T>
V3<T> carry(const Walk<T>& w, V3<T> f) {
    using std::cos, std::sin;
    const T fa = dot(f, w.plane.a), fb = dot(f, w.plane.b);
    const V3<T> across = f - fa * w.plane.a - fb * w.plane.b;
    const T c = cos(w.turn), s = sin(w.turn);
    return across + (fa * c - fb * s) * w.plane.a + (fa * s + fb * c) * w.plane.b;
}

// A frame's vectors turned about the unit carried axis by `angle` (a body's spin, right-handed).
template <class T>
V3<T> turned(V3<T> f, V3<T> axis, T angle) {
    using std::cos, std::sin;
    const T c = cos(angle), s = sin(angle);
    return c * f + s * cross(axis, f) + ((T(1) - c) * dot(axis, f)) * axis;
}

// Re-orthonormalised (Gram-Schmidt from forward, then up; right = forward x up), so that
// rounding does not shear a frame carried for hours.
template <class T>
Frame<T> orthonormal(const Frame<T>& f) {
    Frame<T> o;
    o.forward = unit(f.forward);
    o.up = unit(f.up - dot(f.up, o.forward) * o.forward, some_normal(o.forward));
    o.right = cross(o.forward, o.up);
    return o;
}

// A body's position, direction of travel and frame after moving distance s along the travel:
// both carried (the travel stays the geodesic's tangent; the frame keeps its angles to it).
template <class T>
void fly(T K, Point<T>& p, V3<T>& travel, Frame<T>& f, T s) {
    const Walk<T> w = walk(K, p, travel, s);
    p = w.end;
    travel = unit(w.heading, travel);
    f = orthonormal(Frame<T>{carry(w, f.forward), carry(w, f.up), carry(w, f.right)});
}

}  // namespace noneuclid::space
