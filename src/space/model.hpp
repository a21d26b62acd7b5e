// The three-dimensional world's geometry (docs/space.md): a space of constant curvature K in
// [-1, 1] (S³ for K > 0, flat E³ at 0, H³ for K < 0), in the paper's way. A point is its
// distance r from the origin O and its direction u from O (a unit 3-vector: the 2D polar angle's
// one more dimension); a direction at a point is a 3-vector in the carried frame, the tangent
// space at O carried out along the radial geodesic from O, as the 2D engine's headings are. The
// 4-vector model (C_K(r), S_K(r) u) with <p, q> = w1 w2 + K (x1 x2 + y1 y2 + z1 z2) = C_K(d)
// holds for every K including 0 and is the tests' embedding (S³ in R⁴, the hyperboloid in R^{3,1},
// scaled by K).
//
// Every triangle O - P - Q lies in a totally geodesic plane (through O, spanned by u_p and u_q),
// so the 2D engine's laws in their K-continuous forms (geometry/model.hpp, geometry/walk.hpp)
// solve it: distance, bearing and the walk along a geodesic are the 2D ones in that plane.
// Templated on the scalar (geometry/scalar.hpp).
#pragma once

#include <cmath>

#include "geometry/model.hpp"
#include "geometry/walk.hpp"

namespace noneuclid::space {

// A 3-vector: a direction from O, a carried direction at a point, or a map view's position.
template <class T>
struct V3 {
    T x{}, y{}, z{};
};
template <class T>
V3<T> operator+(V3<T> a, V3<T> b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class T>
V3<T> operator-(V3<T> a, V3<T> b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T>
V3<T> operator*(T s, V3<T> a) { return {s * a.x, s * a.y, s * a.z}; }
template <class T>
T dot(V3<T> a, V3<T> b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T>
V3<T> cross(V3<T> a, V3<T> b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
template <class T>
T norm(V3<T> a) {
    using std::sqrt;
    return sqrt(dot(a, a));
}
// a / |a|, or `fallback` when a is 0.
template <class T>
V3<T> unit(V3<T> a, V3<T> fallback = {T(1), T(0), T(0)}) {
    const T n = norm(a);
    return n > T(0) ? (T(1) / n) * a : fallback;
}
// A unit vector at right angles to the unit vector u (any one; the same one for the same u).
template <class T>
V3<T> some_normal(V3<T> u) {
    const T ax = u.x < T(0) ? -u.x : u.x;  // (|u.x| for every scalar: fixed point has no fabs)
    const V3<T> axis = ax < T(0.6) ? V3<T>{T(1), T(0), T(0)} : V3<T>{T(0), T(1), T(0)};
    return unit(axis - dot(axis, u) * u);
}

// A point: its distance from O and its direction from O (a unit vector; any at O).
template <class T>
struct Point {
    T r{};
    V3<T> u{T(1), T(0), T(0)};
};

// A point of the 4-vector model.
template <class T>
struct V4 {
    T w{}, x{}, y{}, z{};
};

template <class T>
V4<T> to_v4(T K, const Point<T>& p) {
    const T s = geo::S_K(K, p.r);
    return {geo::C_K(K, p.r), s * p.u.x, s * p.u.y, s * p.u.z};
}
template <class T>
Point<T> to_point(T K, const V4<T>& v) {
    const V3<T> x{v.x, v.y, v.z};
    const T s = norm(x);
    return {geo::arc_K(K, s, v.w), unit(x)};
}

// The plane of the triangle O - P - Q (or O - P and a direction at P): an orthonormal pair
// (a, b) with a = u_p and b the part of `toward` across it, in which P is the 2D point (r, 0)
// and `toward` has the 2D angle atan2(toward . b, toward . a).
template <class T>
struct Plane {
    V3<T> a, b;
};
template <class T>
Plane<T> plane_of(V3<T> u_p, V3<T> toward) {
    return {u_p, unit(toward - dot(toward, u_p) * u_p, some_normal(u_p))};
}
template <class T>
T angle_in(const Plane<T>& pl, V3<T> v) {
    using std::atan2;
    return atan2(dot(v, pl.b), dot(v, pl.a));
}
template <class T>
V3<T> at_angle(const Plane<T>& pl, T angle) {
    using std::cos, std::sin;
    return cos(angle) * pl.a + sin(angle) * pl.b;
}

// The angle between two unit vectors (atan2 of the sine and cosine: exact near 0 and pi).
template <class T>
T angle_between(V3<T> a, V3<T> b) {
    using std::atan2;
    return atan2(norm(cross(a, b)), dot(a, b));
}

// The geodesic distance: the 2D haversine form in the triangle's plane.
template <class T>
T distance(T K, const Point<T>& p, const Point<T>& q) {
    return geo::distance(K, geo::Polar<T>{p.r, T(0)}, geo::Polar<T>{q.r, angle_between(p.u, q.u)});
}

// The direction (carried frame at p) of the geodesic from p toward q; any when q = p.
template <class T>
V3<T> bearing(T K, const Point<T>& p, const Point<T>& q) {
    const Plane<T> pl = plane_of(p.u, q.u);
    return at_angle(pl, geo::bearing(K, geo::Polar<T>{p.r, T(0)}, geo::Polar<T>{q.r, angle_in(pl, q.u)}));
}

}  // namespace noneuclid::space
