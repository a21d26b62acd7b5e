// The paper's triangle solutions in polar coordinates, in forms that are exact for every
// curvature K, including 0, and never divide by zero (design.md, "Where the paper's formulas
// break"). Written once, templated on the scalar: double (the reference engine), float, and
// fx::fixed (the device engine).
//
// Conventions
// - A position is polar (r, theta) about the screen centre O. theta runs counter-clockwise from
//   east as seen on screen (screen y grows downward: y_px = cy - rho sin theta).
// - Directions at a point P (a body's facing, its direction of travel, the heading of an edge)
//   are angles in the frame carried from O along the ray O->P by parallel transport. In that
//   frame the outward radial direction at P has angle theta_P, exactly as in the flat plane;
//   at r = 0 the carried frame is the global frame, so the convention is regular there.
// - A body's local vertex (rho, phi): distance rho from the centre, at angle phi measured
//   counter-clockwise from the body's facing. Its direction at the centre is facing + phi.
// - The paper measures the angle at the centre C from the direction toward O (its alpha). In
//   these terms alpha = heading - (theta_C + pi): the direction toward O has carried angle
//   theta_C + pi. The code below uses delta = heading - theta_C (from the outward radial),
//   so alpha = delta - pi.
// - Lengths are in world units; at K = +1 the whole sphere is r <= pi.
//
// The 3-vector model (design.md): a point is p = (C_K(r), S_K(r) cos theta, S_K(r) sin theta)
// with <p, q> = w1 w2 + K (x1 x2 + y1 y2) = C_K(dist). Every solution below is the polar
// reading of a small piece of that model, written without 1/sqrt|K| and without acos.
#pragma once

#include <bit>
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

// ---- the triangle O - P - Q -----------------------------------------------------------------

// Where a walk ends: the end point and the direction of travel carried along the walk,
// expressed in the end point's carried frame; `turn` is heading_end - heading_start, the angle
// by which the carried frame turned (0 on every geodesic of the flat plane).
template <class T>
struct Walk {
    Polar<T> end;
    T heading{};
    T turn{};
};

// From p, go distance b along the geodesic leaving p at `heading` (carried frame). This is the
// paper's triangle O-P-Q solved in the 3-vector model, in a frame rotated so that p lies on +x:
//   Q = C_K(b) P + S_K(b) (cos delta e_r + sin delta e_theta),   delta = heading - theta_p
// and the carried direction of travel T' = -K S_K(b) P + C_K(b) (cos delta e_r + ...). The
// end's bearing from O is atan2(Q_y, Q_x) (design.md: no acos, no division, fine at r = 0).
template <class T>
Walk<T> walk(T K, Polar<T> p, T heading, T b) {
    using std::atan2, std::cos, std::sin;
    const T delta = heading - p.theta;
    const T cd = cos(delta), sd = sin(delta);
    const T sa = S_K(K, p.r), ca = C_K(K, p.r), sb = S_K(K, b), cb = C_K(K, b);
    const T qw = dot2(ca, cb, -K * sa, sb * cd);
    const T qx = dot2(sa, cb, ca * sb, cd);
    const T qy = sb * sd;
    const T s = hypot(qx, qy);
    Walk<T> out;
    out.end = {arc_K(K, s, qw), wrap_pi(p.theta + atan2(qy, qx))};
    // The carried direction of travel at the end, T' = -K S_K(b) P + C_K(b) (cos delta e_r + ...):
    const T tw = -K * dot2(sb, ca, cb * sa, cd);
    const T tx = dot2(cb * ca, cd, -K * sb, sa);
    const T ty = cb * sd;
    // The new heading is found as heading + turn, the turn as the angle of (X, Y) below rotated
    // back by delta: a small angle computed directly, so a straight path does not drift by a
    // rounding of sin/cos/atan2 at every step (in the flat plane the turn is exactly 0).
    T X, Y;  // the direction of T' in the frame rotated so that p lies on +x
    if (s <= T(24) && qw >= T(0)) {
        // T' split into the end's outward radial and tangential parts (alpha, beta), turned by
        // the end's bearing D, in closed form: D cancels, and with 1 - C = K S^2 / (1 + C),
        // times (1 + C) > 0,
        //   X = (1 + C) (T'_x - T'_w qx) - K qx (T'_x qx + T'_y qy)
        //   Y = (1 + C) (T'_y - T'_w qy) - K qy (T'_x qx + T'_y qy)
        // No division, exact at O, and exactly no turn on a flat straight path. (Products
        // stay below 10^4 for S <= 24: r <= 3.9 at K = -1, far past the limit circle; and
        // 1 + C stays >= 1 while C >= 0, i.e. away from the sphere's antipode.)
        const T c1 = T(1) + qw;
        const T along = dot2(tx, qx, ty, qy);
        X = dot2(c1, tx - tw * qx, -K * qx, along);
        Y = dot2(c1, ty - tw * qy, -K * qy, along);
    } else {
        // Far out in hyperbolic space the products above would overflow Q16.16, and on the
        // sphere's far hemisphere 1 + C goes to 0: split T' with the unit bearing
        // (cos D, sin D) = (qx, qy) / s instead:
        //   alpha = C (T'_x cos D + T'_y sin D) - S T'_w,   beta = T'_y cos D - T'_x sin D
        // (no division by K or by C: C^2 + K S^2 = 1), and (X, Y) = (alpha, beta) turned by D.
        const T cD = qx / s, sD = qy / s;
        const T alpha = dot2(qw, dot2(tx, cD, ty, sD), -s, tw);
        const T beta = dot2(ty, cD, -tx, sD);
        X = dot2(alpha, cD, -beta, sD);
        Y = dot2(alpha, sD, beta, cD);
    }
    out.turn = atan2(dot2(Y, cd, -X, sd), dot2(X, cd, Y, sd));
    out.heading = wrap_pi(heading + out.turn);
    return out;
}

