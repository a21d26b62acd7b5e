// Exact pictures where the projection bends hardest: every drawn pixel of every body within one
// pixel of its true projected curve (tests/render/curve_reference.hpp), and no piece of the
// curve inside the clip circle left out, for the kiosk scene at K = +1 (the antipode on the rim)
// in the fixed and double engines over its first seconds, and for every projection at K = -1, 0
// and +1.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "curve_reference.hpp"

namespace noneuclid {
namespace {

constexpr double kWithin = 1.0;  // px: a drawn pixel's centre from the true curve
constexpr double kGap = 1.5;     // px: a true curve's point from the nearest drawn pixel's centre

template <class W>
testing::CurveCheck run_and_check(world::Scene s, double K, int frames, int every, geo::Projection p, int w, int h) {
    s.curvature = K;
    W world(s);
    testing::CurveCheck all;
    for (int f = 0; f <= frames; ++f) {
        if (f % every == 0) all.add(testing::check_world(world, p, w, h));
        world.step(typename W::scalar(1.0 / 60));
    }
    return all;
}

void expect(const testing::CurveCheck& c, const std::string& what) {
    EXPECT_LE(c.worst, kWithin) << what << ": a drawn pixel " << c.worst << " px from the curve (" << c.worst_body << ")";
    EXPECT_LE(c.gap, kGap) << what << ": the curve " << c.gap << " px from the drawing (" << c.gap_body << ")";
    EXPECT_GT(c.pixels, 1000) << what;  // not vacuous
    std::printf("%-40s worst %.3f px, gap %.3f px, %ld pixels, %ld reference points\n", what.c_str(), c.worst, c.gap,
                c.pixels, c.samples);
}

world::Scene kiosk() {
    world::Scene s;
    world::builtin_scene("kiosk", {}, s);
    return s;
}

TEST(Curves, TheKioskAtKPlusOneIsWithinOnePixelInBothEngines) {
    for (const auto& [w, h] : {std::pair{800, 480}, std::pair{1920, 1080}}) {
        const std::string size = std::to_string(w) + "x" + std::to_string(h);
        const testing::CurveCheck f = run_and_check<world::World<fx::fixed>>(kiosk(), 1, 600, 60, geo::Projection::azimuthal_equidistant, w, h);
        expect(f, "kiosk K=+1 fixed " + size);
        RecordProperty("kiosk_k1_fixed_" + size + "_worst_px", std::to_string(f.worst));
        const testing::CurveCheck d = run_and_check<world::World<double>>(kiosk(), 1, 600, 60, geo::Projection::azimuthal_equidistant, w, h);
        expect(d, "kiosk K=+1 double " + size);
        RecordProperty("kiosk_k1_double_" + size + "_worst_px", std::to_string(d.worst));
    }
}

TEST(Curves, EveryProjectionAtKMinusOneZeroAndPlusOneIsWithinOnePixel) {
    for (geo::Projection p : geo::kProjections)
        for (double K : {-1.0, 0.0, 1.0}) {
            const std::string what = std::string(geo::projection_name(p)) + " K=" + std::to_string(static_cast<int>(K));
            expect(run_and_check<world::World<fx::fixed>>(kiosk(), K, 120, 120, p, 480, 480), what + " fixed");
            expect(run_and_check<world::World<double>>(kiosk(), K, 120, 120, p, 480, 480), what + " double");
        }
}

}  // namespace
}  // namespace noneuclid
