// The paper's formulas, literally (Osudin, Child & He 2019), in double: the law of cosines
// solved with acos / acosh, lengths scaled by sqrt|K| and divided back, and the flat special
// case its code takes for |K| <= 0.01. Used only to compare against (accuracy report, tests):
// it jumps where it switches to the flat branch, loses short distances to acos near 1, and
// divides by sin(sqrt K a), which is 0 at the centre (NaN there; nothing here hides it).
#pragma once

#include <algorithm>
#include <cmath>

#include "geometry/geometry.hpp"

namespace noneuclid::geo::paper {

inline constexpr double kFlatBelow = 0.01;  // the paper's code: |K| <= 0.01 is flat

// Side c opposite the angle gamma between sides a and b, and the angle opposite side b (at the
// vertex between sides a and c), by the law of cosines for the given K.
struct Solved {
    double c, angle_opposite_b;
};
inline Solved law_of_cosines(double K, double a, double b, double gamma, double flat_below) {
    if (std::fabs(K) <= flat_below) {
        const double c = std::sqrt(std::max(0.0, a * a + b * b - 2 * a * b * std::cos(gamma)));
        const double cb = (a * a + c * c - b * b) / (2 * a * c);
        return {c, std::acos(std::clamp(cb, -1.0, 1.0))};
    }
    if (K > 0) {
        const double k = std::sqrt(K);
        const double cc = std::cos(k * a) * std::cos(k * b) + std::sin(k * a) * std::sin(k * b) * std::cos(gamma);
        const double c = std::acos(std::clamp(cc, -1.0, 1.0)) / k;
        const double cb = (std::cos(k * b) - std::cos(k * a) * std::cos(k * c)) / (std::sin(k * a) * std::sin(k * c));
        return {c, std::acos(std::clamp(cb, -1.0, 1.0))};
    }
    const double k = std::sqrt(-K);
    const double cc = std::cosh(k * a) * std::cosh(k * b) - std::sinh(k * a) * std::sinh(k * b) * std::cos(gamma);
    const double c = std::acosh(std::max(1.0, cc)) / k;
    const double cb = (std::cosh(k * a) * std::cosh(k * c) - std::cosh(k * b)) / (std::sinh(k * a) * std::sinh(k * c));
    return {c, std::acos(std::clamp(cb, -1.0, 1.0))};
}

// (a) in the paper's terms: the angle at the centre C between C->O and C->V is
// beta = |wrap(delta - pi)| (delta = heading - theta_C), and V lies on the side given by sin delta.
inline Polar<double> vertex_position(double K, Polar<double> centre, double facing, Polar<double> local,
                                     double flat_below = kFlatBelow) {
    const double delta = wrap_pi(facing + local.theta - centre.theta);
    const double beta = std::fabs(wrap_pi(delta - pi_v<double>));
    const Solved s = law_of_cosines(K, centre.r, local.r, beta, flat_below);
    const double side = std::sin(delta) >= 0 ? 1.0 : -1.0;
    return {s.c, wrap_pi(centre.theta + side * s.angle_opposite_b)};
}

// The angle between sides a and b of a triangle whose third side is `opposite` (law of cosines
// solved for the angle, through acos).
inline double angle_from_sides(double K, double a, double b, double opposite,
                               double flat_below = kFlatBelow) {
    double c;
    if (std::fabs(K) <= flat_below) {
        c = (a * a + b * b - opposite * opposite) / (2 * a * b);
    } else if (K > 0) {
        const double k = std::sqrt(K);
        c = (std::cos(k * opposite) - std::cos(k * a) * std::cos(k * b)) / (std::sin(k * a) * std::sin(k * b));
    } else {
        const double k = std::sqrt(-K);
        c = (std::cosh(k * a) * std::cosh(k * b) - std::cosh(k * opposite)) / (std::sinh(k * a) * std::sinh(k * b));
    }
    return std::acos(std::clamp(c, -1.0, 1.0));
}

// (d) the paper's movement: the new centre as above; the direction of travel from the angle at
// the new centre between it->O and it->old centre (opposite the old radius).
inline Pose<double> move(double K, Pose<double> pose, double d, double flat_below = kFlatBelow) {
    const Polar<double> c1 = vertex_position(K, pose.centre, pose.travel, {d, 0.0}, flat_below);
    const double delta = wrap_pi(pose.travel - pose.centre.theta);
    const double side = std::sin(delta) >= 0 ? 1.0 : -1.0;
    const double eps = angle_from_sides(K, d, c1.r, pose.centre.r, flat_below);
    const double travel = wrap_pi(c1.theta + side * eps);
    return {c1, travel, wrap_pi(pose.facing + (travel - pose.travel))};
}

// The paper's distance between two polar points: the law of cosines through acos / acosh.
inline double distance(double K, Polar<double> p, Polar<double> q, double flat_below = kFlatBelow) {
    return law_of_cosines(K, p.r, q.r, std::fabs(wrap_pi(q.theta - p.theta)), flat_below).c;
}

// (c) the paper's tessellation: the point at fraction t of the edge p -> q, from triangle
// O-p-X: the edge's length and the angle at p by the law of cosines, then (a) again.
inline Polar<double> edge_point(double K, Polar<double> p, Polar<double> q, double t,
                                double flat_below = kFlatBelow) {
    const double d = distance(K, p, q, flat_below);
    const double at_p = angle_from_sides(K, p.r, d, q.r, flat_below);
    const double side = std::sin(q.theta - p.theta) >= 0 ? 1.0 : -1.0;
    const double heading = p.theta + pi_v<double> - side * at_p;
    return vertex_position(K, p, heading, {t * d, 0.0}, flat_below);
}

}  // namespace noneuclid::geo::paper
