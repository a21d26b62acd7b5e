// The projections of the curved plane onto the screen's plane (azimuthal about O, continuous
// in K): the screen radius of a point (project), its place in the projection plane from polar
// coordinates (project_polar) or straight from its 3-vector (project_vec), and the screen
// point.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "geometry/fx/equidistant.hpp"
#include "geometry/model.hpp"

namespace noneuclid::geo {

// A projection is a type of static formulas, for every scalar T and curvature K, continuous in
// K (at K = 0 every projection is rho = r):
//   name, help                the command line's word and its line in --help
//   project(K, r)             the screen radius rho = f_K(r) of a point at distance r from O
//                             (Projected: visible false where the view cannot show it)
//   cut(K, c)                 on the sphere (K > 0): whether the view is cut short of the limit
//                             circle, at distance c (see shown_radius)
//   antipode(K, rho)          whether the view draws the sphere's antipode as a whole circle, of
//                             projected radius rho
//   straight(K)               whether every geodesic the view draws is a straight line
//   factor(K, v, f)           the view of a 3-vector v = (w, x, y) as (x, y) f, where such a factor
//                             exists and v is in its domain (w >= 0, |x|, |y| <= 100); false
//                             sends v through its polar coordinates instead
//   unproject(K, X, Y)        the 3-vector whose projection is (X, Y) (local_frame.hpp uses it)
// kProjectionTable lists them; everything that names, parses, lists or dispatches projections
// reads it, so a new projection is its formulas and one row.
template <class T>
struct Projected {
    T rho{};
    bool visible = true;
};
// A point of the projection plane taken back to the 3-vector model: `valid` is false where the
// projection shows no point (beyond the equidistant view's rim at r = pi / sqrt K, outside the
// Poincare and Klein disks, beyond the orthographic and Lambert views' rims).
template <class T>
struct Unprojected {
    bool valid = false;
    Vec3<T> p;
};

// The paper's: rho = r.
struct Equidistant {
    static constexpr const char* name = "equidistant";
    static constexpr const char* help = "azimuthal equidistant, the paper's view (rho = r)";
    template <class T>
    static Projected<T> project(T, T r) {
        return {r, true};
    }
    template <class T>
    static bool cut(T, T&) {
        return false;
    }
    template <class T>
    static bool antipode(T K, T& rho) {  // at pi / sqrt K
        using std::sqrt;
        return rho = pi_v<T> / sqrt(K), true;
    }
    template <class T>
    static bool straight(T) {
        return false;
    }
    template <class T>
    static bool factor(T K, const Vec3<T>& v, T& f);  // below: E(w) (equidistant_ratio)
    template <class T>
    static Unprojected<T> unproject(T K, T X, T Y) {  // p = (Cf(u), Sf(u) X, Sf(u) Y), u = K rho^2
        const T u = K * (X * X + Y * Y);
        if (u >= pi_v<T> * pi_v<T>) return {};  // at or past the antipode's circle
        const T s = Sf(u);
        return {true, {Cf(u), s * X, s * Y}};
    }
};
// rho = 2 T_K(r/2); the Poincare disk when K < 0.
struct Stereographic {
    static constexpr const char* name = "stereographic";
    static constexpr const char* help = "stereographic, the Poincare disc at K < 0 (rho = 2 T_K(r/2))";
    template <class T>
    static Projected<T> project(T K, T r) {
        const T h = r / T(2), c = C_K(K, h);
        if (c <= num<T>(1e-6)) return {T(0), false};  // at (or a rounding short of) the antipode
        return {T(2) * S_K(K, h) / c, true};
    }
    template <class T>
    static bool cut(T K, T& c) {  // at 120 degrees, where a radial step is stretched four times
        using std::sqrt;
        return c = T(2) * pi_v<T> / T(3) / sqrt(K), true;
    }
    template <class T>
    static bool antipode(T, T&) {
        return false;
    }
    template <class T>
    static bool straight(T) {
        return false;
    }
    template <class T>
    static bool factor(T, const Vec3<T>& v, T& f) {
        return f = quotient(T(2), T(1) + v.w), true;
    }
    template <class T>
    static Unprojected<T> unproject(T K, T X, T Y) {  // p = (1 - q, X, Y) / (1 + q), q = K rho^2 / 4
        const T q = quarter(K * (X * X + Y * Y)), d = T(1) + q;
        if (d <= num<T>(1e-6)) return {};
        return {true, {quotient(T(1) - q, d), quotient(X, d), quotient(Y, d)}};
    }
};
// rho = T_K(r); Beltrami-Klein when K < 0 (geodesics are straight).
struct Gnomonic {
    static constexpr const char* name = "gnomonic";
    static constexpr const char* help = "gnomonic, Beltrami-Klein at K < 0: geodesics are straight (rho = T_K(r))";
    template <class T>
    static Projected<T> project(T K, T r) {
        const T c = C_K(K, r);
        if (c <= num<T>(1e-6)) return {T(0), false};  // the far hemisphere
        return {S_K(K, r) / c, true};
    }
    template <class T>
    static bool cut(T K, T& c) {  // at 60 degrees, where a radial step is stretched four times
        using std::sqrt;
        return c = pi_v<T> / T(3) / sqrt(K), true;
    }
    template <class T>
    static bool antipode(T, T&) {
        return false;
    }
    template <class T>
    static bool straight(T) {
        return true;
    }
    template <class T>
    static bool factor(T, const Vec3<T>&, T&) {
        return false;
    }
    template <class T>
    static Unprojected<T> unproject(T K, T X, T Y) {  // p = (1, X, Y) / sqrt(1 + K rho^2)
        using std::sqrt;
        const T d = T(1) + K * (X * X + Y * Y);
        if (d <= num<T>(1e-6)) return {};
        const T w = quotient(T(1), sqrt(d));
        return {true, {w, X * w, Y * w}};
    }
};
// rho = S_K(r).
struct Orthographic {
    static constexpr const char* name = "orthographic";
    static constexpr const char* help = "orthographic (rho = S_K(r))";
    template <class T>
    static Projected<T> project(T K, T r) {
        return {S_K(K, r), !(C_K(K, r) < T(0))};
    }
    template <class T>
    static bool cut(T K, T& c) {  // at the equator, where it folds
        using std::sqrt;
        return c = pi_v<T> / T(2) / sqrt(K), true;
    }
    template <class T>
    static bool antipode(T, T&) {
        return false;
    }
    template <class T>
    static bool straight(T) {
        return false;
    }
    template <class T>
    static bool factor(T, const Vec3<T>&, T&) {
        return false;
    }
    template <class T>
    static Unprojected<T> unproject(T K, T X, T Y) {  // p = (sqrt(1 - K rho^2), X, Y)
        using std::sqrt;
        const T u = K * (X * X + Y * Y);
        if (u > T(1)) return {};
        return {true, {sqrt(T(1) - u), X, Y}};
    }
};
// rho = 2 S_K(r/2).
struct Lambert {
    static constexpr const char* name = "lambert";
    static constexpr const char* help = "Lambert azimuthal equal-area (rho = 2 S_K(r/2))";
    template <class T>
    static Projected<T> project(T K, T r) {
        return {T(2) * S_K(K, r / T(2)), true};
    }
    template <class T>
    static bool cut(T, T&) {
        return false;
    }
    template <class T>
    static bool antipode(T K, T& rho) {  // at 2 / sqrt K
        using std::sqrt;
        return rho = T(2) / sqrt(K), true;
    }
    template <class T>
    static bool straight(T) {
        return false;
    }
    template <class T>
    static bool factor(T, const Vec3<T>& v, T& f) {
        using std::sqrt;
        return f = sqrt(quotient(T(2), T(1) + v.w)), true;
    }
    template <class T>
    static Unprojected<T> unproject(T K, T X, T Y) {  // p = (1 - K rho^2 / 2, sqrt(1 - K rho^2 / 4) (X, Y))
        using std::sqrt;
        const T u = K * (X * X + Y * Y);
        if (u > T(4)) return {};
        const T f = sqrt(T(1) - quarter(u));
        return {true, {T(1) - u / T(2), f * X, f * Y}};
    }
};

// The projections, in the order P cycles them and --help lists them.
using ProjectionTable = std::tuple<Equidistant, Stereographic, Gnomonic, Orthographic, Lambert>;
inline constexpr std::size_t kProjectionCount = std::tuple_size_v<ProjectionTable>;

// A projection: its row in ProjectionTable. The rows the code names have names here (a new row
// needs none: Projection{5} is the sixth).
enum class Projection : uint8_t {
    azimuthal_equidistant,
    stereographic,
    gnomonic,
    orthographic,
    lambert_equal_area,
};

// f(P{}) for P the row of projection p (a row past the table is the first).
template <std::size_t I = 0, class F>
constexpr decltype(auto) with_projection(Projection p, F&& f) {
    using P = std::tuple_element_t<I, ProjectionTable>;
    if constexpr (I + 1 == kProjectionCount) {
        return f(P{});
    } else {
        if (static_cast<std::size_t>(p) == I) return f(P{});
        return with_projection<I + 1>(p, f);
    }
}
// Every projection, in the table's order.
inline constexpr auto kProjections = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<Projection, kProjectionCount>{static_cast<Projection>(I)...};
}(std::make_index_sequence<kProjectionCount>{});

