// Exact pictures where the projection bends hardest: every drawn pixel of every body within one
// pixel of its true projected curve (tests/render/curve_reference.hpp), and no piece of the
// curve inside the clip circle left out, for the kiosk scene at K = +1 (the antipode on the rim)
// in the fixed and double engines over its first seconds, for every projection at K = -1, 0
// and +1, and for the demo's figures (app/figures.hpp) at each panel's K.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <tuple>

#include "app/figures.hpp"
#include "curve_reference.hpp"

namespace noneuclid {
namespace {

constexpr double kWithin = testing::kWithinPx;  // px: a drawn pixel's centre from the true curve
constexpr double kGap = testing::kGapPx;        // px: a true curve's point from the nearest drawn pixel's centre

template <class W>
testing::CurveCheck run_and_check(world::Scene s, double K, int frames, int every, geo::Projection p, int w, int h) {
    s.curvature = K;
    W world(s);
    testing::CurveCheck all;
    for (int f = 0; f <= frames; ++f) {
        if (f % every == 0 || f == frames) all.add(testing::check_world(world, p, w, h));
        world.step(1.0 / 60);
    }
    return all;
}

void expect(const testing::CurveCheck& c, const std::string& what) {
    EXPECT_LE(c.worst, kWithin) << what << ": a drawn pixel " << c.worst << " px from the curve (" << c.worst_body << ")";
    EXPECT_LE(c.gap, kGap) << what << ": the curve " << c.gap << " px from the drawing (" << c.gap_body << ")";
    EXPECT_GT(c.pixels, 500) << what;  // not vacuous (figure 2's two geodesics: about 700)
    std::printf("%-40s worst %.3f px, gap %.3f px, %ld pixels, %ld reference points\n", what.c_str(), c.worst, c.gap,
                c.pixels, c.samples);
}

world::Scene kiosk() {
    world::Scene s;
    world::builtin_scene("kiosk", {}, s);
    return s;
}

TEST(Curves, TheKioskAtKPlusOneIsWithinOnePixelInBothEngines) {
    // (Frames 0 to 600, every 150th at the kiosk's size and every 300th at full HD: a check of a
    // full-HD frame costs seconds under the sanitizers.)
    for (const auto& [w, h, every] : {std::tuple{800, 480, 150}, std::tuple{1920, 1080, 300}}) {
        const std::string size = std::to_string(w) + "x" + std::to_string(h);
        const testing::CurveCheck f = run_and_check<world::World<fx::fixed>>(kiosk(), 1, 600, every, geo::Projection::azimuthal_equidistant, w, h);
        expect(f, "kiosk K=+1 fixed " + size);
        RecordProperty("kiosk_k1_fixed_" + size + "_worst_px", std::to_string(f.worst));
        const testing::CurveCheck d = run_and_check<world::World<double>>(kiosk(), 1, 600, every, geo::Projection::azimuthal_equidistant, w, h);
        expect(d, "kiosk K=+1 double " + size);
        RecordProperty("kiosk_k1_double_" + size + "_worst_px", std::to_string(d.worst));
    }
}

TEST(Curves, EveryProjectionAtKMinusOneZeroAndPlusOneIsWithinOnePixel) {
    for (geo::Projection p : geo::kProjections)
        for (double K : {-1.0, 0.0, 1.0}) {
            const std::string what = std::string(geo::projection_name(p)) + " K=" + std::to_string(static_cast<int>(K));
            const testing::CurveCheck f = run_and_check<world::World<fx::fixed>>(kiosk(), K, 120, 120, p, 480, 480);
            const testing::CurveCheck d = run_and_check<world::World<double>>(kiosk(), K, 120, 120, p, 480, 480);
            expect(f, what + " fixed"), expect(d, what + " double");
            RecordProperty(std::string(geo::projection_name(p)) + "_K" + std::to_string(static_cast<int>(K)) + "_worst_px",
                           std::to_string(std::max(f.worst, d.worst)));
        }
}

// Each figure of the demo's table, each panel at its K, over the frames its time-lapse lays
// down (every 4th of them, and the last frame), at the goldens' 480x480.
TEST(Curves, TheDemosFiguresAreWithinOnePixel) {
    for (int i = 0; i < app::kFigureCount; ++i) {
        const app::Figure& f = app::kFigures[i];
        for (int panel = 0; panel < f.panels; ++panel) {
            world::Scene s;
            world::SceneParams params;
            params.centre_lat = f.centre_lat, params.centre_lon = f.centre_lon;
            ASSERT_TRUE(world::builtin_scene(f.scene, params, s)) << f.scene;
            const double K = f.own_K ? s.curvature : f.K[panel];
            const long every = std::max(1L, f.timelapse > 0 ? 4 * f.timelapse : f.frames);  // (a still figure: frame 0)
            const std::string what = std::string(f.name) + " panel " + std::to_string(panel) + " K=" + std::to_string(K);
            expect(run_and_check<world::World<fx::fixed>>(s, K, static_cast<int>(f.frames), static_cast<int>(every),
                                                           f.projection, 480, 480),
                   what + " fixed");
            expect(run_and_check<world::World<double>>(s, K, static_cast<int>(f.frames), static_cast<int>(every),
                                                        f.projection, 480, 480),
                   what + " double");
        }
    }
}

}  // namespace
}  // namespace noneuclid
