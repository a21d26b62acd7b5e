// The instruments' readings (docs/measure.md): what a triangle, a circle, two parallels and a
// ring of regular polygons measure at curvature K, in forms that are exact for every K,
// including 0, with no 0/0 as K -> 0. Read in double from the marks' polar coordinates, whatever
// the world's engine (a fixed-point world's marks are Q16.16 numbers, read exactly).
//
//  - triangle A B C: its sides (geodesic distances), its interior angles (the angle between the
//    bearings of the two sides at each vertex, in the carried frame there), their sum, the
//    excess (sum - 180 degrees) and the area, from two sides a, b and the angle C between them:
//        tan(K area / 2) = K t_a t_b sin C / (1 + K t_a t_b cos C),   t = T_K(x / 2),
//    written as area = 2 n / m atanc(K n / m) with n = t_a t_b sin C, m = 1 + K t_a t_b cos C
//    and atanc(u) = atan(u) / u (1 at 0): at K = 0 it is a b sin C / 2. Gauss-Bonnet says
//    K area = excess; the two are computed by different routes and shown side by side.
//  - circle of radius rho: circumference 2 pi S_K(rho), area pi (2 S_K(rho / 2))^2, against the
//    flat 2 pi rho and pi rho^2.
//  - parallels: two geodesics leaving a common perpendicular of length d on the same side; after
//    an arclength s along each they are 2 AS_K(S_K(d / 2) |C_K(s)|) apart (each point is
//    AS_K(S_K(d / 2) C_K(s)) from the perpendicular bisector). At K > 0 they meet at
//    s = pi / (2 sqrt K); at K < 0 they fly apart.
//  - polygon closure: a regular p-gon of side a has the interior angle alpha with
//        sin(alpha / 2) = cos(pi / p) / C_K(a / 2)
//    (the right triangle centre - edge midpoint - vertex); q of them around a vertex leave a gap
//    of 360 - q alpha degrees (an overlap when negative), and close exactly where
//    C_K(a / 2) = cos(pi / p) / sin(pi / q), i.e. K = 4 u / a^2 with Cf(u) = that value.
// Bad input (a mark past the limit circle, coincident or collinear marks, a polygon that closes
// at no K in [-1, 1], a radius that is not positive) is a MeasureError, never a NaN.
#pragma once

#include <cmath>
#include <numbers>

#include "geometry/model.hpp"
#include "geometry/walk.hpp"

