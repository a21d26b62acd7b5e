// What the three-dimensional world looks like (docs/space.md).
//
// The inhabitant's view: light travels along geodesics, so a point is seen in the direction in
// which the geodesic from the eye to it leaves the eye (space::bearing), at the perspective image
// of that direction in the eye's frame. In S³ the same point is also seen the other way, along
// the rest of the great circle through the antipode (its distance 2 pi / sqrt K - d); in H³ a far
// body's angular size falls as e^-d.
//
// The map: the 3D analogue of the paper's azimuthal equidistant view, a point at distance r in
// direction u drawn at r u in a Euclidean ball of radius the limit distance, which an orbiting
// camera looks at from outside.
#pragma once

#include "space/motion.hpp"

namespace noneuclid::space {

// A point's image seen from an eye: where on the screen (x right, y up, in units of the focal
// length: multiply by it and add the centre), how far along its ray (brightness: nearer is
// brighter) and whether it is in front of the eye at all (behind: not drawn).
template <class T>
struct Sight {
    T x{}, y{};
    T depth{};     // the distance light travels from it to the eye
    bool front = false;
};

// The perspective image of a carried direction d in the eye's frame, with `depth`.
template <class T>
Sight<T> perspective(const Frame<T>& eye, V3<T> d, T depth) {
    const T z = dot(d, eye.forward);
    Sight<T> s;
    s.depth = depth, s.front = z > T(0);
    if (s.front) s.x = dot(d, eye.right) / z, s.y = dot(d, eye.up) / z;
    return s;
}

// The point q seen from the eye at p directly: along the geodesic from p to q.
template <class T>
Sight<T> sight(T K, const Point<T>& p, const Frame<T>& eye, const Point<T>& q) {
    return perspective(eye, bearing(K, p, q), distance(K, p, q));
}

// In S³ (K > 0), q seen the other way round: from the opposite direction, light having come
// through q's antipode and the eye's. None (front false) at K <= 0.
template <class T>
Sight<T> sight_around(T K, const Point<T>& p, const Frame<T>& eye, const Point<T>& q) {
    using std::sqrt;
    if (!(K > T(0))) return {};
    const V3<T> d = bearing(K, p, q);
    return perspective(eye, T(-1) * d, T(2) * geo::pi_v<T> / sqrt(K) - distance(K, p, q));
}

// The map's position of a point: r u, in the units of distance.
template <class T>
V3<T> map_position(const Point<T>& p) {
    return p.r * p.u;
}

}  // namespace noneuclid::space
