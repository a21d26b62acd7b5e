// A world whose curvature changes from place to place (docs/uneven.md): a conformal chart,
// points x in R^2 and the metric g = e^{2 psi(x)} |dx|^2 with
//
//     psi(x) = -ln(1 + K |x|^2 / 4) + sum_i beta_i(x).
//
// With no bumps this is the world of constant K in its stereographic chart: a point at distance
// r from O in direction theta is x = rho(r) (cos theta, sin theta), rho(r) = 2 tan(r sqrt(K) / 2)
// / sqrt(K) (K > 0), 2 tanh(r sqrt(-K) / 2) / sqrt(-K) (K < 0), r (K = 0). Each bump adds a beta:
//
//   hill: beta = a exp(-|x - c|^2 / s^2)                 curvature up at c, down in a ring (a > 0),
//                                                       no curvature added in all
//   mass: beta = -(alpha / 2) ln(1 + |x - c|^2 / s^2)    a smoothed cone: 2 pi alpha of curvature
//
// The Gaussian curvature is K(x) = -e^{-2 psi} lap(psi), and K(x) dA = -lap(psi) dx dy, so
// the curvature a region holds is minus the flux of grad(psi) through its edge (Gauss-Bonnet's
// other side). Plain double, no heap, no OS.
#pragma once

#include <cmath>

namespace noneuclid::uneven {

struct Vec2 {
    double x = 0, y = 0;
};
inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

enum class BumpKind { hill, mass };

struct Bump {
    BumpKind kind = BumpKind::hill;
    Vec2 centre;          // a chart point
    double width = 0.5;   // s, chart units (> 0)
    double strength = 0;  // hill: a; mass: alpha (total curvature 2 pi alpha)
};

// psi and its derivatives at a point: what the geodesic equation and the curvature need.
struct MetricAt {
    double psi = 0;
    Vec2 grad;
    double laplacian = 0;
};

inline constexpr int kMaxBumps = 8;

struct Metric {
    double K = 0;
    Bump bumps[kMaxBumps] = {};
    int bump_count = 0;

    // psi, grad psi and lap psi at x.
    MetricAt at(Vec2 x) const {
        MetricAt m;
        const double q = 1 + K * dot(x, x) / 4;  // (> 0 wherever the chart is a world's point)
        m.psi = -std::log(q);
        m.grad = (-K / (2 * q)) * x;
        // lap(-ln q) = -(K / q) + K^2 |x|^2 / (4 q^2) in the plane: -K / q^2.
        m.laplacian = -K / (q * q);
        for (int i = 0; i < bump_count; ++i) {
            const Bump& b = bumps[i];
            const Vec2 d = x - b.centre;
            const double d2 = dot(d, d), s2 = b.width * b.width;
            if (b.kind == BumpKind::hill) {
                const double beta = b.strength * std::exp(-d2 / s2);
                m.psi += beta;
                m.grad = m.grad + (-2 * beta / s2) * d;
                m.laplacian += beta * (4 * d2 / (s2 * s2) - 4 / s2);
            } else {
                const double u = s2 + d2;
                m.psi += -(b.strength / 2) * std::log(u / s2);
                m.grad = m.grad + (-b.strength / u) * d;
                m.laplacian += -2 * b.strength * s2 / (u * u);
            }
        }
        return m;
    }
    // The Gaussian curvature at x.
    double curvature(Vec2 x) const {
        const MetricAt m = at(x);
        const double k = -std::exp(-2 * m.psi) * m.laplacian;
        return std::isfinite(k) ? k : 0;  // (0 past the edge of the Poincare disc, K < 0)
    }
};

// The chart's radius of a point at distance r from O in the world of constant K, and back.
inline double chart_radius(double K, double r) {
    if (K > 0) return 2 * std::tan(r * std::sqrt(K) / 2) / std::sqrt(K);
    if (K < 0) return 2 * std::tanh(r * std::sqrt(-K) / 2) / std::sqrt(-K);
    return r;
}
inline double world_radius(double K, double rho) {
    if (K > 0) return 2 * std::atan(rho * std::sqrt(K) / 2) / std::sqrt(K);
    if (K < 0) return 2 * std::atanh(rho * std::sqrt(-K) / 2) / std::sqrt(-K);
    return rho;
}

}  // namespace noneuclid::uneven
