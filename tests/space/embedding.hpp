// The tests' own model of the 3D world, in long double (tests/space): the 4-vector embedding
// p = (C_K(r), S_K(r) u) with <p, q> = w w' + K x.x' (S³ in R⁴ at K > 0, the hyperboloid in
// R^{3,1} at K < 0, each scaled by K), tangent vectors measured by g(a, b) = a_w b_w / K + a_x.b_x,
// geodesics p(t) = C_K(t) P + S_K(t) V. It uses std::cos, std::sin, std::cosh, std::sinh,
// std::acos and std::acosh directly: none of the engine's K-continuous forms.
#pragma once

#include <algorithm>
#include <cmath>

#include "space/model.hpp"

namespace noneuclid::space_embedding {

using LD = long double;
using space::Point;
using space::V3;

inline LD S(LD K, LD t) {
    return K > 0 ? std::sin(std::sqrt(K) * t) / std::sqrt(K) : K < 0 ? std::sinh(std::sqrt(-K) * t) / std::sqrt(-K) : t;
}
inline LD C(LD K, LD t) { return K > 0 ? std::cos(std::sqrt(K) * t) : K < 0 ? std::cosh(std::sqrt(-K) * t) : 1; }

struct R4 {
    LD w, x, y, z;
};
inline R4 operator+(R4 a, R4 b) { return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z}; }
inline R4 operator-(R4 a, R4 b) { return {a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z}; }
inline R4 operator*(LD s, R4 a) { return {s * a.w, s * a.x, s * a.y, s * a.z}; }
inline LD form(LD K, R4 a, R4 b) { return a.w * b.w + K * (a.x * b.x + a.y * b.y + a.z * b.z); }  // points
inline LD g(LD K, R4 a, R4 b) { return a.w * b.w / K + a.x * b.x + a.y * b.y + a.z * b.z; }     // tangents (K != 0)

// (u normalised in long double: the double's last bit off the sphere of directions would move
// the point off the quadric by as much, which short distances feel.)
inline R4 embed(LD K, const Point<double>& p) {
    const LD n = std::sqrt(static_cast<LD>(p.u.x) * p.u.x + static_cast<LD>(p.u.y) * p.u.y + static_cast<LD>(p.u.z) * p.u.z);
    const LD s = S(K, p.r) / n;
    return {C(K, p.r), s * p.u.x, s * p.u.y, s * p.u.z};
}
// The distance between two embedded points (K != 0), from the form: acos or acosh of <P, Q>.
inline LD ref_distance(LD K, R4 P, R4 Q) {
    const LD c = form(K, P, Q);
    return K > 0 ? std::acos(std::clamp(c, -1.0L, 1.0L)) / std::sqrt(K) : std::acosh(std::fmax(c, 1.0L)) / std::sqrt(-K);
}
// The same distance from the chord P - Q, well conditioned however near the points are (K != 0):
// K g(D, D) = <D, D> = 2 - 2 C_K(d) = 4 S_K(d / 2)^2 K.
inline LD near_distance(LD K, R4 P, R4 Q) {
    const R4 D = P - Q;
    const LD g2 = D.w * D.w / K + D.x * D.x + D.y * D.y + D.z * D.z;
    return K > 0 ? 2 * std::asin(std::fmin(std::sqrt(std::fmax(K * g2, 0.0L)) / 2, 1.0L)) / std::sqrt(K)
                 : 2 * std::asinh(std::sqrt(std::fmax(-K * g2, 0.0L)) / 2) / std::sqrt(-K);
}
// The carried vector v at p as a tangent of the embedding: its radial part along the radial
// geodesic's tangent (-K S, C u), the rest as it is.
inline R4 tangent(LD K, const Point<double>& p, V3<double> v) {
    const LD a = v.x * p.u.x + v.y * p.u.y + v.z * p.u.z;
    const R4 radial{-K * S(K, p.r), C(K, p.r) * p.u.x, C(K, p.r) * p.u.y, C(K, p.r) * p.u.z};
    return a * radial + R4{0, v.x - a * p.u.x, v.y - a * p.u.y, v.z - a * p.u.z};
}
// A tangent F at the embedded point Q back to a carried vector (the inverse of `tangent`).
inline V3<LD> carried(LD K, R4 Q, R4 F) {
    const LD s = std::sqrt(Q.x * Q.x + Q.y * Q.y + Q.z * Q.z), c = Q.w;
    const LD ux = Q.x / s, uy = Q.y / s, uz = Q.z / s;
    const R4 radial{-K * s, c * ux, c * uy, c * uz};
    const LD a = g(K, F, radial);
    return {a * ux + (F.x - a * c * ux), a * uy + (F.y - a * c * uy), a * uz + (F.z - a * c * uz)};
}
inline LD gap(V3<LD> a, V3<double> b) { return std::hypot(a.x - b.x, std::hypot(a.y - b.y, a.z - b.z)); }

}  // namespace noneuclid::space_embedding
