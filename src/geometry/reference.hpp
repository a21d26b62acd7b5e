// The reference model: the 3-vector model of docs/design.md as 3x3 matrices (GLM, double),
// built from std:: functions with the textbook branch for each sign of K. Independent of
// geometry.hpp (no Sf/Cf series, no haversine, no slerp): it is what the tests and the
// accuracy report measure the engines against.
//
// A point is p = (w, x, y) = (C_K(r), S_K(r) cos theta, S_K(r) sin theta). Matrices act on
// column vectors (w, x, y); translation by d along +x and rotation by a are
//     Tr(d) = [[C_K(d), -K S_K(d), 0], [S_K(d), C_K(d), 0], [0, 0, 1]],   Rot(a) = xy rotation.
// The frame carried from O along the ray at angle theta to distance r is
//     F(r, theta) = Rot(theta) Tr(r) Rot(-theta).
#pragma once

#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "geometry/geometry.hpp"

namespace noneuclid::geo::ref {

inline double S(double K, double x) {
    if (K > 0) return std::sin(std::sqrt(K) * x) / std::sqrt(K);
    if (K < 0) return std::sinh(std::sqrt(-K) * x) / std::sqrt(-K);
    return x;
}
inline double C(double K, double x) {
    if (K > 0) return std::cos(std::sqrt(K) * x);
    if (K < 0) return std::cosh(std::sqrt(-K) * x);
    return 1;
}

// GLM is column-major: m[column][row]. Built from rows for readability.
inline glm::dmat3 rows(double a, double b, double c, double d, double e, double f, double g,
                       double h, double i) {
    return glm::dmat3(a, d, g, b, e, h, c, f, i);
}
inline glm::dmat3 Tr(double K, double d) {
    const double s = S(K, d), c = C(K, d);
    return rows(c, -K * s, 0, s, c, 0, 0, 0, 1);
}
inline glm::dmat3 Rot(double a) {
    const double c = std::cos(a), s = std::sin(a);
    return rows(1, 0, 0, 0, c, -s, 0, s, c);
}
inline glm::dmat3 frame(double K, Polar<double> p) {
    return Rot(p.theta) * Tr(K, p.r) * Rot(-p.theta);
}
inline glm::dmat3 frame_inverse(double K, Polar<double> p) {
    return Rot(p.theta) * Tr(K, -p.r) * Rot(-p.theta);
}
inline glm::dvec3 point(double K, Polar<double> p) { return frame(K, p) * glm::dvec3(1, 0, 0); }

// Polar reading of a model point, from its two well-conditioned parts.
inline Polar<double> polar(double K, glm::dvec3 v) {
    const double s = std::hypot(v.y, v.z), w = v.x;
    double r;
    if (K > 0)
        r = std::atan2(std::sqrt(K) * s, w) / std::sqrt(K);
    else if (K < 0)
        r = std::asinh(std::sqrt(-K) * s) / std::sqrt(-K);
    else
        r = s;
    return {r, s == 0 ? 0.0 : std::atan2(v.z, v.y)};
}

inline double distance(double K, Polar<double> p, Polar<double> q) {
    return polar(K, frame_inverse(K, p) * point(K, q)).r;
}
// Direction from p toward q in p's carried frame.
inline double bearing(double K, Polar<double> p, Polar<double> q) {
    const glm::dvec3 v = frame_inverse(K, p) * point(K, q);
    return std::atan2(v.z, v.y);
}

inline Polar<double> vertex(double K, Polar<double> centre, double facing, Polar<double> local) {
    return polar(K, frame(K, centre) * Rot(facing + local.theta) * Tr(K, local.r) *
                        glm::dvec3(1, 0, 0));
}

// Moving: the frame transported along the geodesic, compared with the carried-from-O frame at
// the new centre; the rotation between them turns travel and facing alike.
inline Pose<double> move(double K, Pose<double> pose, double d) {
    const glm::dmat3 moved =
        frame(K, pose.centre) * Rot(pose.travel) * Tr(K, d) * Rot(-pose.travel);
    const Polar<double> c = polar(K, moved * glm::dvec3(1, 0, 0));
    const glm::dmat3 rel = frame_inverse(K, c) * moved;  // a rotation about the point
    const double omega = std::atan2(rel[1][2], rel[1][1]);  // column x, rows y and x
    return {c, pose.travel + omega, pose.facing + omega};
}

// The point at fraction t of the way from p to q along the geodesic.
inline Polar<double> along(double K, Polar<double> p, Polar<double> q, double t) {
    const glm::dvec3 v = frame_inverse(K, p) * point(K, q);
    const double d = polar(K, v).r, dir = std::atan2(v.z, v.y);
    return polar(K, frame(K, p) * Rot(dir) * Tr(K, t * d) * glm::dvec3(1, 0, 0));
}

}  // namespace noneuclid::geo::ref
