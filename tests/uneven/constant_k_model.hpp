// The world of constant K as a 3-vector model, in long double: the reference a body on a
// geodesic of the uneven world's metric without bumps must follow (tests/uneven).
//
// A point is (w, z), w in R^2, with K |w|^2 + z^2 = 1: for K > 0 the sphere of radius 1/sqrt(K)
// (w its first two coordinates, z the third times sqrt(K)), for K < 0 the hyperboloid, for K = 0
// the plane z = 1. The stereographic chart: x = 2 w / (1 + z), and back w = lambda x,
// z = 2 lambda - 1 with lambda = 1 / (1 + K |x|^2 / 4). A geodesic of unit speed from p with unit
// tangent t is p(tau) = C(tau) p + S(tau) t, C = cos(sqrt(K) tau), S = sin(sqrt(K) tau) / sqrt(K)
// (cosh and sinh for K < 0, 1 and tau for K = 0), and its tangent is -K S p + C t.
#pragma once

#include <cmath>

namespace noneuclid::test {

struct ModelPoint {
    long double wx = 0, wy = 0, z = 1;
};

struct ModelGeodesic {
    long double K = 0;
    ModelPoint p, t;  // a point and the unit tangent there

    // From a chart point and a chart heading.
    static ModelGeodesic from_chart(long double K, long double x, long double y, long double phi) {
        ModelGeodesic g;
        g.K = K;
        const long double q = 1 + K * (x * x + y * y) / 4, lambda = 1 / q;
        g.p = {lambda * x, lambda * y, 2 * lambda - 1};
        // A unit world vector at x is (cos phi, sin phi) / lambda in the chart; w = lambda x and
        // z = 2 lambda - 1 carry it: dlambda = -lambda^2 (K / 2) x . dx.
        const long double dx = std::cos(phi) / lambda, dy = std::sin(phi) / lambda;
        const long double dl = -lambda * lambda * (K / 2) * (x * dx + y * dy);
        g.t = {dl * x + lambda * dx, dl * y + lambda * dy, 2 * dl};
        return g;
    }

    // C and S at tau.
    void cs(long double tau, long double& C, long double& S) const {
        if (K > 0) {
            const long double k = std::sqrt(K);
            C = std::cos(k * tau), S = std::sin(k * tau) / k;
        } else if (K < 0) {
            const long double k = std::sqrt(-K);
            C = std::cosh(k * tau), S = std::sinh(k * tau) / k;
        } else {
            C = 1, S = tau;
        }
    }

    // The chart point and heading a world distance tau along.
    void chart_at(long double tau, long double& x, long double& y, long double& phi) const {
        long double C, S;
        cs(tau, C, S);
        const ModelPoint q{C * p.wx + S * t.wx, C * p.wy + S * t.wy, C * p.z + S * t.z};
        const ModelPoint v{-K * S * p.wx + C * t.wx, -K * S * p.wy + C * t.wy, -K * S * p.z + C * t.z};
        const long double d = 1 + q.z;
        x = 2 * q.wx / d, y = 2 * q.wy / d;
        // dx = 2 dw / (1 + z) - 2 w dz / (1 + z)^2
        const long double vx = 2 * v.wx / d - 2 * q.wx * v.z / (d * d), vy = 2 * v.wy / d - 2 * q.wy * v.z / (d * d);
        phi = std::atan2(vy, vx);
    }
};

}  // namespace noneuclid::test
