// The projections of the curved plane onto the screen's plane (azimuthal about O, continuous
// in K): the screen radius of a point (project), its place in the projection plane from polar
// coordinates (project_polar) or straight from its 3-vector (project_vec), and the screen
// point.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "geometry/fx/equidistant.hpp"
#include "geometry/model.hpp"

namespace noneuclid::geo {

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

// The part of the world a projection shows: the disc r <= shown_radius, which the screen's
// limit circle frames. It is the limit radius R, except on the sphere (K > 0) where the
// projection's image of r <= R would be unbounded or folded: the gnomonic view is cut at
// 60 degrees (pi / 3 sqrt K) and the stereographic at 120 degrees (2 pi / 3 sqrt K), where
// each stretches a radial step four times as much as at the centre (1 / C_K(r)^2, resp.
// 1 / C_K(r/2)^2), and the orthographic at the equator (pi / 2 sqrt K), where it folds. Each is
// continuous in K (it is R until K reaches the cut).
template <class T>
T shown_radius(T K, T R, Projection p) {
    using std::sqrt;
    if (!(K > T(0))) return R;
    T cut;
    switch (p) {
        case Projection::gnomonic: cut = pi_v<T> / T(3) / sqrt(K); break;
        case Projection::stereographic: cut = T(2) * pi_v<T> / T(3) / sqrt(K); break;
        case Projection::orthographic: cut = pi_v<T> / T(2) / sqrt(K); break;
        default: return R;
    }
    return cut < R ? cut : R;
}
// The projected radius of the shown disc's rim (the limit circle on the screen).
template <class T>
T rim_rho(T K, T R, Projection p) {
    return project(K, shown_radius(K, R, p), p).rho;
}
// The sphere's antipode (K > 0, distance pi / sqrt K) is a point where the equidistant and
// Lambert views are singular: they draw it as a whole circle, of this projected radius
// (pi / sqrt K, resp. 2 / sqrt K). False for the other views (it is at infinity or hidden)
// and for K <= 0.
template <class T>
bool antipode_circle(T K, Projection p, T& rho) {
    using std::sqrt;
    if (!(K > T(0))) return false;
    if (p == Projection::azimuthal_equidistant) return rho = pi_v<T> / sqrt(K), true;
    if (p == Projection::lambert_equal_area) return rho = T(2) / sqrt(K), true;
    return false;
}
// Whether every geodesic a projection draws is a straight line: the gnomonic view's (great
// circles through the projection's centre plane), and every view of the plane (K = 0).
template <class T>
bool straight_geodesics(T K, Projection p) {
    return K == T(0) || p == Projection::gnomonic;
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

}  // namespace noneuclid::geo
