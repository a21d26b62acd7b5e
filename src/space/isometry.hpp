// The three-dimensional world's motions as 4 x 4 matrices (docs/space.md, "Drawing fast"): in
// the 4-vector model (space/model.hpp) a point is Y = (w, X) = (C_K(r), S_K(r) u), and every
// isometry is linear, for every K including 0 (there a translation moves X by w times a vector).
// So the drawing places a body, and then sees it from the eye, by multiplying 4-vectors: the
// trigonometry is done once a body (its distance from O) and once a frame, not once a point.
//
// A geodesic segment between two points P and Q (not antipodal in S³) is the set of positive
// combinations a P + b Q, scaled back onto the model: the segment is the cut of the model by the
// 2-plane through 0 spanned by P and Q (a great circle of S³, a branch of the hyperboloid's, a
// line of E³ at w = 1). Nothing in a combination needs the edge's length or direction.
#pragma once

#include <cmath>

#include "space/motion.hpp"

namespace noneuclid::space {

template <class T>
V4<T> operator+(V4<T> a, V4<T> b) { return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class T>
V4<T> operator*(T s, V4<T> a) { return {s * a.w, s * a.x, s * a.y, s * a.z}; }
template <class T>
V3<T> spatial(const V4<T>& a) { return {a.x, a.y, a.z}; }

// A linear map of 4-vectors, rows (w, x, y, z).
template <class T>
struct Iso {
    T m[4][4]{{T(1), T(0), T(0), T(0)}, {T(0), T(1), T(0), T(0)}, {T(0), T(0), T(1), T(0)}, {T(0), T(0), T(0), T(1)}};

    V4<T> operator()(const V4<T>& v) const {
        const T* r[4] = {m[0], m[1], m[2], m[3]};
        T o[4];
        for (int i = 0; i < 4; ++i) o[i] = r[i][0] * v.w + r[i][1] * v.x + r[i][2] * v.y + r[i][3] * v.z;
        return {o[0], o[1], o[2], o[3]};
    }
};

// a after b.
template <class T>
Iso<T> operator*(const Iso<T>& a, const Iso<T>& b) {
    Iso<T> o;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) o.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j] + a.m[i][3] * b.m[3][j];
    return o;
}

// The translation along the geodesic from O in the unit direction u by the distance whose S_K
// is s and C_K is c: O goes to (c, s u), a vector at O to the same vector carried there (the
// carried frame is this map's image of the frame at O). In the plane (w, u . X) it turns by
// [[c, -K s], [s, c]] (determinant c^2 + K s^2 = 1); across u nothing moves. (c, -s): back.
template <class T>
Iso<T> translation(T K, V3<T> u, T c, T s) {
    Iso<T> t;
    const T uu[3] = {u.x, u.y, u.z};
    for (int i = 0; i < 3; ++i) {
        t.m[0][i + 1] = T(-1) * K * s * uu[i];
        t.m[i + 1][0] = s * uu[i];
        for (int j = 0; j < 3; ++j) t.m[i + 1][j + 1] = (i == j ? T(1) : T(0)) + (c - T(1)) * uu[i] * uu[j];
    }
    t.m[0][0] = c;
    return t;
}
template <class T>
Iso<T> translation_to(T K, const Point<T>& p) {
    return translation(K, p.u, geo::C_K(K, p.r), geo::S_K(K, p.r));
}

// The rotation taking a body's own coordinates (x forward, y left, z up) to the carried frame f.
template <class T>
Iso<T> frame_rotation(const Frame<T>& f) {
    Iso<T> r;
    const V3<T> cols[3] = {f.forward, T(-1) * f.right, f.up};
    for (int j = 0; j < 3; ++j) r.m[1][j + 1] = cols[j].x, r.m[2][j + 1] = cols[j].y, r.m[3][j + 1] = cols[j].z;
    return r;
}

// A body's placement: its own coordinates about its centre to the world's.
template <class T>
Iso<T> placement(T K, const Point<T>& centre, const Frame<T>& f) {
    return translation_to(K, centre) * frame_rotation(f);
}

// The eye's: the world's coordinates to the eye's own, rows (w, forward, right, up). A point
// then is (C_K(d), S_K(d) times its direction from the eye), d its distance from the eye.
template <class T>
Iso<T> eye_coordinates(T K, const Point<T>& eye, const Frame<T>& f) {
    Iso<T> r;  // (the transpose of frame_rotation, with right for left)
    const V3<T> rows[3] = {f.forward, f.right, f.up};
    for (int i = 0; i < 3; ++i) r.m[i + 1][1] = rows[i].x, r.m[i + 1][2] = rows[i].y, r.m[i + 1][3] = rows[i].z;
    return r * translation(K, eye.u, geo::C_K(K, eye.r), T(-1) * geo::S_K(K, eye.r));
}

// The point at distance `length` from O in the unit direction d of O's frame.
template <class T>
V4<T> out_from_origin(T K, V3<T> d, T length) {
    const T s = geo::S_K(K, length);
    return {geo::C_K(K, length), s * d.x, s * d.y, s * d.z};
}

// A positive combination of points scaled back onto the model, as its distance from the origin
// of its coordinates and its direction from there (any, at the origin). N^2 = w^2 + K |X|^2 is
// positive for every combination of a segment's ends (at K = 0 it is w^2).
template <class T>
struct Polar4 {
    T r{};
    V3<T> u;
    T s{}, c{};  // S_K(r) and C_K(r)
};
// Only its distance (the inhabitant's view's depth: no direction, no division for it).
template <class T>
T distance_of(T K, const V4<T>& y) {
    using std::sqrt;
    const T x2 = y.x * y.x + y.y * y.y + y.z * y.z, n = sqrt(y.w * y.w + K * x2);
    return geo::arc_K(K, sqrt(x2) / n, y.w / n);
}
template <class T>
Polar4<T> polar_of(T K, const V4<T>& y) {
    using std::sqrt;
    const V3<T> X = spatial(y);
    const T x2 = dot(X, X), n = sqrt(y.w * y.w + K * x2), len = sqrt(x2);
    Polar4<T> p;
    p.s = len / n, p.c = y.w / n;
    p.r = geo::arc_K(K, p.s, p.c);
    p.u = len > T(0) ? (T(1) / len) * X : V3<T>{T(1), T(0), T(0)};
    return p;
}

}  // namespace noneuclid::space
