// What filling and texturing a body needs of the geometry (render/fill.hpp): the way back from
// the screen to the body's own frame, and whether a point lies inside a geodesic polygon.
//  - unproject: the inverse of each projection (its formulas are in geometry/projection.hpp),
//    from a point (X, Y) of the projection plane to its 3-vector, where the projection shows one;
//  - body_motion_inverse: the inverse of geo::body_motion, which takes a point's 3-vector to the
//    body's local frame (its centre at O, its facing along +x);
//  - point_in_polygon: the even-odd inside test of a geodesic polygon of any shape (star-shaped
//    or not, convex or not), by signs of determinants in the 3-vector model, for every K.
// docs/rendering.md ("Filled and textured bodies") explains the choices.
#pragma once

#include <cmath>
#include <cstddef>

#include "geometry/collision.hpp"
#include "geometry/model.hpp"
#include "geometry/motion.hpp"
#include "geometry/projection.hpp"

namespace noneuclid::geo {

// The 3-vector whose projection is (X, Y), in world units of the projection plane (the screen
// point minus the centre, over the scale, y up), for every K: each projection's own inverse
// (geometry/projection.hpp, checked with <p, p> = 1 and against the forward projection in the
// tests); `valid` is false where the projection shows no point.
template <class T>
Unprojected<T> unproject(T K, T X, T Y, Projection proj) {
    return with_projection(proj, [&](auto P) { return decltype(P)::unproject(K, X, Y); });
}

// The inverse of body_motion(K, centre, facing): a point's 3-vector p lands at Mi p in the body's
// local frame. body_motion is R(theta_c) T(r_c) R(alpha); this is R(-alpha) T(-r_c) R(-theta_c),
// with T(-r) = [[C, K S, 0], [-S, C, 0], [0, 0, 1]].
template <class T>
Motion<T> body_motion_inverse(T K, Polar<T> centre, T facing) {
    using std::cos, std::sin;
    const T alpha = facing - centre.theta;
    const T ca = cos(alpha), sa = sin(alpha), ct = cos(centre.theta), st = sin(centre.theta);
    const T S = S_K(K, centre.r), C = C_K(K, centre.r);
    const T ks = K * S, cca = C * ca, csa = C * sa;
    Motion<T> M;
    M.m[0][0] = C, M.m[0][1] = ks * ct, M.m[0][2] = ks * st;
    M.m[1][0] = -(ca * S), M.m[1][1] = dot2(cca, ct, -sa, st), M.m[1][2] = dot2(cca, st, sa, ct);
    M.m[2][0] = sa * S, M.m[2][1] = dot2(-csa, ct, -ca, st), M.m[2][2] = dot2(-csa, st, ca, ct);
    return M;
}

// Whether q lies inside the geodesic polygon v[0..n) (the body's outline, any shape; its
// vertices in any order), by the even-odd rule. The polygon and q are read in the gnomonic
// chart about the point c (where every geodesic is a straight line), and q is inside when a ray
// from q crosses the outline an odd number of times: PNPOLY, with each comparison the sign of a
// determinant (geo::orientation, exact in fixed point). The ray leaves q toward the direction E,
// a tangent vector at c (a body's: its facing, E = M (0, 1, 0)): vertex a is on the ray's left
// when det[q, E, a] > 0, and an edge a -> b crossing the ray's line from right to left crosses
// the ray itself when det[a, b, q] > 0 (from left to right, when < 0).
// Needs the polygon within an open hemisphere about c (on the sphere; a body's outline is, its
// vertices at most kBodyRadius = 1.4 < pi/2 from its centre); q outside that hemisphere is outside.
// A point on the outline may be found either way.
template <class T>
bool point_in_polygon(T K, const Vec3<T>& c, const Vec3<T>& E, const Vec3<T>* v, std::size_t n, const Vec3<T>& q) {
    if (K > T(0) && !(dot2(c.w, q.w, K, dot2(c.x, q.x, c.y, q.y)) > T(0))) return false;
    bool inside = false;
    bool left = orientation(q, E, v[n - 1]) > 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3<T>& a = v[i == 0 ? n - 1 : i - 1];
        const Vec3<T>& b = v[i];
        const bool b_left = orientation(q, E, b) > 0;
        if (b_left != left) {
            const int o = orientation(a, b, q);
            if (b_left ? o > 0 : o < 0) inside = !inside;
        }
        left = b_left;
    }
    return inside;
}

}  // namespace noneuclid::geo
