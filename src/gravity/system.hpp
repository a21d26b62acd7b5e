// N bodies attracting each other on a surface of constant curvature K in [-1, 1]
// (docs/gravity.md): their state in the 3-vector model, the forces of gravity/law.hpp along the
// geodesics between them, a symplectic integrator, and the two integrals the motion keeps, the
// energy and the angular momentum. Templated on the scalar (geometry/scalar.hpp); fixed
// capacity, nothing allocated.
//
// The state. A body is a point p = (w, x, y) = (C_K(r), S_K(r) cos theta, S_K(r) sin theta) of
// the 3-vector model (geometry/model.hpp: <p, q> = w1 w2 + K (x1 x2 + y1 y2) = C_K(d), so
// <p, p> = 1) and a velocity v, a tangent vector at p: <p, v> = 0, the derivative of p along
// the motion. At K = 0 the model is the plane (w = 1, v_w = 0, (x, y) the plane's coordinates).
//
// Lengths of tangent vectors. For K != 0 the surface's metric is the form scaled by 1 / K
// (the sphere of radius 1 / sqrt K sits in R³ as (w / sqrt K, x, y)), so
// g(a, b) = a_w b_w / K + a_s . b_s, with a_s = (a_x, a_y), which divides 0 by 0 at K = 0.
// For tangent vectors at p, multiply a_w b_w / K by <p, p> = w^2 + K |p_s|^2 = 1 and use
// w a_w = -K p_s . a_s (tangency):
//     g_p(a, b) = a_s . b_s + K (p_s . a_s)(p_s . b_s) + a_w b_w |p_s|^2,
// a polynomial, the same for every K, right at K = 0 (the plane's a_s . b_s) and on the
// sphere's equator (w = 0), where solving the tangency for a_w would divide by 0.
//
// The motion is Hamilton's for H = sum m |v|^2 / 2 + sum_{i<j} U_ij: each body follows a
// geodesic, bent by the forces. A free body's geodesic through p with velocity v (speed u) is
//     p(t) = C_K(u t) p + S_K(u t) v / u,   v(t) = -K u S_K(u t) p + C_K(u t) v
// (p'' = -K u^2 p: C_K and S_K solve f'' = -K f), which carries v along by parallel transport.
// Written with z = K t^2 u^2 as p(t) = Cf(z) p + t Sf(z) v, v(t) = -K u^2 t Sf(z) p + Cf(z) v
// there is no 1 / u and no 1 / sqrt K: it holds at u = 0 and K = 0 (the plane's p + t v).
//
// The integrator splits H into its kinetic part, whose flow is exactly that geodesic drift of
// every body, and its potential part, whose flow is a kick v += t a at fixed positions (a the
// force / m, a tangent vector: gravity/law.hpp's pull times q - c p). Each flow is exact and
// symplectic, so their symmetric composition kick(h/2) drift(h) kick(h/2) (leapfrog) is a
// symplectic, time-reversible map of second order: it keeps a nearby "modified" energy
// exactly, so the energy's error stays O(h^2) and bounded for ever instead of drifting. Both
// flows keep the angular momentum exactly (the drift maps (p, v) to (a p + b v, c p + d v) with
// ad - bc = C_K^2 + K S_K^2 = 1; the kicks' pair forces cancel in it), so it changes only by
// rounding. yoshida4 composes three leapfrogs (Yoshida 1990) for fourth order: the same
// properties, errors (h / T)^4. (RATTLE on the embedding would need the constraint's gradient
// in the metric diag(1/K, 1, 1), which degenerates at K = 0; the exact geodesic drift does
// not: it never leaves the surface, up to the rounding that each drift takes back, settle.)
//
// A fixed body (a sun held in place, for the Kepler problem) pulls the others but does not
// move: the drift and the kicks skip it, and it counts in neither the kinetic energy nor the
// angular momentum. Bodies may have mass 0 (test bodies: pulled, pulling nothing).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "geometry/model.hpp"
#include "gravity/law.hpp"