// Only the end of walk(K, p, heading, b), the same bits, without the carried direction (a
// body's vertices need no more).
template <class T>
Polar<T> walk_end(T K, Polar<T> p, T heading, T b) {
    using std::atan2, std::cos, std::sin;
    const T delta = heading - p.theta;
    const T cd = cos(delta), sd = sin(delta);
    const T sa = S_K(K, p.r), ca = C_K(K, p.r), sb = S_K(K, b), cb = C_K(K, b);
    const T qw = dot2(ca, cb, -K * sa, sb * cd);
    const T qx = dot2(sa, cb, ca * sb, cd);
    const T qy = sb * sd;
    return {arc_K(K, hypot(qx, qy), qw), wrap_pi(p.theta + atan2(qy, qx))};
}

// The direction (carried frame at p) of the geodesic from p toward q. The component of q
// across p's outward radial is S_q sin D, along it C_p S_q cos D - S_p C_q (D = theta_q -
// theta_p). atan2(0, 0) = 0 when q = p.
template <class T>
T bearing(T K, Polar<T> p, Polar<T> q) {
    using std::atan2, std::cos, std::sin;
    const T dth = q.theta - p.theta;
    const T sq = S_K(K, q.r);
    const T along = dot2(C_K(K, p.r) * sq, cos(dth), -S_K(K, p.r), C_K(K, q.r));
    const T across = sq * sin(dth);
    return wrap_pi(p.theta + atan2(across, along));
}

// ---- the paper's four solutions --------------------------------------------------------------

// (a) A vertex's global position from the body centre, the body's facing (carried frame) and
//     the local polar vertex (rho, phi from the facing).
template <class T>
Polar<T> vertex_position(T K, Polar<T> centre, T facing, Polar<T> local) {
    return walk_end(K, centre, facing + local.theta, local.r);
}

// (b) An edge: its length and the angle at O between its end points' position vectors.
template <class T>
struct Edge {
    T length{}, angle{};
};
template <class T>
Edge<T> edge(T K, Polar<T> p, Polar<T> q) {
    return {distance(K, p, q), wrap_pi(q.theta - p.theta)};
}

