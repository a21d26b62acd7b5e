// The triangle instrument in an uneven world (docs/uneven.md, docs/measure.md): three marks
// joined by the metric's geodesics, found by shooting (Newton's method on the heading and the
// length from each mark), and what it reads: the sides, the interior angles (between the side
// leaving a vertex and the reverse of the one arriving, from the headings the integrator
// carries), the angle sum and its excess over pi, the world area, and the curvature the
// triangle holds, the integral of K dA. By Gauss-Bonnet the excess equals that integral; the
// reading computes the two independently: the integral as minus the flux of grad psi out
// through the traced sides (the divergence theorem: K dA = -lap(psi) dx dy), the area by the
// midpoint rule on a kAreaGrid x kAreaGrid grid over the chart triangle.
//
// Memory: the sides' points are fixed arrays; measuring allocates nothing.
#pragma once

#include "uneven/geodesic.hpp"

namespace noneuclid::uneven {

inline constexpr int kSidePoints = 129;  // points traced along each side, ends included (an odd count: Simpson)
inline constexpr int kAreaGrid = 64;

struct Triangle {
    Vec2 mark[3];
    bool valid = false;        // the sides were found and the marks are apart and not in a line
    double side[3] = {};       // side[i]: opposite mark i, world units
    double angle[3] = {};      // interior angle at mark i, radians
    double excess = 0;         // angle sum - pi
    double curvature = 0;      // the integral of K dA: minus the flux of grad psi
    double area = 0;           // world units squared
    Vec2 path[3][kSidePoints]; // side i from mark i to mark i + 1, chart points
};

// A geodesic from `from` to `to`: its heading at `from` and its length; false if Newton's
// method does not reach `to` within 1e-12 chart units.
bool shoot(const Metric& m, Vec2 from, Vec2 to, double& phi, double& length);

// Measures the triangle on its marks (t.mark) under the metric; t.valid says whether it could.
void measure(const Metric& m, Triangle& t);

}  // namespace noneuclid::uneven