namespace noneuclid::geo {

// The instruments, in the order a button cycles them.
enum class Instrument { triangle, circle, parallels, polygon };
inline constexpr Instrument kInstruments[] = {Instrument::triangle, Instrument::circle, Instrument::parallels,
                                              Instrument::polygon};
inline const char* instrument_name(Instrument i) {
    constexpr const char* names[] = {"triangle", "circle", "parallels", "polygon"};
    return names[static_cast<int>(i)];
}
inline const char* instrument_help(Instrument i) {
    constexpr const char* help[] = {
        "three marks joined by geodesics: its angles, their sum and excess, the area, K times the area",
        "a centre and a radius: the circumference and the area against the flat ones",
        "two geodesics leaving a common perpendicular: how far apart they are further on",
        "q regular p-gons around a vertex: the gap or overlap, and the K at which they close"};
    return help[static_cast<int>(i)];
}
// The instrument named `name`; false if none is.
inline bool parse_instrument(const char* name, Instrument& out) {
    for (Instrument i : kInstruments) {
        const char* a = instrument_name(i);
        const char* b = name;
        while (*a && *a == *b) ++a, ++b;
        if (!*a && !*b) return out = i, true;
    }
    return false;
}

enum class MeasureError {
    none,
    outside,        // a mark lies past the limit circle
    coincident,     // two marks at (nearly) the same place
    collinear,      // three marks on (nearly) one geodesic
    radius,         // a radius, length or distance that is not positive (or wraps the sphere)
    polygon,        // no regular p-gon of that side, or p or q below 3
    never_closes,   // q p-gons of that side close at no K in [-1, 1]
};
// The sentence for an error (no full stop), for the HUD and the command line.
inline const char* measure_error_sentence(MeasureError e) {
    switch (e) {
        case MeasureError::none: return "";
        case MeasureError::outside: return "a mark lies outside the limit circle: place it inside";
        case MeasureError::coincident: return "two marks are at the same place: move one of them";
        case MeasureError::collinear: return "the three marks lie on one geodesic: move one off it";
        case MeasureError::radius: return "a length must be positive (and, on the sphere, shorter than halfway round)";
        case MeasureError::polygon: return "no regular polygon has that many sides of that length here (p and q from 3)";
        case MeasureError::never_closes: return "those polygons close at no curvature from -1 to +1: change the side";
    }
    return "";
}

// The smallest side and angle the instruments accept: below them the marks coincide or are
// collinear for every purpose a screen has.
inline constexpr double kMeasureMinLength = 1e-6, kMeasureMinAngle = 1e-6;

namespace detail {
inline double degrees(double rad) { return rad * 180 / std::numbers::pi; }
// atan(u) / u, 1 at 0 (its series where u is small, exact there to the last bit).
inline double atanc(double u) {
    if (std::fabs(u) < 1e-4) return 1 - u * u / 3 + u * u * u * u / 5;
    return std::atan(u) / u;
}
// T_K(x / 2) = S_K(x / 2) / C_K(x / 2).
inline double half_tangent(double K, double x) { return S_K(K, x / 2) / C_K(K, x / 2); }
// The largest distance on the sphere: pi / sqrt K (infinite for K <= 0).
inline double antipode(double K) { return K > 0 ? std::numbers::pi / std::sqrt(K) : INFINITY; }
}  // namespace detail

struct TriangleReading {
    double side[3] = {};        // side[i]: opposite vertex i (BC, CA, AB)
    double angle_deg[3] = {};   // interior angle at vertex i
    double sum_deg = 0, excess_deg = 0;
    double area = 0;            // world units squared
    double k_area_deg = 0;      // K times the area, in degrees: the excess, by Gauss-Bonnet
};
inline MeasureError measure_triangle(double K, const Polar<double> v[3], double R, TriangleReading& out) {
    out = {};
    for (int i = 0; i < 3; ++i)
        if (!(v[i].r >= 0) || v[i].r > R) return MeasureError::outside;
    for (int i = 0; i < 3; ++i) {
        out.side[i] = distance(K, v[(i + 1) % 3], v[(i + 2) % 3]);
        if (!(out.side[i] >= kMeasureMinLength)) return MeasureError::coincident;
    }
    double angle[3];
    for (int i = 0; i < 3; ++i) {
        const double to_next = bearing(K, v[i], v[(i + 1) % 3]), to_prev = bearing(K, v[i], v[(i + 2) % 3]);
        angle[i] = std::fabs(wrap_pi(to_next - to_prev));
        if (angle[i] < kMeasureMinAngle || angle[i] > std::numbers::pi - kMeasureMinAngle) return MeasureError::collinear;
        out.angle_deg[i] = detail::degrees(angle[i]);
    }
    out.sum_deg = out.angle_deg[0] + out.angle_deg[1] + out.angle_deg[2];
    out.excess_deg = detail::degrees(angle[0] + angle[1] + angle[2] - std::numbers::pi);
    // The area from the two sides at vertex 2 (CA = side[1], CB = side[0]) and its angle.
    const double P = detail::half_tangent(K, out.side[0]) * detail::half_tangent(K, out.side[1]);
    const double n = P * std::sin(angle[2]), m = 1 + K * P * std::cos(angle[2]);
    out.area = m > 0 ? 2 * n / m * detail::atanc(K * n / m) : 2 * std::atan2(K * n, m) / K;  // (m <= 0 only for K > 0)
    out.k_area_deg = detail::degrees(K * out.area);
    return MeasureError::none;
}

struct CircleReading {
    double radius = 0;
    double circumference = 0, flat_circumference = 0, circumference_ratio = 0;
    double area = 0, flat_area = 0, area_ratio = 0;
};
inline MeasureError measure_circle(double K, Polar<double> centre, double rho, double R, CircleReading& out) {
    out = {};
    if (!(centre.r >= 0) || centre.r > R) return MeasureError::outside;
    if (!(rho > 0) || rho >= detail::antipode(K)) return MeasureError::radius;
    const double pi = std::numbers::pi, s = 2 * S_K(K, rho / 2);
    out.radius = rho;
    out.circumference = 2 * pi * S_K(K, rho), out.flat_circumference = 2 * pi * rho;
    out.area = pi * s * s, out.flat_area = pi * rho * rho;
    out.circumference_ratio = out.circumference / out.flat_circumference;
    out.area_ratio = out.area / out.flat_area;
    return MeasureError::none;
}

struct ParallelsReading {
    double start = 0, length = 0;  // d, s
    double distance = 0;           // apart after s
    double ratio = 0;              // distance / d (1 in the plane)
    bool meet = false;             // they meet (K > 0), at meet_at along each
    double meet_at = 0;
};
inline MeasureError measure_parallels(double K, double d, double s, ParallelsReading& out) {
    out = {};
    if (!(d > 0) || !(s >= 0) || d >= detail::antipode(K) || s > 1e6) return MeasureError::radius;
    out.start = d, out.length = s;
    out.distance = 2 * AS_K(K, S_K(K, d / 2) * std::fabs(C_K(K, s)));
    out.ratio = out.distance / d;
    out.meet = K > 0;
    out.meet_at = out.meet ? detail::antipode(K) / 2 : 0;
    return MeasureError::none;
}

struct PolygonReading {
    int sides = 0, around = 0;
    double side = 0;
    double angle_deg = 0;   // a polygon's interior angle
    double gap_deg = 0;     // 360 - around * angle: > 0 a gap, < 0 an overlap
    double closing_K = 0;   // where they close exactly
};
inline MeasureError measure_polygon(double K, int p, int q, double a, PolygonReading& out) {
    out = {};
    if (p < 3 || q < 3 || p > 1000 || q > 1000) return MeasureError::polygon;
    if (!(a > 0) || a >= detail::antipode(K)) return MeasureError::radius;
    const double pi = std::numbers::pi;
    const double c = C_K(K, a / 2), half_sin = std::cos(pi / p) / c;
    if (!(c > 0) || half_sin > 1) return MeasureError::polygon;
    out.sides = p, out.around = q, out.side = a;
    out.angle_deg = detail::degrees(2 * std::asin(half_sin));
    out.gap_deg = 360 - q * out.angle_deg;
    // Cf(u) = v: u = acos(v)^2 for v <= 1, -acosh(v)^2 above; v = 1 exactly for the flat tilings.
    const double v = std::cos(pi / p) / std::sin(pi / q);
    const double u = v < 1 ? std::pow(std::acos(v), 2) : -std::pow(std::acosh(v), 2);
    out.closing_K = 4 * u / (a * a);
    if (std::fabs(out.closing_K) < 1e-12) out.closing_K = 0;
    if (out.closing_K < -1 || out.closing_K > 1) return MeasureError::never_closes;
    return MeasureError::none;
}

}  // namespace noneuclid::geo