// (c) Points along the edge p -> q at tessellation level n: n segments, n + 1 points, at
//     fractions k/n of the length (k = 0 .. n), by the generalised slerp of design.md
//         X(t) = (S_K((1 - t) d) P + S_K(t d) Q) / S_K(d),
//     with the ratios written as (1 - t) Sf(K ((1-t)d)^2) / Sf(K d^2), which has no 0/0 at
//     d = 0. For antipodal ends on the sphere (S_K(d) = 0: every great circle through them is
//     a geodesic) the edge follows the one through p's radial line. out(k, Polar) is called
//     for each point.
// Whether an edge of length d (sfd = Sf(K d^2)) has antipodal ends on the sphere: S_K(d) ~ 0
// with d near pi/sqrt K, not merely d ~ 0. The slerp's weights divide by S_K(d) and cannot be
// used there.
template <class T>
bool antipodal_edge(T K, T d, T sfd) {
    return K > T(0) && K * d * d > T(2) && sfd * d <= num<T>(1e-4);
}
template <class T, class Out>
void edge_points(T K, Polar<T> p, Polar<T> q, int n, Out&& out) {
    const T d = distance(K, p, q);
    const T sfd = Sf(K * d * d);
    if (antipodal_edge(K, d, sfd)) {
        const T heading = p.r > T(0) ? p.theta : q.theta;
        out(0, p);
        for (int k = 1; k < n; ++k) out(k, walk(K, p, heading, d * T(k) / T(n)).end);
        out(n, q);
        return;
    }
    const Vec3<T> P = to_vec(K, p), Q = to_vec(K, q);
    out(0, p);
    // The same arithmetic as t = T(k)/T(n), a = u Sf(...) / sfd, but in fixed point without a
    // 64-bit divide per point: the fractions are carried from k to k, and sfd's reciprocal is
    // taken once per edge (the quotients are bit for bit those of operator/).
    if (n > 1 && n < 32768) {
        Fractions<T> f(n);
        const auto by_sfd = divisor(sfd);
        for (int k = 1; k < n; ++k) {
            f.next();
            const T t = f.t(k), u = f.u(k);
            const T a = by_sfd(u * Sf(K * (u * d) * (u * d)));
            const T b = by_sfd(t * Sf(K * (t * d) * (t * d)));
            out(k, to_polar(K, Vec3<T>{dot2(a, P.w, b, Q.w), dot2(a, P.x, b, Q.x), dot2(a, P.y, b, Q.y)}));
        }
    } else {
        for (int k = 1; k < n; ++k) {
            const T t = T(k) / T(n), u = T(n - k) / T(n);
            const T a = u * Sf(K * (u * d) * (u * d)) / sfd;
            const T b = t * Sf(K * (t * d) * (t * d)) / sfd;
            out(k, to_polar(K, Vec3<T>{dot2(a, P.w, b, Q.w), dot2(a, P.x, b, Q.x), dot2(a, P.y, b, Q.y)}));
        }
    }
    out(n, q);
}

// (d) Moving a body centre distance d along its direction of travel: the new centre, the
//     direction of travel carried along the geodesic, and the facing carried with it (the
//     paper's corollary: a non-rotating body keeps its angle to its path).
template <class T>
struct Pose {
    Polar<T> centre;
    T travel{};  // direction of travel, carried frame
    T facing{};  // carried frame
};
template <class T>
Pose<T> move(T K, Pose<T> pose, T d) {
    const Walk<T> w = walk(K, pose.centre, pose.travel, d);
    return {w.end, w.heading, wrap_pi(pose.facing + w.turn)};
}

// ---- a rigid body in the 3-vector model --------------------------------------------------

