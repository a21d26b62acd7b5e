// Tissot's indicatrices as the engines draw them (--tissot, docs/earth.md): each circle of 500 km,
// drawn by the fixed and the double engine in a projection at K = +1, is an ellipse whose axes,
// measured from the screen points the engine outputs, are in the ratio of that projection's
// textbook scale factors at the circle's angle c from the centre (radial / tangential):
// orthographic cos c / 1, Lambert equal-area cos(c/2) / (1 / cos(c/2)), gnomonic
// (1 / cos^2 c) / (1 / cos c), stereographic 1 (conformal), equidistant 1 / (c / sin c).
// (The factors themselves, in world units: tests/world/test_tissot.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/body_points.hpp"
#include "earth_level.hpp"
#include "tissot_reference.hpp"
#include "world/earth.hpp"
#include "world/world.hpp"

namespace {
namespace tissot_screen {  // (a unity batch shares this file's scope with others)

using namespace noneuclid;

using test::kPi;
constexpr double kRad = kPi / 180;
// The circle is not infinitesimal: the factors change across it by a relative O(a^2 tan^2 c)
// (a = 500 / 6371), most for the gnomonic at 60 degrees; and the points are on a sub-pixel grid.
constexpr double kWithin = 0.02;

using Row = test::tissot::Factors;

// The circle's angle from the centre: that of the grid's place it belongs to.
double angle_of_place(const world::SceneBody& b, double lat0, double lon0) {
    const test::tissot::Place c = test::tissot::owner(b, lat0, lon0);
    return world::earth_polar(lat0, lon0, c.lat, c.lon).r;
}

// The worst relative error of the drawn ellipses' axis ratios in one engine and projection,
// over the circles within 60 degrees of the centre (and wholly inside the view); `checked` counts them.
template <class T>
double worst_ratio_error(const world::Scene& s, const Row& row, double lat0, double lon0, int& checked) {
    world::World<T> w(s);
    std::vector<typename world::World<T>::engine::Cache> caches;
    render::make_shape_caches(w, caches);
    render::DrawOptions o;
    o.projection = row.p;
    constexpr int kSize = 1000;
    const geo::ScreenMap<T> m = geo::ScreenMap<T>::of(kSize, kSize, w.K, T(kPi), row.p);
    const double mid = kSize / 2.0 * geo::kSub;
    double worst = 0;
    checked = 0;
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        if (s.bodies[i].name.rfind("tissot", 0) != 0) continue;
        const double c = angle_of_place(s.bodies[i], lat0, lon0);
        // (The centre has no radial axis; a circle must be wholly inside the view's cut.)
        if (c < 0.05 || c > 60 * kRad || c + world::kTissotRadiusKm / world::kEarthRadiusKm > row.cut) continue;
        const auto& b = w.bodies[i];
        std::vector<geo::Polar<T>> verts(b.local.size());
        std::vector<geo::Vec3<T>> vecs(b.local.size());
        std::vector<geo::SubPoint> out(render::body_point_capacity(w, b));
        const std::size_t n = render::body_screen_points(w, b, caches[i], m, o, verts.data(), vecs.data(), out.data());
        double sx = 0, sy = 0;
        for (std::size_t k = 0; k < n; ++k) {
            EXPECT_NE(out[k].x, geo::kBreak.x) << row.name << ": a circle within 60 degrees is drawn whole";
            sx += out[k].x, sy += out[k].y;
        }
        // The radial axis: from the screen's centre through the ellipse's; the tangential across.
        const double cx = sx / double(n) - mid, cy = sy / double(n) - mid, len = std::hypot(cx, cy);
        const double ux = cx / len, uy = cy / len;
        double rmin = 1e18, rmax = -1e18, tmin = 1e18, tmax = -1e18;
        for (std::size_t k = 0; k < n; ++k) {
            const double x = out[k].x - mid, y = out[k].y - mid;
            const double r = x * ux + y * uy, t = -x * uy + y * ux;
            rmin = std::min(rmin, r), rmax = std::max(rmax, r), tmin = std::min(tmin, t), tmax = std::max(tmax, t);
        }
        const double e = (rmax - rmin) / (tmax - tmin) / (row.radial(c) / row.tangential(c)) - 1;
        EXPECT_NEAR(e, 0, kWithin) << row.name << " at c = " << c / kRad << " degrees";
        worst = std::max(worst, std::fabs(e));
        ++checked;
    }
    return worst;
}

TEST(TissotOnScreen, EachDrawnEllipseHasItsProjectionsAxisRatio) {
    const double lat0 = 45, lon0 = 10;
    world::SceneParams p;
    p.centre_lat = lat0, p.centre_lon = lon0, p.tissot = true;
    const world::Scene s = test::earth_level(p);
    for (const Row& row : test::tissot::kFactors) {
        int fixed_checked = 0, double_checked = 0;
        const double f = worst_ratio_error<fx::fixed>(s, row, lat0, lon0, fixed_checked);
        const double d = worst_ratio_error<double>(s, row, lat0, lon0, double_checked);
        EXPECT_GE(fixed_checked, 8) << row.name;
        EXPECT_EQ(fixed_checked, double_checked) << row.name;
        RecordProperty(std::string(row.name) + "_worst_fixed", std::to_string(f));
        RecordProperty(std::string(row.name) + "_worst_double", std::to_string(d));
    }
}

}  // namespace tissot_screen
}  // namespace
