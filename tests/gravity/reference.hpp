// The gravity tests' own references, in long double and in the textbook forms with a branch on
// the sign of K (the engine's are one K-continuous formula): the curvature functions, the
// distance in the scaled embedding (R³ for K > 0, R^{2,1} for K < 0, the plane at 0), a body's
// polar reading, the energy and the angular momentum, and the curved Kepler problem's closed
// forms (docs/gravity.md).
#pragma once

#include <cmath>
#include <numbers>

#include "gravity/system.hpp"

namespace gravity_ref {

using LD = long double;
using noneuclid::gravity::Body;
using noneuclid::gravity::System;
inline constexpr LD kPi = std::numbers::pi_v<long double>;
// The curvatures the figures are taken at.
inline constexpr double kCurvatures[] = {-1.0, -0.5, 0.0, 0.5, 1.0};

inline LD S(LD K, LD x) {
    if (K > 0) return std::sin(std::sqrt(K) * x) / std::sqrt(K);
    if (K < 0) return std::sinh(std::sqrt(-K) * x) / std::sqrt(-K);
    return x;
}
inline LD C(LD K, LD x) {
    if (K > 0) return std::cos(std::sqrt(K) * x);
    if (K < 0) return std::cosh(std::sqrt(-K) * x);
    return 1;
}
inline LD ctn(LD K, LD x) {
    if (K > 0) return std::sqrt(K) / std::tan(std::sqrt(K) * x);
    if (K < 0) return std::sqrt(-K) / std::tanh(std::sqrt(-K) * x);
    return 1 / x;
}
// The distance r from O of the point whose S_K(r) is s and C_K(r) is c.
inline LD arc(LD K, LD s, LD c) {
    if (K > 0) return std::atan2(std::sqrt(K) * s, c) / std::sqrt(K);
    if (K < 0) return std::asinh(std::sqrt(-K) * s) / std::sqrt(-K);
    return s;
}

// The geodesic distance from the chord of the embedding X = (w / sqrt|K|, x, y): its squared
// length dw^2 / K + dx^2 + dy^2 (Euclidean for K > 0, Minkowski for K < 0) is (2 S_K(d/2))^2.
template <class V>
LD distance(LD K, const V& p, const V& q) {
    const LD dw = LD(p.w) - LD(q.w), dx = LD(p.x) - LD(q.x), dy = LD(p.y) - LD(q.y);
    const LD half = std::sqrt((K != 0 ? dw * dw / K : 0) + dx * dx + dy * dy) / 2;  // S_K(d/2)
    if (K > 0) return 2 * std::asin(std::sqrt(K) * half) / std::sqrt(K);
    if (K < 0) return 2 * std::asinh(std::sqrt(-K) * half) / std::sqrt(-K);
    return 2 * half;
}

// A body in polar terms: r, theta, dr/dt, S_K(r)^2 dtheta/dt (its angular momentum about O per
// unit mass) and its squared speed. From S = S_K(r) = |(x, y)| and w = C_K(r):
// d/dt S = C dr/dt and d/dt w = -K S dr/dt, so dr/dt = w dS/dt - S dw/dt.
struct Reading {
    LD r, theta, rdot, L, speed2;
};
template <class B>
Reading read(LD K, const B& b) {
    const LD w = b.p.w, x = b.p.x, y = b.p.y, vw = b.v.w, vx = b.v.x, vy = b.v.y;
    const LD s = std::hypot(x, y);
    Reading out;
    out.r = arc(K, s, w);
    out.theta = std::atan2(y, x);
    out.rdot = w * (x * vx + y * vy) / s - s * vw;
    out.L = x * vy - y * vx;
    out.speed2 = vx * vx + vy * vy + (K != 0 ? vw * vw / K : 0);
    return out;
}

// The energy with the cotangent law, eps = 0: sum m |v|^2 / 2 - sum G m1 m2 ctn_K(d).
template <std::size_t N>
LD energy(const System<double, N>& sys) {
    const LD K = sys.K;
    LD e = 0;
    for (std::size_t i = 0; i < sys.count; ++i) {
        const auto& a = sys.bodies[i];
        if (!a.fixed) e += LD(a.mass) * read(K, a).speed2 / 2;
        for (std::size_t j = i + 1; j < sys.count; ++j) {
            const auto& b = sys.bodies[j];
            if (!(a.fixed && b.fixed)) e -= LD(sys.G) * a.mass * b.mass * ctn(K, distance(K, a.p, b.p));
        }
    }
    return e;
}

// The angular momentum's three components: for K = 1 those of m p x v in R³ (scaled so that
// they stay finite at K = 0, where they are the angular momentum about O and the linear
// momentum): m (x v_y - y v_x), m (w v_x - x v_w), m (w v_y - y v_w).
struct Momentum {
    LD o = 0, x = 0, y = 0;
};
template <std::size_t N>
Momentum momentum(const System<double, N>& sys) {
    Momentum j;
    for (std::size_t i = 0; i < sys.count; ++i) {
        const auto& b = sys.bodies[i];
        if (b.fixed) continue;
        const LD m = b.mass, w = b.p.w, x = b.p.x, y = b.p.y;
        j.o += m * (x * b.v.y - y * LD(b.v.x));
        j.x += m * (w * b.v.x - x * LD(b.v.w));
        j.y += m * (w * b.v.y - y * LD(b.v.w));
    }
    return j;
}
inline LD norm(const Momentum& j) { return std::sqrt(j.o * j.o + j.x * j.x + j.y * j.y); }
inline LD difference(const Momentum& a, const Momentum& b) {
    return norm({a.o - b.o, a.x - b.x, a.y - b.y});
}

// ---- the curved Kepler problem (a test body around a fixed mass at O, cotangent law) --------
// With u = ctn_K(r), du/dr = -1/S_K(r)^2 and 1/S_K^2 = u^2 + K, the energy per unit mass is
// E = L^2 (u'^2 + u^2 + K) / 2 - mu u (u' = du/dtheta), and its derivative in theta gives
// u'' + u = mu / L^2: u = (mu / L^2)(1 + e cos(theta - theta0)), a closed orbit for every K.
struct Kepler {
    LD K, mu, e, L;  // the orbit u = (mu / L^2)(1 + e cos theta), periapsis on +x
    LD rp;           // the periapsis distance
};
// The orbit of eccentricity e whose periapsis is at distance rp: u(0) = ctn_K(rp) = mu (1 + e) / L^2.
inline Kepler kepler(LD K, LD mu, LD e, LD rp) { return {K, mu, e, std::sqrt(mu * (1 + e) / ctn(K, rp)), rp}; }
// The speed at periapsis (all tangential): L / S_K(rp).
inline LD periapsis_speed(const Kepler& k) { return k.L / S(k.K, k.rp); }
// The radial period, T = integral of dtheta S_K(r)^2 / L = (1/L) integral dtheta / (u^2 + K) over
// one turn; the trapezoid rule converges geometrically for a smooth periodic integrand.
inline LD period(const Kepler& k) {
    const int n = 4096;
    LD sum = 0;
    for (int i = 0; i < n; ++i) {
        const LD u = k.mu / (k.L * k.L) * (1 + k.e * std::cos(2 * kPi * i / n));
        sum += 1 / (u * u + k.K);
    }
    return sum * 2 * kPi / n / k.L;
}
// The periapsis direction from any point of the orbit: e cos(theta - theta0) = u L^2 / mu - 1
// and e sin(theta - theta0) = (dr/dt) L / mu (since dr/dt = -L u'). Constant on the exact orbit.
inline LD periapsis_angle(LD K, LD mu, const Reading& b) {
    const LD u = ctn(K, b.r);
    return b.theta - std::atan2(b.rdot * b.L / mu, u * b.L * b.L / mu - 1);
}

}  // namespace gravity_ref
