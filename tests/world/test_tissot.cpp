// Tissot's indicatrices in the earth scene (--tissot, world/earth.hpp): every circle's vertex is
// 500 km from its place (the spherical law of cosines on the polar points, against the haversine
// placing tested in test_earth.cpp), the grid is every place the docs name, and each circle, put
// through a projection, is the ellipse of that projection's scale factors there (the textbook
// factors, radial and tangential, at angle c from the centre).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "geometry/projection.hpp"
#include "test_common.hpp"
#include "tissot_reference.hpp"
#include "world/earth.hpp"
#include "earth_level.hpp"
#include "world/scene.hpp"

namespace {
namespace tissot {  // (a unity batch shares this file's scope with test_earth.cpp's)

using namespace noneuclid;
using test::kPi;

constexpr double kRad = kPi / 180;
constexpr double kEarthKm = 6371;

std::vector<const world::SceneBody*> circles(const world::Scene& s) {
    std::vector<const world::SceneBody*> out;
    for (const world::SceneBody& b : s.bodies)
        if (b.name.rfind("tissot", 0) == 0) out.push_back(&b);
    return out;
}

using test::tissot::grid;
using test::tissot::owner;
using test::tissot::Place;
using test::tissot::sphere_distance;

TEST(Tissot, EveryCircleIs500KmAboutItsPlaceOnTheGrid) {
    for (const auto& [lat0, lon0] : {std::pair{51.5, 0.0}, {90.0, 0.0}, {0.0, 180.0}, {-33.9, 151.2}}) {
        world::SceneParams p;
        p.centre_lat = lat0, p.centre_lon = lon0, p.tissot = true;
        const world::Scene s = test::earth_level(p);
        p.tissot = false;
        const world::Scene plain = test::earth_level(p);
        EXPECT_TRUE(circles(plain).empty());
        const std::vector<const world::SceneBody*> cs = circles(s);
        std::vector<int> seen(grid().size(), 0);
        long vertices = 0;
        for (const world::SceneBody* b : cs) {
            const Place c = owner(*b, lat0, lon0);
            const world::EarthPolar q = world::earth_polar(lat0, lon0, c.lat, c.lon);
            if (q.r < kPi - 0.2) {  // (near the antipode a line may break: earth.md)
                EXPECT_TRUE(b->closed) << b->name;
            }
            for (const auto& v : b->vertices) {
                // The ring's points are 500 km away; the halving's, on the chords between them,
                // up to the chord's sagitta (0.48 km) nearer.
                const double km = sphere_distance(q.r, q.theta_deg, v.rho, v.phi_deg) * kEarthKm;
                EXPECT_LE(km, 500 + 1e-6) << b->name << " about " << c.lat << "," << c.lon;
                EXPECT_GE(km, 500 - 0.5) << b->name << " about " << c.lat << "," << c.lon;
                ++vertices;
            }
            for (std::size_t i = 0; i < grid().size(); ++i)
                if (grid()[i].lat == c.lat && grid()[i].lon == c.lon) ++seen[i];
        }
        // Every place of the grid has its circle (one, or pieces of one near the antipode).
        for (std::size_t i = 0; i < seen.size(); ++i)
            EXPECT_GE(seen[i], 1) << grid()[i].lat << "," << grid()[i].lon << " about " << lat0 << "," << lon0;
        EXPECT_GE(vertices, static_cast<long>(grid().size()) * 72);
    }
}

// A circle of angular radius a at angle c from the centre, through a projection, spans
// 2 a k_radial across and 2 a k_tangential along: its extents along the two axes (from the
// projected vertices), divided by 2a, are the scale factors, to within the circle's finite size
// (a = 500 / 6371: the factors vary across it by a relative O(a^2 tan^2 c), under 2% here).
TEST(Tissot, EachCircleIsItsProjectionsEllipse) {
    const double a = world::kTissotRadiusKm / kEarthKm;
    const double lat0 = 45, lon0 = 10;
    world::SceneParams params;
    params.centre_lat = lat0, params.centre_lon = lon0, params.tissot = true;
    const world::Scene s = test::earth_level(params);
    for (const test::tissot::Factors& row : test::tissot::kFactors) {
        int checked = 0;
        double worst = 0;
        for (const world::SceneBody* b : circles(s)) {
            const Place c = owner(*b, lat0, lon0);
            const world::EarthPolar q = world::earth_polar(lat0, lon0, c.lat, c.lon);
            if (q.r < 0.05 || q.r > 60 * kRad) continue;  // (the centre has no radial axis; the gnomonic cut)
            const double t = q.theta_deg * kRad;
            // Radial axis (cos t, sin t), tangential (-sin t, cos t).
            double rmin = 1e9, rmax = -1e9, tmin = 1e9, tmax = -1e9;
            for (const auto& v : b->vertices) {
                const geo::ProjectedPoint<double> pp = geo::project_polar(1.0, geo::Polar<double>{v.rho, v.phi_deg * kRad}, row.p);
                ASSERT_TRUE(pp.visible) << row.name;
                const double u = pp.X * std::cos(t) + pp.Y * std::sin(t), w = -pp.X * std::sin(t) + pp.Y * std::cos(t);
                rmin = std::min(rmin, u), rmax = std::max(rmax, u), tmin = std::min(tmin, w), tmax = std::max(tmax, w);
            }
            const double kr = (rmax - rmin) / (2 * a), kt = (tmax - tmin) / (2 * a);
            const double er = kr / row.radial(q.r) - 1, et = kt / row.tangential(q.r) - 1;
            EXPECT_NEAR(er, 0, 0.02) << row.name << " radial at " << c.lat << "," << c.lon << " (c = " << q.r / kRad << ")";
            EXPECT_NEAR(et, 0, 0.02) << row.name << " tangential at " << c.lat << "," << c.lon;
            worst = std::max({worst, std::fabs(er), std::fabs(et)});
            ++checked;
        }
        EXPECT_GE(checked, 8) << row.name;
        RecordProperty(std::string(row.name) + "_worst_relative", std::to_string(worst));
    }
}

TEST(Tissot, ZoomedTheCirclesKeepTheirKilometres) {
    world::SceneParams p;
    p.view_km = 5000, p.tissot = true;
    const world::Scene s = test::earth_level(p);
    const double unit_km = kEarthKm * std::sqrt(s.curvature);  // a world unit on the zoomed sphere
    // About 51.5 N 0 E, 5000 km: the places within view (60 N and 30 N at 30 W, 0 and 30 E, and
    // more) have their circles, each circle's first vertex 500 km from its place.
    int near = 0;
    for (const world::SceneBody* b : circles(s)) {
        const auto& v = b->vertices[0];
        if (v.rho > kPi) continue;  // (a circle's piece just past the view's edge)
        Place best{};
        double d = 1e9, kmbest = 0;
        for (const Place& g : grid()) {
            const world::EarthPolar q = world::earth_polar(51.5, 0, g.lat, g.lon);
            const double km = sphere_distance(q.r, q.theta_deg, v.rho * unit_km / kEarthKm, v.phi_deg) * kEarthKm;
            if (km < d) d = km, best = g, kmbest = km;
        }
        EXPECT_NEAR(kmbest, 500, 0.5) << "about " << best.lat << "," << best.lon;
        ++near;
    }
    EXPECT_GE(near, 6);
}

}  // namespace tissot
}  // namespace