// The rigid motion that takes a body's local frame (its centre at O, its facing along +x) to
// where the body is: a point given by its local 3-vector L = to_vec(K, (rho, phi)) lands at
// motion * L. It is walk_end's triangle as a matrix, built once per body and frame: with
// alpha = facing - theta_c (the facing against the centre's outward radial),
//   (w, x', y') = (C L_w - K S (cos alpha L_x - sin alpha L_y),
//                  S L_w + C (cos alpha L_x - sin alpha L_y),  sin alpha L_x + cos alpha L_y)
// for S = S_K(r_c), C = C_K(r_c), then (x', y') turned by theta_c. So a vertex costs nine
// products, not walk_end's sines, cosines, curvature functions, square root and atan2.
template <class T>
struct Motion {
    T m[3][3];  // rows w, x, y; columns L_w, L_x, L_y
    Vec3<T> operator()(const Vec3<T>& L) const {
        return {dot3(m[0][0], L.w, m[0][1], L.x, m[0][2], L.y), dot3(m[1][0], L.w, m[1][1], L.x, m[1][2], L.y),
                dot3(m[2][0], L.w, m[2][1], L.x, m[2][2], L.y)};
    }
};
// M(L) for many L, the same bits as M(L). In fixed point, where every entry of M is below 2^14
// in magnitude (`small`, checked once per body), without dot3's overflow tests: each product
// is then below 2^30 2^31 = 2^61 and a row's sum below 3 2^61 < 2^63, so it cannot overflow,
// and rounding it and saturating to 32 bits gives what dot3 gives (dot3's early clamp at
// 2^62 - 2^15 clamps what saturation clamps too).
template <class T>
struct MotionApply {
    explicit MotionApply(const Motion<T>& m) : M(m) {}
    Vec3<T> operator()(const Vec3<T>& L) const { return M(L); }
    void operator()(const Vec3<T>* L, Vec3<T>* out, std::size_t n) const {
        for (std::size_t i = 0; i < n; ++i) out[i] = M(L[i]);
    }
    const Motion<T>& M;
};
template <>
struct MotionApply<fixed> {
    static constexpr int64_t kLim = int64_t{1} << 30;  // 2^14 in Q16.16
    static bool below(fixed v) { return static_cast<uint64_t>(v.raw() + kLim) < uint64_t{2 * kLim}; }
    explicit MotionApply(const Motion<fixed>& m) : M(m) {
        for (const auto& row : m.m)
            for (fixed v : row) small = small && below(v);
    }
    [[gnu::always_inline]] Vec3<fixed> operator()(const Vec3<fixed>& L) const { return small ? fast(L) : M(L); }
    // M(L[i]) for n vertices, the same bits. The test for `small` is out of the loop, and so is
    // the saturation: the loop keeps each row's 32-bit truncation and ORs together whether any
    // did not fit, and only then (never, in the scenes) is the loop done again, saturating. So
    // its body has no branch: three multiply-adds a row (aarch64 smaddl). Where the first row
    // is (1, 0, 0) (the plane, K = 0, where every w is 1; or a body centred at O) w is L_w,
    // which is that row's rounded sum exactly, and is copied.
    void operator()(const Vec3<fixed>* L, Vec3<fixed>* out, std::size_t n) const {
        if (!small) {
            for (std::size_t i = 0; i < n; ++i) out[i] = M(L[i]);
            return;
        }
        const bool w_is_Lw = M.m[0][0].raw() == fixed::one_raw && M.m[0][1].raw() == 0 && M.m[0][2].raw() == 0;
        const uint64_t wide = w_is_Lw ? batch<true>(L, out, n) : batch<false>(L, out, n);
        if ((wide >> 32) != 0)
            for (std::size_t i = 0; i < n; ++i) out[i] = fast(L[i]);
    }
    template <bool WIsLw>
    [[gnu::always_inline]] uint64_t batch(const Vec3<fixed>* L, Vec3<fixed>* out, std::size_t n) const {
        const Motion<fixed> m = M;  // a copy, in registers: out[i] could alias M
        uint64_t wide = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const int64_t x = row(m.m[1], L[i]), y = row(m.m[2], L[i]);
            const int64_t w = WIsLw ? L[i].w.raw() : row(m.m[0], L[i]);
            wide |= (WIsLw ? 0 : biased(w)) | biased(x) | biased(y);
            out[i] = {fixed::from_raw(static_cast<int32_t>(w)), fixed::from_raw(static_cast<int32_t>(x)),
                      fixed::from_raw(static_cast<int32_t>(y))};
        }
        return wide;
    }
    [[gnu::always_inline]] static int64_t row(const fixed* m, const Vec3<fixed>& L) {
        int64_t s = (int64_t{1} << 15) + int64_t{m[0].raw()} * L.w.raw();  // rounded to nearest, as dot3
        s += int64_t{m[1].raw()} * L.x.raw();
        s += int64_t{m[2].raw()} * L.y.raw();
        return s >> 16;
    }
    // v + 2^31 is below 2^32 exactly when v fits in 32 bits.
    static uint64_t biased(int64_t v) { return static_cast<uint64_t>(v) + (uint64_t{1} << 31); }
    [[gnu::always_inline]] Vec3<fixed> fast(const Vec3<fixed>& L) const {
        const int64_t w = row(M.m[0], L), x = row(M.m[1], L), y = row(M.m[2], L);
        if (((biased(w) | biased(x) | biased(y)) >> 32) != 0)  // one does not: dot3 saturates it
            return {fixed::from_raw(fx::detail::saturate32(w)), fixed::from_raw(fx::detail::saturate32(x)),
                    fixed::from_raw(fx::detail::saturate32(y))};
        return {fixed::from_raw(static_cast<int32_t>(w)), fixed::from_raw(static_cast<int32_t>(x)),
                fixed::from_raw(static_cast<int32_t>(y))};
    }
    const Motion<fixed>& M;
    bool small = true;
};

