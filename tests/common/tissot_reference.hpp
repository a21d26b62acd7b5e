// The reference for Tissot's indicatrices (--tissot, docs/earth.md), shared by the world-unit
// test (world/test_tissot.cpp) and the drawn one (render/test_tissot_screen.cpp): the grid of
// places as the docs name it, the place a circle belongs to, and the five projections' textbook
// scale factors at angle c from the centre.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/projection.hpp"
#include "test_common.hpp"
#include "world/earth.hpp"
#include "world/scene.hpp"

namespace noneuclid::test::tissot {

struct Place {
    double lat, lon;
};
// Latitudes 60 S to 60 N every 30 degrees, longitudes -180 to 150 every 30, and the poles.
inline std::vector<Place> grid() {
    std::vector<Place> out;
    for (int lat = -60; lat <= 60; lat += 30)
        for (int lon = -180; lon < 180; lon += 30) out.push_back({double(lat), double(lon)});
    out.push_back({90, 0});
    out.push_back({-90, 0});
    return out;
}

// The distance on the unit sphere between two polar points (r, theta in degrees) about the same
// centre: the spherical law of cosines.
inline double sphere_distance(double r1, double t1, double r2, double t2) {
    const double c = std::cos(r1) * std::cos(r2) + std::sin(r1) * std::sin(r2) * std::cos(deg(t1 - t2));
    return std::acos(std::clamp(c, -1.0, 1.0));
}

// The place of the grid nearest to a circle's first vertex, about the centre (lat0, lon0): the
// circle's own (no other place is within 1000 km of it).
inline Place owner(const world::SceneBody& b, double lat0, double lon0) {
    const auto& v = b.vertices[0];
    Place best{};
    double d = 1e9;
    for (const Place& p : grid()) {
        const world::EarthPolar q = world::earth_polar(lat0, lon0, p.lat, p.lon);
        const double e = sphere_distance(q.r, q.theta_deg, v.rho, v.phi_deg);
        if (e < d) d = e, best = p;
    }
    return best;
}

// A projection's scale factors at angle c from the centre, radial and tangential; cut: where the
// view stops short of the limit circle at K = +1 (geometry/projection.hpp).
struct Factors {
    geo::Projection p;
    const char* name;
    double (*radial)(double c);
    double (*tangential)(double c);
    double cut = kPi;
};
inline const Factors kFactors[] = {
    {geo::Projection::orthographic, "orthographic", [](double c) { return std::cos(c); }, [](double) { return 1.0; }},
    {geo::Projection::lambert_equal_area, "lambert", [](double c) { return std::cos(c / 2); },
     [](double c) { return 1 / std::cos(c / 2); }},
    {geo::Projection::gnomonic, "gnomonic", [](double c) { return 1 / (std::cos(c) * std::cos(c)); },
     [](double c) { return 1 / std::cos(c); }, kPi / 3},
    {geo::Projection::stereographic, "stereographic", [](double c) { return 1 / (std::cos(c / 2) * std::cos(c / 2)); },
     [](double c) { return 1 / (std::cos(c / 2) * std::cos(c / 2)); }},
    {geo::Projection::azimuthal_equidistant, "equidistant", [](double) { return 1.0; },
     [](double c) { return c / std::sin(c); }},
};

}  // namespace noneuclid::test::tissot
