// The 3-vector model of docs/design.md, for every curvature K including 0: a point is
// p = (C_K(r), S_K(r) cos theta, S_K(r) sin theta) with <p, q> = w1 w2 + K (x1 x2 + y1 y2) =
// C_K(dist). Here: polar points and 3-vectors, the curvature functions S_K, C_K and their
// inverses, the way between polar and 3-vector (to_vec, to_polar), the geodesic distance, and
// the generalised slerp's point. Written without 1/sqrt|K| and without acos, templated on the
// scalar (geometry/scalar.hpp).
#pragma once

#include <cmath>
#include <cstddef>

#include "geometry/scalar.hpp"

namespace noneuclid::geo {

template <class T>
struct Polar {
    T r{}, theta{};
};

// A point (or a tangent vector) of the 3-vector model.
template <class T>
struct Vec3 {
    T w{}, x{}, y{};
};

// ---- S_K, C_K and their inverses --------------------------------------------------------

// S_K(x) = sin(sqrt K x)/sqrt K, x, sinh(sqrt -K x)/sqrt -K for K >, =, < 0: one formula.
template <class T>
T S_K(T K, T x) {
    return mul_Sf(x, K * x * x);
}
template <class T>
T C_K(T K, T x) {
    return Cf(K * x * x);
}
// The inverse of S_K on [0, pi/(2 sqrt K)] (K > 0) or everywhere (K <= 0).
template <class T>
T AS_K(T K, T y) {
    return mul_ASf(y, K * y * y);
}
// The inverse of the tangent T_K = S_K / C_K on the same range.
template <class T>
T AT_K(T K, T t) {
    return mul_ATf(t, K * t * t);
}

// The distance r >= 0 whose S_K is s >= 0 and C_K is c: the polar inverse of the 3-vector model,
// well conditioned everywhere. With t = s / (1 + c) = T_K(r/2) (no cancellation while c >= 0),
// r = 2 AT_K(t). Past the sphere's equator (c < 0, only when K > 0) the point is read from the
// antipode instead: r = pi/sqrt K - 2 AT_K(s / (1 - c)).
// (Written as w ATf(K w^2 / 4) with w = 2 t computed in one division: doubling a rounded t
// would round every radius up by half a step on average in fixed point, a drift that
// accumulates over a moving body's steps.)
template <class T>
T arc_K(T K, T s, T c) {
    using std::sqrt;
    // (quotient and quarter are a / b and x / 4, bit for bit; fx's avoid a 64-bit divide.)
    if (c >= T(0)) {
        const T w = quotient(T(2) * s, T(1) + c);  // 2 T_K(r/2)
        return mul_ATf(w, quarter(K * w * w));
    }
    const T w = quotient(T(2) * s, T(1) - c);
    return pi_v<T> / sqrt(K) - mul_ATf(w, quarter(K * w * w));
}

template <class T>
Vec3<T> to_vec(T K, Polar<T> p) {
    using std::cos, std::sin;
    const T s = S_K(K, p.r);
    return {C_K(K, p.r), s * cos(p.theta), s * sin(p.theta)};
}
// Back to polar; theta = 0 at O.
template <class T>
Polar<T> to_polar(T K, Vec3<T> v) {
    using std::atan2;
    return {arc_K(K, hypot(v.x, v.y), v.w), atan2(v.y, v.x)};
}

// ---- distance ----------------------------------------------------------------------------

// Geodesic distance, haversine form (valid for all K, no cancellation for short distances):
//   S_K(d/2)^2 = S_K((r1 - r2)/2)^2 + S_K(r1) S_K(r2) sin^2((theta1 - theta2)/2)
// taken as S_K(d/2) = hypot(S_K((r1 - r2)/2), sqrt S_K(r1) sqrt S_K(r2) sin(...)), so that no
// small quantity is squared (in Q16.16, the square of 0.01 keeps two significant digits).
// The square root of S_K(r), clamped at 0 (S_K may round to a hair below 0 at the sphere's
// antipode).
template <class T>
T clamped_root(T s) {
    using std::sqrt;
    return sqrt(s > T(0) ? s : T(0));
}
template <class T>
T root_S_K(T K, T r) {
    return clamped_root(S_K(K, r));
}
// The half-angle sine of distance_from: sin((theta1 - theta2)/2), in the scalar's finest form.
template <class T>
using HalfSine = decltype(sine_of_half(T{}));
// distance(K, p, q) from its parts: r1, r2, the roots root_S_K(K, r) of both and
// sine_of_half(theta1 - theta2), which does not depend on K (a body's shape keeps it). The same
// bits as distance.
template <class T>
T distance_from(T K, T r1, T r2, T root1, T root2, HalfSine<T> half_sine) {
    const T a = S_K(K, (r1 - r2) / T(2));
    // sqrt(S_K(r1) S_K(r2)) sin(dtheta/2); only its square matters, so the sign is free.
    const T g = mul_unit(root1 * root2, half_sine);
    return T(2) * AS_K(K, hypot(a, g));
}
template <class T>
T distance(T K, Polar<T> p, Polar<T> q) {
    return distance_from(K, p.r, q.r, root_S_K(K, p.r), root_S_K(K, q.r), sine_of_half(p.theta - q.theta));
}

// The generalised slerp's point a P + b Q on the edge from P to Q, for the weights (a, b)
// (docs/design.md; the weights: geometry/edges.hpp), each coordinate rounded once.
template <class T>
Vec3<T> slerp_point(T a, const Vec3<T>& P, T b, const Vec3<T>& Q) {
    return {dot2(a, P.w, b, Q.w), dot2(a, P.x, b, Q.x), dot2(a, P.y, b, Q.y)};
}

}  // namespace noneuclid::geo