template <class T>
Motion<T> body_motion(T K, Polar<T> centre, T facing) {
    using std::cos, std::sin;
    const T alpha = facing - centre.theta;
    const T ca = cos(alpha), sa = sin(alpha), ct = cos(centre.theta), st = sin(centre.theta);
    const T S = S_K(K, centre.r), C = C_K(K, centre.r);
    const T ks = K * S, cca = C * ca, csa = C * sa;
    Motion<T> M;
    M.m[0][0] = C, M.m[0][1] = -(ks * ca), M.m[0][2] = ks * sa;
    M.m[1][0] = ct * S, M.m[1][1] = dot2(ct, cca, -st, sa), M.m[1][2] = dot2(-ct, csa, -st, ca);
    M.m[2][0] = st * S, M.m[2][1] = dot2(st, cca, ct, sa), M.m[2][2] = dot2(-st, csa, ct, ca);
    return M;
}

// ---- projections ---------------------------------------------------------------------------

// Screen radius rho = f_K(r) of a point at distance r from O, continuous in K; at K = 0 every
// projection is rho = r. Multiply by (disk radius in px) / (limit radius R) for pixels.
enum class Projection {
    azimuthal_equidistant,  // the paper's: rho = r
    stereographic,          // rho = 2 T_K(r/2); the Poincare disk when K < 0
    gnomonic,               // rho = T_K(r); Beltrami-Klein when K < 0 (geodesics are straight)
    orthographic,           // rho = S_K(r)
    lambert_equal_area,     // rho = 2 S_K(r/2)
};
inline constexpr Projection kProjections[] = {
    Projection::azimuthal_equidistant, Projection::stereographic, Projection::gnomonic,
    Projection::orthographic, Projection::lambert_equal_area};
inline const char* projection_name(Projection p) {
    switch (p) {
        case Projection::azimuthal_equidistant: return "equidistant";
        case Projection::stereographic: return "stereographic";
        case Projection::gnomonic: return "gnomonic";
        case Projection::orthographic: return "orthographic";
        case Projection::lambert_equal_area: return "lambert";
    }
    return "?";
}

// visible = false where a projection cannot show the point: the gnomonic and orthographic
// views of the far hemisphere (C_K(r) <= 0, resp. < 0), the stereographic view of the
// antipode. The caller clips those (and anything beyond the screen).
template <class T>
struct Projected {
    T rho{};
    bool visible = true;
};
template <class T>
Projected<T> project(T K, T r, Projection p) {
    switch (p) {
        case Projection::azimuthal_equidistant: return {r, true};
        case Projection::stereographic: {
            const T h = r / T(2), c = C_K(K, h);
            if (c <= num<T>(1e-6)) return {T(0), false};  // at (or a rounding short of) the antipode
            return {T(2) * S_K(K, h) / c, true};
        }
        case Projection::gnomonic: {
            const T c = C_K(K, r);
            if (c <= num<T>(1e-6)) return {T(0), false};  // the far hemisphere
            return {S_K(K, r) / c, true};
        }
        case Projection::orthographic:
            return {S_K(K, r), !(C_K(K, r) < T(0))};
        case Projection::lambert_equal_area: return {T(2) * S_K(K, r / T(2)), true};
    }
    return {r, true};
}

// A screen point: centre (cx, cy) in px, `scale` px per unit of rho.
template <class T>
struct ScreenPoint {
    T x{}, y{};
};
template <class T>
ScreenPoint<T> to_screen(T rho, T theta, T cx, T cy, T scale) {
    using std::cos, std::sin;
    return {cx + scale * rho * cos(theta), cy - scale * rho * sin(theta)};
}

// ---- edges straight to the projection plane --------------------------------------------------

