// Collision detection in curved space, for every K from -1 through 0 to +1: the game's broad
// phase (centres closer than the sum of bounding radii, by the haversine distance of
// geometry/model.hpp) and its narrow phase, in the 3-vector model.
//
// In the model a geodesic is the model's surface cut by a plane through the origin of R^3 (at
// K = 0 the surface is the plane w = 1, and the cut a straight line), so which side of the
// geodesic through a and b a point p lies on is the sign of det[a, b, p]: positive on the left
// of a -> b (counter-clockwise as seen on screen). Every predicate below is a few such signs:
// no angle, no division, no acos.
//  - point_in_star: p inside a polygon that is star-shaped about its centre c (its vertices
//    counter-clockwise around c, each wedge c, v_i, v_i+1 narrower than pi): p lies in the
//    wedge of some edge and on c's side of that edge. The game's bodies (ship, asteroids) are
//    such polygons by construction (world/game_shapes.hpp).
//  - segments_cross: two geodesic segments meet (touching counts): each one's ends are not
//    strictly on one side of the other's geodesic.
//  - polygons_overlap: two star polygons share a point: an edge of one crosses an edge of the
//    other, or one holds a vertex of the other (the whole of it, when no edges cross).
// On the sphere a plane cuts two antipodal points out of every other geodesic; the predicates
// read the near one, which needs every point involved within an open hemisphere: so the
// bodies tested must be close (the broad phase) and small (each within a quarter of the sphere's
// circumference of its centre, which the game's settings check).
//
// The signs are exact for the vectors given: in fixed point the determinant is computed in
// 64-bit integers (each vector first scaled by a power of two so that no product overflows,
// which does not change a sign), so every machine gives the same answer bit for bit; in
// floating point it is computed in double.
#pragma once

#include <cstddef>
#include <cstdint>

#include "geometry/model.hpp"
#include "geometry/motion.hpp"

namespace noneuclid::geo {

// The sign of det[a, b, p] (rows): +1, 0 or -1.
template <class T>
int orientation(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& p) {
    const double aw = static_cast<double>(a.w), ax = static_cast<double>(a.x), ay = static_cast<double>(a.y);
    const double bw = static_cast<double>(b.w), bx = static_cast<double>(b.x), by = static_cast<double>(b.y);
    const double pw = static_cast<double>(p.w), px = static_cast<double>(p.x), py = static_cast<double>(p.y);
    const double d = aw * (bx * py - by * px) - ax * (bw * py - by * pw) + ay * (bw * px - bx * pw);
    return (d > 0) - (d < 0);
}

namespace detail {
// v's raw components, shifted right so that each is below 2^20 in magnitude.
struct Raw3 {
    int64_t w, x, y;
};
inline Raw3 reduced(const Vec3<fixed>& v) {
    auto mag = [](int32_t r) { return r < 0 ? -static_cast<int64_t>(r) : static_cast<int64_t>(r); };
    int64_t m = mag(v.w.raw());
    if (mag(v.x.raw()) > m) m = mag(v.x.raw());
    if (mag(v.y.raw()) > m) m = mag(v.y.raw());
    int s = 0;
    while ((m >> s) >= (int64_t{1} << 20)) ++s;
    return {int64_t{v.w.raw()} >> s, int64_t{v.x.raw()} >> s, int64_t{v.y.raw()} >> s};
}
}  // namespace detail

// Fixed point: exact in 64 bits. With every component below 2^20, each product is below 2^40,
// each 2x2 minor below 2^41, and the determinant below 3 2^61 < 2^63.
inline int orientation(const Vec3<fixed>& a, const Vec3<fixed>& b, const Vec3<fixed>& p) {
    const detail::Raw3 A = detail::reduced(a), B = detail::reduced(b), P = detail::reduced(p);
    const int64_t d = A.w * (B.x * P.y - B.y * P.x) - A.x * (B.w * P.y - B.y * P.w) + A.y * (B.w * P.x - B.x * P.w);
    return (d > 0) - (d < 0);
}

// A rigid body's outline as 3-vectors: its centre's into c, and each local vertex (rho, phi
// from the facing) moved to where the body is (geometry/motion.hpp), as drawing moves them.
template <class T>
void body_vectors(T K, Polar<T> centre, T facing, const Polar<T>* local, std::size_t n, Vec3<T>& c, Vec3<T>* out) {
    const Motion<T> m = body_motion(K, centre, facing);
    for (std::size_t i = 0; i < n; ++i) out[i] = m(to_vec(K, local[i]));
    c = to_vec(K, centre);
}

// Whether p lies inside (or on the boundary of) the star polygon v[0..n) about its centre c.
template <class T>
bool point_in_star(const Vec3<T>& c, const Vec3<T>* v, std::size_t n, const Vec3<T>& p) {
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3<T>& a = v[i];
        const Vec3<T>& b = v[(i + 1) % n];
        if (orientation(c, a, p) >= 0 && orientation(c, b, p) <= 0 && orientation(a, b, p) >= 0) return true;
    }
    return false;
}

// Whether the geodesic segments a-b and c-d meet (touching counts). Two segments on one
// geodesic are reported apart: where they overlap, an end of one lies on the other, and the
// polygon edge that meets that end from off the geodesic touches there, which counts, so the
// polygon tests below miss nothing.
template <class T>
bool segments_cross(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d) {
    const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
    if (o1 == 0 && o2 == 0) return false;
    return o1 * o2 <= 0 && orientation(c, d, a) * orientation(c, d, b) <= 0;
}

// Whether star polygons A (centre ca, n vertices) and B (centre cb, m vertices) overlap.
template <class T>
bool polygons_overlap(const Vec3<T>& ca, const Vec3<T>* a, std::size_t n, const Vec3<T>& cb, const Vec3<T>* b,
                      std::size_t m) {
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < m; ++j)
            if (segments_cross(a[i], a[(i + 1) % n], b[j], b[(j + 1) % m])) return true;
    return point_in_star(cb, b, m, a[0]) || point_in_star(ca, a, n, b[0]);
}

// Whether the segment p-q (a bullet's last step) meets the star polygon: q inside, or the
// segment crossing an edge.
template <class T>
bool segment_meets_star(const Vec3<T>& c, const Vec3<T>* v, std::size_t n, const Vec3<T>& p, const Vec3<T>& q) {
    if (point_in_star(c, v, n, q)) return true;
    for (std::size_t i = 0; i < n; ++i)
        if (segments_cross(v[i], v[(i + 1) % n], p, q)) return true;
    return false;
}

}  // namespace noneuclid::geo