constexpr const char* projection_name(Projection p) {
    return with_projection(p, [](auto P) { return decltype(P)::name; });
}
constexpr const char* projection_help(Projection p) {
    return with_projection(p, [](auto P) { return decltype(P)::help; });
}
// The projections' names, in the table's order.
inline std::vector<std::string> projection_names() {
    std::vector<std::string> names;
    for (Projection p : kProjections) names.emplace_back(projection_name(p));
    return names;
}
// The projection named `name`; false if none is.
inline bool parse_projection_name(std::string_view name, Projection& out) {
    for (Projection p : kProjections)
        if (name == projection_name(p)) return out = p, true;
    return false;
}

// visible = false where a projection cannot show the point: the gnomonic and orthographic
// views of the far hemisphere (C_K(r) <= 0, resp. < 0), the stereographic view of the
// antipode. The caller clips those (and anything beyond the screen).
template <class T>
Projected<T> project(T K, T r, Projection p) {
    return with_projection(p, [&](auto P) { return decltype(P)::project(K, r); });
}

// The part of the world a projection shows: the disc r <= shown_radius, which the screen's
// limit circle frames. It is the limit radius R, except on the sphere (K > 0) where the
// projection's image of r <= R would be unbounded or folded (the projection's cut: the gnomonic
// view at 60 degrees, the stereographic at 120, where each stretches a radial step four times as
// much as at the centre, and the orthographic at the equator, where it folds). Each is
// continuous in K (it is R until K reaches the cut).
template <class T>
T shown_radius(T K, T R, Projection p) {
    if (!(K > T(0))) return R;
    T cut{};
    if (!with_projection(p, [&](auto P) { return decltype(P)::cut(K, cut); })) return R;
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
    if (!(K > T(0))) return false;
    return with_projection(p, [&](auto P) { return decltype(P)::antipode(K, rho); });
}
// Whether every geodesic a projection draws is a straight line: the gnomonic view's (great
// circles through the projection's centre plane), and every view of the plane (K = 0).
template <class T>
bool straight_geodesics(T K, Projection p) {
    return K == T(0) || with_projection(p, [&](auto P) { return decltype(P)::straight(K); });
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
// The equidistant view's factor: E(w) in floating point, in fixed point 2 t ATf(K t^2) / S with
// t = S / (1 + w) (mul_ATf), rounded once.
template <class T>
bool Equidistant::factor(T K, const Vec3<T>& v, T& f) {
    if constexpr (std::is_floating_point_v<T>) {
        f = equidistant_ratio(v.w);
    } else {
        const T g = quotient(T(2), T(1) + v.w);
        const T s2 = dot2(v.x, v.x, v.y, v.y);
        f = mul_ATf(g, quarter(K * s2 * g * g));
    }
    return true;
}
template <class T>
ProjectedPoint<T> project_vec_general(T K, Vec3<T> v, Projection proj) {
    const T big = num<T>(100);
    T f{};
    if (v.w < T(0) || v.x > big || v.x < -big || v.y > big || v.y < -big ||
        !with_projection(proj, [&](auto P) { return decltype(P)::factor(K, v, f); }))
        return project_polar(K, to_polar(K, v), proj);
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