// (c, for drawing) The points of edge_points, projected: out(k, visible, X, Y) with
// (X, Y) = rho (cos theta, sin theta), the point in the projection plane relative to O
// (pixels: cx + scale X, cy - scale Y). The interior points skip the polar reading: for the
// 3-vector (w, x, y) = (C_K(r), S_K(r) cos theta, S_K(r) sin theta), rho(r) / S_K(r) depends on
// w and S^2 = x^2 + y^2 alone, so (X, Y) = (x, y) rho/S with, for g = 2 / (1 + w) (w >= 0),
//   equidistant    r / S = g ATf(K S^2 g^2 / 4)     (arc_K without its square root)
//   stereographic  2 T_K(r/2) / S = g
//   Lambert        2 S_K(r/2) / S = sqrt(g)
// and no atan2, hypot, sine or cosine is needed per point. The end points, points past the
// sphere's equator (w < 0), points too far out for S^2 in the scalar, antipodal edges, and the
// gnomonic and orthographic projections take the polar path (project, then the bearing's cosine
// and sine): in fixed point 1/w near the gnomonic horizon, and x, y read straight off the
// 3-vector in the orthographic view, were measured less accurate than the polar path
// (tests/perf/test_fast_paths.cpp holds the others to the polar path's error).
// The slerp's weights a_k = S_K((n - k) delta) / S_K(d), b_k = S_K(k delta) / S_K(d) for
// delta = d / n, by the recurrence of design.md: with sigma_k = S_K(k delta) / delta,
//   sigma_0 = 0, sigma_1 = Sf(K delta^2), sigma_{k+1} = 2 C_K(delta) sigma_k - sigma_{k-1},
// a_k = sigma_{n-k} / sigma_n, b_k = sigma_k / sigma_n: no trigonometry, no table and no
// division per point, and no 0/0 for short edges. Fixed point only, in 64-bit integers with
// 30 fractional bits (fx::slerp_sigmas), one reciprocal per edge. prepare() is false where the
// caller should use the direct form instead: floating point, fewer than 4 or more than 64 segments,
// |K delta^2| > 2, or an edge near the sphere's antipode, where sigma_n is small and the
// weights large.
template <class T>
class SlerpWeights {
public:
    // Floating point keeps the direct form: the recurrence in float lost accuracy near the
    // gnomonic horizon and in the orthographic view (tests/perf/test_fast_paths.cpp), and
    // double's libm Sf is not the cost it is in fixed point's 64-bit emulation on 32-bit ARM.
    bool prepare(T, T, int) { return false; }
    T a(int) const { return T(0); }
    T b(int) const { return T(0); }
};
template <>
class SlerpWeights<fixed> {
public:
    bool prepare(fixed K, fixed d, int n) {
        // From 4 segments on: below, the direct form's two table lookups per point cost less
        // than the recurrence's set-up per edge.
        if (n < 4 || n > kMax) return false;
        if (!fx::slerp_sigmas(K, d, n, sigma_)) return false;
        const int64_t top = sigma_[n];
        if (top < (int64_t{1} << 27)) return false;  // sigma_n < 1/8
        for (int k = 1; k < n; ++k)
            if (sigma_[k] >= 2 * top || sigma_[k] <= -2 * top) return false;
        n_ = n;
        // top 2^e in [2^31, 2^32): inv ~ 2^(62 + e) / top.
        e_ = std::countl_zero(static_cast<uint64_t>(top)) - 32;
        inv_ = fx::detail::recip_q62(static_cast<uint32_t>(e_ >= 0 ? top << e_ : top >> -e_));
        return true;
    }
    fixed a(int k) const { return weight(sigma_[n_ - k]); }
    fixed b(int k) const { return weight(sigma_[k]); }

private:
    // sigma / sigma_n in Q16.16: (sigma 2^e) (2^(62+e) / top) / 2^(62 + 2e - ...) -> x' inv >> 46.
    fixed weight(int64_t sig) const {
        const int64_t x = e_ >= 0 ? sig * (int64_t{1} << e_) : sig >> -e_;  // |x| < 2^33
        const uint64_t m = static_cast<uint64_t>(x < 0 ? -x : x);
        const uint64_t q = (m * inv_ + (uint64_t{1} << 45)) >> 46;
        return fixed::from_raw(static_cast<int32_t>(x < 0 ? -static_cast<int64_t>(q) : static_cast<int64_t>(q)));
    }
    static constexpr int kMax = 64;
    int64_t sigma_[kMax + 1];
    uint64_t inv_ = 0;
    int e_ = 0;
    int n_ = 0;
};

