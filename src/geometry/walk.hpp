// Walking along geodesics: the paper's triangle O - P - Q solved in the 3-vector model (walk,
// walk_end, bearing), and three of the paper's four solutions built on it: (a) a vertex's
// position, (b) an edge's length and angle, (d) moving a body. (The fourth, (c), the points
// along an edge, is geometry/edges.hpp.) Conventions: geometry/geometry.hpp.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "geometry/fx/coast.hpp"
#include "geometry/model.hpp"

namespace noneuclid::geo {

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
// end's bearing from O is atan2(Q_y, Q_x) (docs/design.md: no acos, no division, fine at r = 0).
// The sines and cosines and Q itself are walk_triangle's, which walk_end shares (always
// inlined: the walk's values stay in registers).
template <class T>
struct WalkTriangle {
    T cd, sd;          // cos delta, sin delta
    T sa, ca, sb, cb;  // S_K(r_p), C_K(r_p), S_K(b), C_K(b)
    T qw, qx, qy;      // Q, in the frame rotated so that p lies on +x
};
template <class T>
[[gnu::always_inline]] inline WalkTriangle<T> walk_triangle(T K, Polar<T> p, T heading, T b) {
    using std::cos, std::sin;
    const T delta = heading - p.theta;
    WalkTriangle<T> t;
    t.cd = cos(delta), t.sd = sin(delta);
    t.sa = S_K(K, p.r), t.ca = C_K(K, p.r), t.sb = S_K(K, b), t.cb = C_K(K, b);
    t.qw = dot2(t.ca, t.cb, -K * t.sa, t.sb * t.cd);
    t.qx = dot2(t.sa, t.cb, t.ca * t.sb, t.cd);
    t.qy = t.sb * t.sd;
    return t;
}
template <class T>
Walk<T> walk(T K, Polar<T> p, T heading, T b) {
    using std::atan2;
    const auto [cd, sd, sa, ca, sb, cb, qw, qx, qy] = walk_triangle(K, p, heading, b);
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
    using std::atan2;
    const WalkTriangle<T> t = walk_triangle(K, p, heading, b);
    return {arc_K(K, hypot(t.qx, t.qy), t.qw), wrap_pi(p.theta + atan2(t.qy, t.qx))};
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

// ---- the paper's solutions (a), (b), (d) -----------------------------------------------------

// (a) A vertex's global position from the body centre, the body's facing (carried frame) and
//     the local polar vertex (rho, phi from the facing).
//     In fixed point the walk is the coasts' kernel (fx::coast_walk: 64-bit integers, S_K and
//     C_K in Q26, the end's bearing as a binary angle), within its domain: near the sphere's
//     antipode the end's Q16.16 components are small, and their rounding, magnified by the
//     equidistant view there, would show (docs/accuracy.md).
template <class T>
Polar<T> vertex_position(T K, Polar<T> centre, T facing, Polar<T> local) {
    if constexpr (std::is_same_v<T, fx::fixed>) {
        const fx::angle theta = fx::angle::from_radians(centre.theta);
        fx::CoastEnd e;
        if (fx::coast_walk(K, int64_t{centre.r.raw()} << 8, fx::angle::from_radians(facing + local.theta) - theta,
                           int64_t{local.r.raw()} << 8, e))
            return {fx::fixed::from_raw(fx::detail::saturate32((e.r24 + 128) >> 8)), (theta + e.bearing).to_radians()};
    }
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

}  // namespace noneuclid::geo
