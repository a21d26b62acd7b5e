// Projections and the screen: each projection's known formulas at K = +1 and -1 and its
// continuity through K = 0, screen y growing downward, and the screen report (the fixed engine
// within a quarter pixel of double on the 1080-px disk; short distances keeping their digits).
#include <gtest/gtest.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <iterator>
#include <string>
#include <vector>

#include "geometry/accuracy.hpp"
#include "geometry/geometry.hpp"
#include "geometry/screen.hpp"
#include "test_common.hpp"

using namespace noneuclid::geo;
using noneuclid::fx::fixed;

namespace {

using noneuclid::test::kPi;

// ---- projections ----------------------------------------------------------------------------

TEST(Projection, KnownFormulasAtKPlusMinusOne) {
    for (double r : {0.0, 0.3, 1.0, 1.5, 2.5}) {
        EXPECT_NEAR(project(-1.0, r, Projection::stereographic).rho, 2 * std::tanh(r / 2), 1e-12);
        EXPECT_NEAR(project(-1.0, r, Projection::gnomonic).rho, std::tanh(r), 1e-12);
        EXPECT_NEAR(project(-1.0, r, Projection::orthographic).rho, std::sinh(r), 1e-12);
        EXPECT_NEAR(project(-1.0, r, Projection::lambert_equal_area).rho, 2 * std::sinh(r / 2), 1e-12);
        EXPECT_NEAR(project(1.0, r, Projection::stereographic).rho, 2 * std::tan(r / 2), 1e-12);
        EXPECT_NEAR(project(1.0, r, Projection::lambert_equal_area).rho, 2 * std::sin(r / 2), 1e-12);
        EXPECT_NEAR(project(1.0, r, Projection::orthographic).rho, std::sin(r), 1e-12);
        EXPECT_EQ(project(0.3, r, Projection::azimuthal_equidistant).rho, r);
    }
    EXPECT_FALSE(project(1.0, 2.0, Projection::gnomonic).visible);   // beyond the equator
    EXPECT_TRUE(project(1.0, 1.5, Projection::gnomonic).visible);
    EXPECT_FALSE(project(1.0, 2.0, Projection::orthographic).visible);
    EXPECT_FALSE(project(1.0, kPi, Projection::stereographic).visible);  // the antipode
}

TEST(Projection, ContinuousThroughZeroForEveryProjection) {
    for (Projection p : kProjections)
        for (double r : {0.1, 1.0, 3.0}) {
            const double at0 = project(0.0, r, p).rho;
            EXPECT_EQ(at0, r) << projection_name(p);
            EXPECT_NEAR(project(1e-6, r, p).rho, at0, 2e-5 * r * r * r) << projection_name(p);
            EXPECT_NEAR(project(-1e-6, r, p).rho, at0, 2e-5 * r * r * r) << projection_name(p);
            EXPECT_NEAR(project<fixed>(fixed(0), fixed(r), p).rho.to_double(), r, 2e-5) << projection_name(p);
        }
}

// ---- the screen report ----------------------------------------------------------------------

// As kContinuityBounds: px on the 1080-px disk, per engine, comparison, points and sweep.
// 0: reported only (the paper's formulas). Measured (2025-11): fixed 0.036 (vertices) and 0.058
// (edge points), float 0.00083, double 2.1e-11.
struct ScreenBound {
    const char* engine;
    const char* against;
    const char* where;
    double vertices_px, edge_points_px;
};
// The fixed engine over the whole population of bodies: its edge points near the sphere's
// antipode (K in [0.9, 1], centres at 0.75 to 0.95 of R), where the equidistant view magnifies
// their error most, decide the edge points' bound (docs/accuracy.md has the figures); its
// vertices, walked by the coasts' kernel, hold 0.05 px everywhere.
constexpr double kAntipodeVerticesPx = 0.05, kAntipodeEdgesPx = 0.25;
const ScreenBound kScreenBounds[] = {
    {"fixed", "double", "K in [-1, 1]", kAntipodeVerticesPx, kAntipodeEdgesPx},
    {"float", "double", "K in [-1, 1]", 0.01, 0.01},
    {"double", "reference", "K in [-1, 1]", 1e-7, 1e-7},
    {"fixed", "reference", "K in [-1, 1]", kAntipodeVerticesPx, kAntipodeEdgesPx},
    {"double", "reference", "short edges (~1e-3)", 1e-7, 1e-7},
    {"fixed", "reference", "short edges (~1e-3)", 0.05, 0.08},
    {"fixed", "double", "near the antipode", kAntipodeVerticesPx, kAntipodeEdgesPx},
    {"fixed", "reference", "near the antipode", kAntipodeVerticesPx, kAntipodeEdgesPx},
    {"fixed", "reference", "short edges, antipode", 0.05, 0.08},
    {"paper", "reference", "K in [-1, 1]", 0, 0},
    {"paper", "reference", "|K| <= 0.02", 0, 0},
    {"paper", "reference", "short edges (~1e-3)", 0, 0},
};

TEST(Screen, FixedEngineWithinAQuarterPixelOfDouble) {
    std::vector<ScreenErrorRow> rows(static_cast<std::size_t>(screen_error_row_count()));
    GeometryReportOptions o;
    o.bodies /= noneuclid::test::kEmulatedStride;
    const int n = measure_screen_error(o, rows.data(), static_cast<int>(rows.size()));
    ASSERT_EQ(n, screen_error_row_count());
    ASSERT_EQ(rows.size(), 2 * std::size(kScreenBounds));
    int fixed_rows = 0;
    for (const ScreenErrorRow& r : rows) {
        int found = 0;
        for (const ScreenBound& b : kScreenBounds) {
            if (std::string(b.engine) != r.engine || std::string(b.against) != r.against || std::string(b.where) != r.where)
                continue;
            ++found;
            const std::string what = r.what;
            ASSERT_TRUE(what == "vertices" || what == "edge points") << what;
            const double bound = what == "vertices" ? b.vertices_px : b.edge_points_px;
            if (bound > 0) {
                EXPECT_LE(r.max_px, bound) << r.engine << " vs " << r.against << ", " << r.what << ", " << r.where;
            }
        }
        EXPECT_EQ(found, 1) << r.engine << " vs " << r.against << ", " << r.where << ": no bound (or two) in kScreenBounds";
        EXPECT_GT(r.samples, 1000 / noneuclid::test::kEmulatedStride) << r.engine << " " << r.what;
        if (std::string(r.engine) != "paper") {
            EXPECT_EQ(r.nonfinite, 0) << r.engine << " " << r.what;
        }
        if (std::string(r.engine) == "fixed") {
            ++fixed_rows;
            EXPECT_LE(r.max_px, 0.25) << r.what << ", " << r.where;  // the requirement
        }
    }
    EXPECT_EQ(fixed_rows, 12);
}

// The bound near the antipode is a tail: one seed's bodies found 0.138 px, others more
// (docs/accuracy.md: 0.156 px over 8 seeds, 0.194 over 64, 0.215 over 256). So the rows near
// the antipode are sampled here over kSeeds seeds of their population (NONEUCLID_ANTIPODE_SEEDS
// seeds if set: 256 gives the docs' figure), and every one is within the bounds of
// kScreenBounds, the largest printed.
TEST(Screen, NearTheAntipodeEverySeedWithinTheBound) {
    int seeds = 8 / noneuclid::test::kEmulatedStride;
    if (const char* e = std::getenv("NONEUCLID_ANTIPODE_SEEDS")) seeds = std::max(1, std::atoi(e));
    std::vector<ScreenErrorRow> rows(static_cast<std::size_t>(screen_error_row_count()));
    double most_edges = 0, most_vertices = 0;
    long samples = 0;
    for (int k = 0; k < seeds; ++k) {
        GeometryReportOptions o;
        o.seed += 1000 * static_cast<uint64_t>(k);
        o.antipode_only = true;
        const int n = measure_screen_error(o, rows.data(), static_cast<int>(rows.size()));
        ASSERT_EQ(n, 6);  // three comparisons near the antipode, vertices and edge points each
        for (int i = 0; i < n; ++i) {
            const ScreenErrorRow& r = rows[static_cast<std::size_t>(i)];
            ASSERT_EQ(std::string(r.engine), "fixed");
            EXPECT_EQ(r.nonfinite, 0);
            for (const ScreenBound& b : kScreenBounds) {
                if (std::string(b.against) != r.against || std::string(b.where) != r.where || std::string(b.engine) != "fixed")
                    continue;
                const bool edges = std::string(r.what) == "edge points";
                EXPECT_LE(r.max_px, edges ? b.edge_points_px : b.vertices_px)
                    << "seed " << o.seed << ": " << r.against << ", " << r.where << ", " << r.what;
            }
            if (std::string(r.where) == "near the antipode") {
                (std::string(r.what) == "edge points" ? most_edges : most_vertices) =
                    std::max(std::string(r.what) == "edge points" ? most_edges : most_vertices, r.max_px);
                samples += r.samples;
            }
        }
    }
    std::printf("near the antipode, %d seeds, %ld samples: vertices %.4f px, edge points %.4f px at most\n", seeds, samples,
                most_vertices, most_edges);
}


// Short distances: the haversine form keeps its digits where acos of the law of cosines (the
// paper) loses half of them, and at 1e-7 all of them.
TEST(Screen, ShortDistancesKeepTheirDigits) {
    std::vector<ShortDistanceRow> rows(static_cast<std::size_t>(short_distance_row_count()));
    const int n = measure_short_distance({}, rows.data(), static_cast<int>(rows.size()));
    ASSERT_EQ(n, short_distance_row_count());
    for (const ShortDistanceRow& r : rows) {
        const std::string e = r.engine;
        if (e == "double") {
            // inputs carry ~1e-15 absolute error (r up to 2.5), so relative ~1e-15 / length
            EXPECT_LE(r.max_rel, 2e-13 / r.length) << r.length;
            EXPECT_EQ(r.nonfinite, 0);
        }
        if (e == "fixed") {
            EXPECT_LE(r.max_rel * r.length, 6e-5);  // four Q16.16 steps
        }
        if (e == "paper" && r.length <= 1e-7) {
            EXPECT_GT(r.max_rel, 0.1);
        }
    }
}

// theta counter-clockwise as seen: north (theta = pi/2) is up the screen, i.e. smaller y.
TEST(Projection, ScreenYGrowsDownward) {
    const glm::dvec2 n = screen_point(1.0, kPi / 2, glm::dvec2(100, 100), 10);
    EXPECT_NEAR(n.x, 100, 1e-12);
    EXPECT_NEAR(n.y, 90, 1e-12);
    const ScreenPoint<fixed> e = to_screen(fixed(1), fixed(0), fixed(100), fixed(100), fixed(10));
    EXPECT_EQ(e.x, fixed(110));
    EXPECT_EQ(e.y, fixed(100));
    const ScreenPoint<fixed> s = to_screen(fixed(1), fixed(-kPi / 2), fixed(100), fixed(100), fixed(10));
    EXPECT_NEAR(s.y.to_double(), 110, 1e-3);
}
}  // namespace