namespace noneuclid::gravity {

using geo::Polar;
using geo::Vec3;

inline constexpr std::size_t kMaxBodies = 64;

template <class T>
struct Body {
    Vec3<T> p{T(1), T(0), T(0)};  // the position, <p, p> = 1 (O by default)
    Vec3<T> v{};                  // the velocity, tangent at p
    T mass{};
    bool fixed = false;  // held in place: pulls, is not pulled, does not move
};

template <class T, std::size_t N = kMaxBodies>
struct System {
    T K{};
    T G{1};
    T eps{};  // the softening length (gravity/law.hpp)
    Law law = Law::cotangent;
    std::array<Body<T>, N> bodies{};
    std::size_t count = 0;
    std::array<Vec3<T>, N> acc{};  // the integrator's scratch: force / mass, tangent at p
};

// ---- the model's vectors -------------------------------------------------------------------

template <class T>
Vec3<T> operator+(Vec3<T> a, Vec3<T> b) {
    return {a.w + b.w, a.x + b.x, a.y + b.y};
}
template <class T>
Vec3<T> operator-(Vec3<T> a, Vec3<T> b) {
    return {a.w - b.w, a.x - b.x, a.y - b.y};
}
template <class T>
Vec3<T> operator*(T s, Vec3<T> a) {
    return {s * a.w, s * a.x, s * a.y};
}
// The model's form <a, b> = a_w b_w + K (a_x b_x + a_y b_y).
template <class T>
T form(T K, Vec3<T> a, Vec3<T> b) {
    return a.w * b.w + K * (a.x * b.x + a.y * b.y);
}
// The surface's metric g_p(a, b) on tangent vectors at p (the top of this file).
template <class T>
T metric(T K, Vec3<T> p, Vec3<T> a, Vec3<T> b) {
    const T pa = p.x * a.x + p.y * a.y, pb = p.x * b.x + p.y * b.y;
    return a.x * b.x + a.y * b.y + K * pa * pb + a.w * b.w * (p.x * p.x + p.y * p.y);
}
template <class T>
T speed_squared(T K, Vec3<T> p, Vec3<T> v) {
    return metric(K, p, v, v);
}

// ---- bodies from and to polar coordinates ---------------------------------------------------

// A body at `at` moving with the radial and tangential speeds (dr/dt and S_K(r) dtheta/dt):
// v = radial e_r + tangential e_theta, with the unit vectors at p
//   e_r = (-K S_K(r), C_K(r) cos theta, C_K(r) sin theta)   (d p / d r)
//   e_theta = (0, -sin theta, cos theta)                     (d p / d theta / S_K(r)).
template <class T>
Body<T> make_body(T K, Polar<T> at, T radial, T tangential, T mass, bool fixed = false) {
    using std::cos, std::sin;
    const T c = geo::C_K(K, at.r), s = geo::S_K(K, at.r);
    const T ct = cos(at.theta), st = sin(at.theta);
    Body<T> b;
    b.p = {c, s * ct, s * st};
    b.v = {-K * s * radial, c * ct * radial - st * tangential, c * st * radial + ct * tangential};
    b.mass = mass;
    b.fixed = fixed;
    return b;
}

// Where a body is and how it moves, in polar terms (make_body's inverse).
template <class T>
struct PolarMotion {
    Polar<T> at;
    T radial{}, tangential{};
};
template <class T>
PolarMotion<T> polar_motion(T K, const Body<T>& b) {
    using std::cos, std::sin;
    const Polar<T> at = geo::to_polar(K, b.p);
    const T c = geo::C_K(K, at.r), s = geo::S_K(K, at.r);
    const T ct = cos(at.theta), st = sin(at.theta);
    const Vec3<T> er{-K * s, c * ct, c * st}, et{T(0), -st, ct};
    return {at, metric(K, b.p, b.v, er), metric(K, b.p, b.v, et)};
}

// Adds a body; false when the system is full.
template <class T, std::size_t N>
bool add(System<T, N>& sys, const Body<T>& b) {
    if (sys.count >= N) return false;
    sys.bodies[sys.count++] = b;
    return true;
}

// Turns K keeping every body's polar position and polar velocity (the chart's view of the
// state: what a visitor turning K sees stay put). The energy changes with K: it is the law's.
template <class T, std::size_t N>
void set_curvature(System<T, N>& sys, T K) {
    for (std::size_t i = 0; i < sys.count; ++i) {
        Body<T>& b = sys.bodies[i];
        const PolarMotion<T> m = polar_motion(sys.K, b);
        b = make_body(K, m.at, m.radial, m.tangential, b.mass, b.fixed);
    }
    sys.K = K;
}

// ---- forces ------------------------------------------------------------------------------

// The tangent vector q - c p at p along the geodesic to q (length S_K(d)), with c = <p, q>.
template <class T>
struct Towards {
    Vec3<T> dir;
    T s, c;
};
template <class T>
Towards<T> towards(T K, Vec3<T> p, Vec3<T> q) {
    using std::sqrt;
    const T c = form(K, p, q);
    const Vec3<T> dir = q - c * p;
    return {dir, sqrt(speed_squared(K, p, dir)), c};
}

// sys.acc[i] = the force on body i over its mass, for every body (0 for fixed ones), each pair
// once: the pair's pull is the same number in both directions, so the forces' moments cancel.
template <class T, std::size_t N>
void accelerations(System<T, N>& sys) {
    for (std::size_t i = 0; i < sys.count; ++i) sys.acc[i] = {};
    for (std::size_t i = 0; i < sys.count; ++i) {
        const Body<T>& a = sys.bodies[i];
        for (std::size_t j = i + 1; j < sys.count; ++j) {
            const Body<T>& b = sys.bodies[j];
            if (a.fixed && b.fixed) continue;
            const Towards<T> t = towards(sys.K, a.p, b.p);
            const T pull = sys.G * pair_law(sys.law, sys.K, t.s, t.c, sys.eps).pull;
            if (!a.fixed) sys.acc[i] = sys.acc[i] + (pull * b.mass) * t.dir;
            if (!b.fixed) sys.acc[j] = sys.acc[j] + (pull * a.mass) * (a.p - t.c * b.p);
        }
    }
}

// ---- the integrator ------------------------------------------------------------------------

// Puts a body back on the surface (<p, p> = 1) and its velocity back in the tangent plane
// (<p, v> = 0), undoing rounding. The velocity is corrected along n = (w, K x, K y), the
// gradient of <p, p> / 2, with <p, n> = w^2 + K^2 |p_s|^2 > 0 for every K: at K = 0 that only
// sets v_w = 0 (the form's own normal p would shift the plane's velocity too), at K = 1 it is p.
// Why every drift does it: the drift keeps both constraints exactly, but only in exact
// arithmetic, and off the surface g_p (the top of this file) is not the metric: a rounding
// error in p or v changes the speed by about |p_s|^2 times itself, which the next drifts feed
// back into p. Far out on the hyperbolic plane (w ~ 4) that loop doubled the error every few
// hundred steps, from 1e-16 to a wrecked orbit within 2 10^4 steps. Each step's own error is
// rounding, so taking it back changes nothing the symplectic map would have kept.
template <class T>
void settle(T K, Body<T>& b) {
    using std::sqrt;
    b.p = (T(1) / sqrt(form(K, b.p, b.p))) * b.p;
    const Vec3<T> n{b.p.w, K * b.p.x, K * b.p.y};
    b.v = b.v - (form(K, b.p, b.v) / form(K, b.p, n)) * n;
}
// The same for every moving body, for a caller that edited the bodies.
template <class T, std::size_t N>
void settle(System<T, N>& sys) {
    for (std::size_t i = 0; i < sys.count; ++i)
        if (!sys.bodies[i].fixed) settle(sys.K, sys.bodies[i]);
}

template <class T, std::size_t N>
void kick(System<T, N>& sys, T t) {
    for (std::size_t i = 0; i < sys.count; ++i)
        if (!sys.bodies[i].fixed) sys.bodies[i].v = sys.bodies[i].v + t * sys.acc[i];
}
// Every moving body along its geodesic for the time t (may be negative), its velocity carried.
template <class T, std::size_t N>
void drift(System<T, N>& sys, T t) {
    using geo::Cf, geo::Sf;
    const T K = sys.K;
    for (std::size_t i = 0; i < sys.count; ++i) {
        Body<T>& b = sys.bodies[i];
        if (b.fixed) continue;
        const T u2 = speed_squared(K, b.p, b.v);
        const T z = K * t * t * u2;
        const T c = Cf(z), ts = t * Sf(z);  // C_K(t u), S_K(t u) / u
        const Vec3<T> p = c * b.p + ts * b.v;
        b.v = (-K * u2 * ts) * b.p + c * b.v;
        b.p = p;
        settle(K, b);
    }
}

// `steps` leapfrog steps of length h: kick(h/2) drift(h) kick(h/2), the kicks between two
// steps taken as one (one force evaluation a step, and one more to start).
template <class T, std::size_t N>
void leapfrog(System<T, N>& sys, T h, int steps = 1) {
    if (steps <= 0) return;
    const T half = h / T(2);
    accelerations(sys);
    kick(sys, half);
    for (int n = 0; n < steps; ++n) {
        drift(sys, h);
        accelerations(sys);
        kick(sys, n + 1 < steps ? h : half);
    }
}

// `steps` fourth-order steps of length h: leapfrogs of w1 h, w0 h, w1 h (Yoshida's triple
// jump, w1 = 1 / (2 - 2^(1/3)), w0 = 1 - 2 w1 < 0: the middle one runs backwards), three force
// evaluations a step.
template <class T, std::size_t N>
void yoshida4(System<T, N>& sys, T h, int steps = 1) {
    if (steps <= 0) return;
    const T w1 = geo::num<T>(1.3512071919596576340476878089715);
    const T w0 = geo::num<T>(-1.7024143839193152680953756179429);
    const T a = w1 * h, b = w0 * h, ab = (a + b) / T(2);
    accelerations(sys);
    kick(sys, a / T(2));
    for (int n = 0; n < steps; ++n) {
        drift(sys, a);
        accelerations(sys);
        kick(sys, ab);
        drift(sys, b);
        accelerations(sys);
        kick(sys, ab);
        drift(sys, a);
        accelerations(sys);
        kick(sys, n + 1 < steps ? a : a / T(2));
    }
}

// ---- the integrals ----------------------------------------------------------------------

template <class T, std::size_t N>
T kinetic_energy(const System<T, N>& sys) {
    T e{};
    for (std::size_t i = 0; i < sys.count; ++i) {
        const Body<T>& b = sys.bodies[i];
        if (!b.fixed) e = e + b.mass * speed_squared(sys.K, b.p, b.v) / T(2);
    }
    return e;
}
template <class T, std::size_t N>
T potential_energy(const System<T, N>& sys) {
    T e{};
    for (std::size_t i = 0; i < sys.count; ++i)
        for (std::size_t j = i + 1; j < sys.count; ++j) {
            const Body<T>&a = sys.bodies[i], &b = sys.bodies[j];
            if (a.fixed && b.fixed) continue;
            const Towards<T> t = towards(sys.K, a.p, b.p);
            e = e + sys.G * a.mass * b.mass * pair_law(sys.law, sys.K, t.s, t.c, sys.eps).potential;
        }
    return e;
}
template <class T, std::size_t N>
T energy(const System<T, N>& sys) {
    return kinetic_energy(sys) + potential_energy(sys);
}

// The angular momentum: the momenta that the surface's isometries keep (Noether), one for each
// of three generators, m g_p(v, xi(p)):
//   o:  the rotation about O, xi = (0, -y, x):             m (x v_y - y v_x)
//   x:  the isometry moving O along +x, xi = (-K x, w, 0): m (w v_x - x v_w)
//   y:  the same along +y, xi = (-K y, 0, w):              m (w v_y - y v_w).
// On the sphere (K = 1) they are the components of m p x v in R³, on the hyperbolic plane
// those of so(2,1); at K = 0 they are the plane's angular momentum about O and its linear
// momentum (m v_x, m v_y). With free bodies all three are kept; with a fixed body at q only the
// rotation about q is, angular_momentum_about(sys, q).
template <class T>
struct Momentum {
    T o{}, x{}, y{};
};
template <class T, std::size_t N>
Momentum<T> angular_momentum(const System<T, N>& sys) {
    Momentum<T> j;
    for (std::size_t i = 0; i < sys.count; ++i) {
        const Body<T>& b = sys.bodies[i];
        if (b.fixed) continue;
        j.o = j.o + b.mass * (b.p.x * b.v.y - b.p.y * b.v.x);
        j.x = j.x + b.mass * (b.p.w * b.v.x - b.p.x * b.v.w);
        j.y = j.y + b.mass * (b.p.w * b.v.y - b.p.y * b.v.w);
    }
    return j;
}
// The momentum of the rotation about the point q: q_w xi_o + q_y xi_x - q_x xi_y vanishes at q,
// so it is q_w J_o + q_y J_x - q_x J_y (J_o when q is O).
template <class T, std::size_t N>
T angular_momentum_about(const System<T, N>& sys, Vec3<T> q) {
    const Momentum<T> j = angular_momentum(sys);
    return q.w * j.o + q.y * j.x - q.x * j.y;
}

}  // namespace noneuclid::gravity