// The weights (a_k, b_k), k = 1 .. n - 1, of the generalised slerp along an edge of length d
// at level n (edge_projected's, in the same arithmetic: the recurrence in fixed point where
// SlerpWeights takes it, else the direct form), written to ab[2 (k - 1)], ab[2 (k - 1) + 1].
// They depend on K, d and n alone, so a rigid body keeps them until K changes. False, and
// nothing written, for an edge whose ends are antipodal on the sphere (S_K(d) ~ 0), where the
// caller walks the edge instead (edge_projected does).
template <class T>
bool slerp_weights(T K, T d, int n, T* ab) {
    const T sfd = Sf(K * d * d);
    if (antipodal_edge(K, d, sfd)) return false;
    SlerpWeights<T> w;
    if (w.prepare(K, d, n)) {
        for (int k = 1; k < n; ++k) ab[2 * (k - 1)] = w.a(k), ab[2 * (k - 1) + 1] = w.b(k);
    } else if (n > 1 && n < 32768) {
        // b_k = t Sf(K (t d)^2) / sfd for t = k/n, and a_k = b_{n-k}: u = (n - k)/n rounds
        // exactly as t does at n - k (Fractions), so each weight is computed once.
        Fractions<T> f(n);
        const auto by_sfd = divisor(sfd);
        for (int k = 1; k < n; ++k) {
            f.next();
            const T t = f.t(k);
            const T b = by_sfd(t * Sf(K * (t * d) * (t * d)));
            ab[2 * (k - 1) + 1] = b;
            ab[2 * (n - k - 1)] = b;  // a_{n-k}
        }
    }
    return true;
}

