// The earth scene (world/earth.hpp): a place's distance and bearing about the centre against the
// textbook spherical formulas (haversine, the initial-bearing formula), --centre's values, and
// the scene: every coastline point of the data in it, within the world's budget and ranges, and
// each edge short enough at K = -1 (the hyperbolic law of cosines with std::acosh) at every
// centre. (Against PROJ's projections on the screen: earth_proj_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "test_common.hpp"
#include "world/budget.hpp"
#include "world/earth.hpp"
#include "world/earth_data.hpp"
#include "world/ranges.hpp"

namespace {

using namespace noneuclid;
using test::kPi;

constexpr double kRad = kPi / 180;

double haversine(double lat1, double lon1, double lat2, double lon2) {
    const double a = std::sin((lat2 - lat1) * kRad / 2), b = std::sin((lon2 - lon1) * kRad / 2);
    return 2 * std::asin(std::sqrt(a * a + std::cos(lat1 * kRad) * std::cos(lat2 * kRad) * b * b));
}
// The initial bearing from 1 to 2, clockwise from north, radians.
double azimuth(double lat1, double lon1, double lat2, double lon2) {
    const double p1 = lat1 * kRad, p2 = lat2 * kRad, dl = (lon2 - lon1) * kRad;
    return std::atan2(std::sin(dl) * std::cos(p2), std::cos(p1) * std::sin(p2) - std::sin(p1) * std::cos(p2) * std::cos(dl));
}

TEST(Earth, DistanceAndBearingAreTheSpheresOwn) {
    std::mt19937 rng(35);
    std::uniform_real_distribution<double> lat(-90, 90), lon(-180, 180);
    for (int i = 0; i < 20000; ++i) {
        const double a = lat(rng), b = lon(rng), c = lat(rng), d = lon(rng);
        const world::EarthPolar q = world::earth_polar(a, b, c, d);
        const double r = haversine(a, b, c, d);
        // (haversine loses digits near the antipode, asin of nearly 1: 1e-7 covers it there)
        EXPECT_NEAR(q.r, r, r > 3.1 ? 1e-7 : 1e-12) << a << "," << b << " -> " << c << "," << d;
        if (r < 1e-6 || r > kPi - 1e-6) continue;  // the bearing is undefined at the centre and antipode
        // theta is measured counterclockwise from east: 90 degrees minus the azimuth.
        EXPECT_NEAR(test::angle_diff(q.theta_deg * kRad, kPi / 2 - azimuth(a, b, c, d)), 0, 1e-9)
            << a << "," << b << " -> " << c << "," << d;
    }
    // North of the centre is up, east to the right: London's north pole and Greenwich's east.
    EXPECT_NEAR(world::earth_polar(51.5, 0, 90, 0).theta_deg, 90, 1e-12);
    EXPECT_NEAR(world::earth_polar(0, 0, 0, 10).theta_deg, 0, 1e-12);
    EXPECT_NEAR(world::earth_polar(0, 0, 0, 10).r, 10 * kRad, 1e-15);
}

TEST(Earth, CentreTakesTwoNumbersInRange) {
    double lat = 0, lon = 0;
    EXPECT_TRUE(world::parse_centre("51.5,0", lat, lon));
    EXPECT_EQ(lat, 51.5);
    EXPECT_EQ(lon, 0);
    EXPECT_TRUE(world::parse_centre("-90,180", lat, lon));
    EXPECT_TRUE(world::parse_centre("90,-180", lat, lon));
    for (const char* bad : {"", "51.5", "51.5,", ",0", "51.5;0", "90.01,0", "0,180.5", "nan,0", "0,inf", "1,2,3",
                            "51.5,0 ", "x,y"}) {
        lat = lon = 7;
        EXPECT_FALSE(world::parse_centre(bad, lat, lon)) << bad;
        EXPECT_EQ(lat, 7) << bad;  // unchanged
    }
}

// The hyperbolic distance of two polar points (K = -1), by the law of cosines.
double hyperbolic(world::SceneBody::Vertex a, world::SceneBody::Vertex b) {
    const double c = std::cosh(a.rho) * std::cosh(b.rho) -
                     std::sinh(a.rho) * std::sinh(b.rho) * std::cos((a.phi_deg - b.phi_deg) * kRad);
    return std::acosh(std::fmax(c, 1.0));
}

TEST(Earth, TheSceneHoldsEveryCoastPointWithinTheBudgetAndRanges) {
    for (const auto& [lat, lon] : {std::pair{51.5, 0.0}, {90.0, 0.0}, {-90.0, 0.0}, {0.0, 180.0}, {-33.9, 151.2}}) {
        world::SceneParams p;
        p.centre_lat = lat, p.centre_lon = lon;
        world::Scene s;
        ASSERT_TRUE(world::builtin_scene("earth", p, s));
        EXPECT_EQ(s.curvature, 1);
        EXPECT_EQ(s.limit_radius, kPi);
        std::string why;
        EXPECT_TRUE(world::within_budget(s, why)) << why;
        EXPECT_TRUE(world::within_ranges(s, why)) << why;
        long coast = 0, longest = 0, ships = 0;
        for (const world::SceneBody& b : s.bodies) {
            if (b.controlled) {  // the ship, at O, to fly over the Earth
                EXPECT_TRUE(!b.grid && b.r == 0 && b.speed == 0) << b.name;
                ++ships;
                continue;
            }
            EXPECT_TRUE(b.grid && b.r == 0 && b.facing_deg == 0 && b.speed == 0) << b.name;
            if (b.name.rfind("coast", 0) == 0) coast += static_cast<long>(b.vertices.size());
            for (std::size_t i = 0; i + 1 < b.vertices.size(); ++i) {
                EXPECT_LE(b.vertices[i].rho, kPi + 1e-12);
                // (0.1 at K = -1, the halving's step, plus rounding)
                const double d = hyperbolic(b.vertices[i], b.vertices[i + 1]);
                EXPECT_LE(d, 0.1 + 1e-9) << b.name << " " << i;
                longest = std::max(longest, static_cast<long>(b.vertices.size()));
            }
        }
        EXPECT_EQ(ships, 1);
        // Every point of the data, and the halving's points between them.
        EXPECT_GE(coast, static_cast<long>(std::size(world::earth_data::kPoints))) << lat << "," << lon;
        EXPECT_LE(longest, world::Budget::kVerticesPerBody);
        // Each data point is in the scene where earth_polar puts it (a sample of them).
        for (std::size_t i = 0; i < std::size(world::earth_data::kPoints); i += 97) {
            const auto& pt = world::earth_data::kPoints[i];
            const world::EarthPolar q = world::earth_polar(lat, lon, pt[0] * 1e-4, pt[1] * 1e-4);
            if (q.r > kPi - 0.1) continue;  // lines near the antipode may break there
            bool found = false;
            for (const world::SceneBody& b : s.bodies)
                for (const auto& v : b.vertices) found = found || (v.rho == q.r && v.phi_deg == q.theta_deg);
            EXPECT_TRUE(found) << "point " << i << " about " << lat << "," << lon;
        }
    }
}

// Zoomed (--view KM): K = (KM / (pi 6371))^2, so that the limit radius pi is KM on the sphere of
// that curvature; every data point within the view is there at its angle / sqrt K, and only the
// lines in view (and just past it) are kept.
TEST(Earth, ZoomedTheViewIsKmOnTheSphereOfThatCurvature) {
    for (double view : {5000.0, 1000.0, 50.0}) {
        world::SceneParams p;
        p.view_km = view;
        world::Scene s;
        ASSERT_TRUE(world::builtin_scene("earth", p, s));
        const double K = std::pow(view / (kPi * 6371), 2);
        EXPECT_NEAR(s.curvature, K, 1e-15 * K);
        // The limit radius pi, on the sphere of radius 1 / sqrt K = 6371 km: view km.
        EXPECT_NEAR(s.limit_radius * 6371 * std::sqrt(s.curvature), view, 1e-9 * view);
        std::string why;
        EXPECT_TRUE(world::within_budget(s, why)) << why;
        EXPECT_TRUE(world::within_ranges(s, why)) << why;
        for (const world::SceneBody& b : s.bodies)
            for (const auto& v : b.vertices) EXPECT_LE(v.rho, kPi + 0.25 + 0.1 + 1e-9) << b.name;
        long in_view = 0;
        for (std::size_t i = 0; i < std::size(world::earth_data::kPoints); ++i) {
            const auto& pt = world::earth_data::kPoints[i];
            const world::EarthPolar q = world::earth_polar(51.5, 0, pt[0] * 1e-4, pt[1] * 1e-4);
            const double r = q.r / std::sqrt(K);
            if (r > kPi) continue;
            ++in_view;
            bool found = false;
            for (const world::SceneBody& b : s.bodies)
                for (const auto& v : b.vertices)
                    found = found || (std::fabs(v.rho - r) <= 1e-12 * r && v.phi_deg == q.theta_deg);
            EXPECT_TRUE(found) << "point " << i << " in the " << view << " km view";
        }
        if (view >= 1000) {
            EXPECT_GT(in_view, 10) << view;  // (not vacuous: Britain's coast is within 1000 km)
        }
    }
    world::Scene s;
    world::SceneParams p;
    p.view_km = 1000;
    world::builtin_scene("earth", p, s);
    long n = 0;
    for (const world::SceneBody& b : s.bodies) n += static_cast<long>(b.vertices.size());
    world::Scene globe;
    world::builtin_scene("earth", {}, globe);
    long m = 0;
    for (const world::SceneBody& b : globe.bodies) m += static_cast<long>(b.vertices.size());
    EXPECT_LT(n, m) << "the view keeps only what it shows";
}

}  // namespace
