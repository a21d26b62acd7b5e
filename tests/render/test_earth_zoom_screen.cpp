// The earth scene zoomed live (world::Scene::zoom) in the fixed engine against the double one,
// on the screen: at zooms from the globe down to the least (10 km), where the fixed engine's K
// has rounded to 0, every vertex of the lines shown is drawn within kWithin px of the double
// engine's. The zoom scales the vertices in double and rounds them once (world/world.hpp), so
// nothing jitters as it goes: a point's step is 2^-16 world units, a thousandth of a pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/screen_map.hpp"
#include "test_common.hpp"
#include "world/world.hpp"

namespace {
namespace earth_zoom_screen {  // (a unity batch shares this file's scope with others)

using namespace noneuclid;
using test::kPi;

constexpr double kWithin = 0.05;  // px
constexpr int kSize = 1000;

// The shown lines' vertices on a kSize-px square, equidistant view, after `steps` steps of
// curvature down held from the globe (one list per body, kBreak where a vertex is not shown).
template <class T>
std::vector<std::vector<geo::Spot>> drawn(const world::Scene& s, int steps, double& z) {
    world::World<T> w(s);
    w.press(world::Action::curvature_down);
    for (int i = 0; i < steps; ++i) w.step(1.0 / 60);
    z = w.zoom().z;
    const geo::Projection p = geo::Projection::azimuthal_equidistant;
    const geo::ScreenMap<T> m = geo::ScreenMap<T>::of(kSize, kSize, w.K, w.R, p);
    std::vector<std::vector<geo::Spot>> out;
    for (const auto& b : w.bodies) {
        if (!b.active || !b.desc->grid) continue;
        std::vector<geo::Polar<T>> v(b.local.size());
        w.vertices(b, v.data());
        std::vector<geo::Spot> spots;
        for (const auto& q : v) spots.push_back(geo::polar_spot(m, w.K, q, p));
        out.push_back(spots);
    }
    return out;
}

TEST(EarthZoomScreen, FixedDrawsTheZoomedEarthWithinATwentiethOfAPixelOfDouble) {
    world::Scene s;
    ASSERT_TRUE(world::builtin_scene("earth", {}, s));
    for (const int steps : {60, 200, 330, 450, 600}) {
        double zf = 0, zd = 0;
        const auto f = drawn<fx::fixed>(s, steps, zf), d = drawn<double>(s, steps, zd);
        EXPECT_EQ(zf, zd) << "the zoom is the same in every engine";
        ASSERT_EQ(f.size(), d.size()) << steps;
        double worst = 0;
        long shown = 0;
        for (std::size_t i = 0; i < f.size(); ++i) {
            ASSERT_EQ(f[i].size(), d[i].size());
            for (std::size_t k = 0; k < f[i].size(); ++k) {
                // (A vertex just past the clip circle may be shown by one engine and not the other.)
                if (!f[i][k].in || !d[i][k].in) continue;
                ++shown;
                worst = std::max(worst, std::hypot(f[i][k].at.x - d[i][k].at.x, f[i][k].at.y - d[i][k].at.y) / geo::kSub);
            }
        }
        EXPECT_LE(worst, kWithin) << "at " << kPi * 6371 * std::sqrt(zd) << " km";
        EXPECT_GT(shown, 0) << steps;
    }
}

}  // namespace earth_zoom_screen
}  // namespace