template <class T>
struct ProjectedPoint {
    bool visible = true;
    T X{}, Y{};
};
template <class T>
ProjectedPoint<T> project_polar(T K, Polar<T> p, Projection proj) {
    using std::cos, std::sin;
    const Projected<T> pr = project(K, p.r, proj);
    if (!pr.visible) return {false, T(0), T(0)};
    return {true, pr.rho * cos(p.theta), pr.rho * sin(p.theta)};
}
// The equidistant view of a 3-vector (w, x, y) is (x, y) E(w): a point at distance r has
// w = C_K(r) and (x, y) = S_K(r) (cos theta, sin theta), and E(w) = r / S_K(r) depends on w
// alone, whatever K: acos(w) / sqrt(1 - w^2) below 1, acosh(w) / sqrt(w^2 - 1) above, with
// (1 - w)(1 + w) for 1 - w^2 (no cancellation near w = 1) and its series 1 - d/3 + 2d^2/15 -
// 2d^3/35 (d = w - 1) within 1e-4 of 1 (where it is exact to 1e-16). Floating point's; fixed
// point tabulates the same function (fx::equidistant_ratio_q30).
template <class T>
T equidistant_ratio(T w) {
    using std::acos, std::acosh, std::sqrt;
    const T d = w - T(1);
    if (d < T(1e-4) && d > T(-1e-4)) return T(1) + d * (T(-1) / T(3) + d * (T(2) / T(15) - d * (T(2) / T(35))));
    if (d < T(0)) return acos(w) / sqrt(-d * (T(1) + w));
    return acosh(w) / sqrt(d * (w + T(1)));
}
template <class T>
ProjectedPoint<T> project_vec_general(T K, Vec3<T> v, Projection proj) {
    using std::sqrt;
    const T big = num<T>(100);
    if (v.w < T(0) || v.x > big || v.x < -big || v.y > big || v.y < -big)
        return project_polar(K, to_polar(K, v), proj);
    T f;
    switch (proj) {
        case Projection::azimuthal_equidistant: {
            if constexpr (std::is_floating_point_v<T>) {
                f = equidistant_ratio(v.w);
            } else {
                const T g = quotient(T(2), T(1) + v.w);
                const T s2 = dot2(v.x, v.x, v.y, v.y);
                f = mul_ATf(g, quarter(K * s2 * g * g));
            }
            break;
        }
        case Projection::stereographic: f = quotient(T(2), T(1) + v.w); break;
        case Projection::lambert_equal_area: f = sqrt(quotient(T(2), T(1) + v.w)); break;
        default: return project_polar(K, to_polar(K, v), proj);
    }
    return {true, v.x * f, v.y * f};
}
// (Fixed point's equidistant view, the paper's and the kiosk's, takes fx::equidistant_xy inline:
// the common case is a few dozen integer instructions, worth no call.)
template <class T>
[[gnu::always_inline]] inline ProjectedPoint<T> project_vec(T K, Vec3<T> v, Projection proj) {
    if constexpr (std::is_same_v<T, fixed>) {
        const int32_t big = 100 << 16;
        T X, Y;
        if (proj == Projection::azimuthal_equidistant && v.w.raw() >= 0 && v.x.raw() <= big && v.x.raw() >= -big &&
            v.y.raw() <= big && v.y.raw() >= -big && fx::equidistant_xy(K, v.w, v.x, v.y, X, Y))
            return {true, X, Y};
    }
    return project_vec_general(K, v, proj);
}
// With the end points' 3-vectors P = to_vec(K, p), Q = to_vec(K, q) given (a polygon's vertices
// are each an end of two edges: the caller computes them once), and the start point left out
// when `with_start` is false (it is the previous edge's end).
template <class T, class Out>
void edge_projected(T K, Polar<T> p, Polar<T> q, const Vec3<T>& P, const Vec3<T>& Q, int n, Projection proj,
                    bool with_start, Out&& out) {
    const T d = distance(K, p, q);
    const T sfd = Sf(K * d * d);
    auto polar = [&](int k, Polar<T> x) {
        if (k == 0 && !with_start) return;
        const ProjectedPoint<T> pp = project_polar(K, x, proj);
        out(k, pp.visible, pp.X, pp.Y);
    };
    if (antipodal_edge(K, d, sfd)) {  // as edge_points
        const T heading = p.r > T(0) ? p.theta : q.theta;
        polar(0, p);
        for (int k = 1; k < n; ++k) polar(k, walk(K, p, heading, d * T(k) / T(n)).end);
        polar(n, q);
        return;
    }
    polar(0, p);
    auto point = [&](int k, T a, T b) {
        const ProjectedPoint<T> pp =
            project_vec(K, Vec3<T>{dot2(a, P.w, b, Q.w), dot2(a, P.x, b, Q.x), dot2(a, P.y, b, Q.y)}, proj);
        out(k, pp.visible, pp.X, pp.Y);
    };
    SlerpWeights<T> w;
    if (w.prepare(K, d, n)) {
        for (int k = 1; k < n; ++k) point(k, w.a(k), w.b(k));
    } else if (n > 1 && n < 32768) {
        Fractions<T> f(n);
        const auto by_sfd = divisor(sfd);
        for (int k = 1; k < n; ++k) {
            f.next();
            const T t = f.t(k), u = f.u(k);
            point(k, by_sfd(u * Sf(K * (u * d) * (u * d))), by_sfd(t * Sf(K * (t * d) * (t * d))));
        }
    }
    polar(n, q);
}
// The same points from the end points' 3-vectors and the edge's slerp_weights (ab, n - 1
// pairs), the end points projected from their 3-vectors as well: no polar coordinates at all.
template <class T, class Out>
void edge_projected(T K, const Vec3<T>& P, const Vec3<T>& Q, const T* ab, int n, Projection proj, bool with_start,
                    Out&& out) {
    auto point = [&](int k, const Vec3<T>& v) {
        const ProjectedPoint<T> pp = project_vec(K, v, proj);
        out(k, pp.visible, pp.X, pp.Y);
    };
    if (with_start) point(0, P);
    for (int k = 1; k < n; ++k) {
        const T a = ab[2 * (k - 1)], b = ab[2 * (k - 1) + 1];
        point(k, Vec3<T>{dot2(a, P.w, b, Q.w), dot2(a, P.x, b, Q.x), dot2(a, P.y, b, Q.y)});
    }
    point(n, Q);
}
template <class T, class Out>
void edge_projected(T K, Polar<T> p, Polar<T> q, int n, Projection proj, Out&& out) {
    edge_projected(K, p, q, to_vec(K, p), to_vec(K, q), n, proj, true, out);
}

}  // namespace noneuclid::geo
