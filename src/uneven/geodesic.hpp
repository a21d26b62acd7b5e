// Bodies on geodesics of a conformal metric (uneven/metric.hpp, docs/uneven.md).
//
// A body's state is its chart point x and its heading phi in the chart (the chart is conformal,
// so angles there are the world's); its world speed s is a constant of the body, not a state: a
// unit vector of g at x is e^{-psi} (cos phi, sin phi), and a geodesic of g is a curve whose
// Euclidean curvature in the chart is the derivative of psi across it. So
//
//     dx/dt   = s e^{-psi} (cos phi, sin phi)
//     dphi/dt = s e^{-psi} (-psi_x sin phi + psi_y cos phi)
//
// and the speed is s exactly, at every step, whatever the step's error in x and phi. The
// integrator is the classical fourth-order Runge-Kutta on (x, y, phi), each step cut into
// substeps of at most kMaxSubstep world units, so that the error per world unit travelled is
// the same whatever the speed and the frame time (docs/uneven.md gives its size). A heading
// carried along a geodesic this way is its parallel transport (the geodesic's own tangent).
// No heap, no OS.
#pragma once

#include <cmath>

#include "uneven/metric.hpp"

namespace noneuclid::uneven {

struct Geodesic {
    Vec2 x;           // the chart point
    double phi = 0;   // the heading in the chart, radians
};

// The longest substep, in world units: the fourth-order error of a substep is about
// (kMaxSubstep * curvature scale)^5, 1e-15 here for scales near 1.
inline constexpr double kMaxSubstep = 1.0 / 512;

namespace detail {
struct Rate {
    Vec2 dx;
    double dphi = 0;
};
inline Rate rate(const Metric& m, const Geodesic& g, double s) {
    const MetricAt at = m.at(g.x);
    const double v = s * std::exp(-at.psi), c = std::cos(g.phi), sn = std::sin(g.phi);
    return {{v * c, v * sn}, v * (-at.grad.x * sn + at.grad.y * c)};
}
inline Geodesic moved(const Geodesic& g, const Rate& r, double h) {
    return {g.x + h * r.dx, g.phi + h * r.dphi};
}
}  // namespace detail

// One Runge-Kutta step of time h at world speed s.
inline Geodesic rk4(const Metric& m, const Geodesic& g, double s, double h) {
    using detail::moved;
    using detail::rate;
    const detail::Rate k1 = rate(m, g, s);
    const detail::Rate k2 = rate(m, moved(g, k1, h / 2), s);
    const detail::Rate k3 = rate(m, moved(g, k2, h / 2), s);
    const detail::Rate k4 = rate(m, moved(g, k3, h), s);
    Geodesic out;
    out.x = g.x + (h / 6) * (k1.dx + 2.0 * k2.dx + 2.0 * k3.dx + k4.dx);
    out.phi = g.phi + (h / 6) * (k1.dphi + 2 * k2.dphi + 2 * k3.dphi + k4.dphi);
    return out;
}

// The number of substeps a step of world length `length` takes.
inline int substeps(double length) {
    const double n = std::ceil(std::fabs(length) / kMaxSubstep);
    return n < 1 ? 1 : (n > 1e6 ? 1000000 : static_cast<int>(n));
}

// The body after time dt at world speed s.
inline Geodesic step(const Metric& m, Geodesic g, double s, double dt) {
    const int n = substeps(s * dt);
    for (int i = 0; i < n; ++i) g = rk4(m, g, s, dt / n);
    return g;
}

// The exponential map: the point a world distance `length` from x in chart direction phi (a
// body's vertex from its centre; length >= 0). Its heading there is the geodesic's.
inline Geodesic exp_map(const Metric& m, Vec2 x, double phi, double length) {
    return step(m, Geodesic{x, phi}, 1.0, length);
}

}  // namespace noneuclid::uneven
