// Polylines at their joins and ends, against the segments computed here in double from the
// same sub-pixel points:
//  - thick aliased polylines without notches: every pixel whose centre lies within half the
//    line's width of one of the segments (the union of their capsules) is lit, and no other,
//    for sharp, right-angled and shallow turns, several widths, whole and in row bands;
//  - thin aliased polylines without gaps: every point of every segment lies within sqrt 1.25 px
//    of a lit pixel's centre (raster.hpp), folds back, turns across the diagonals and the ends
//    included, and every lit pixel's centre within sqrt 0.5 px of a segment (it holds a point
//    of the line).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "render/canvas.hpp"
#include "render/raster.hpp"
#include "test_common.hpp"

using namespace noneuclid::render;

namespace {

using noneuclid::test::kPi;
using noneuclid::test::deg;

constexpr int kJoinsW = 160, kJoinsH = 120;

// The distance from (x, y) to the segment a-b, px.
double to_segment(double x, double y, SubPoint a, SubPoint b) {
    const double ax = a.x / 256.0, ay = a.y / 256.0, bx = b.x / 256.0, by = b.y / 256.0;
    const double dx = bx - ax, dy = by - ay, L2 = dx * dx + dy * dy;
    const double t = L2 > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / L2, 0.0, 1.0) : 0.0;
    return std::hypot(x - ax - t * dx, y - ay - t * dy);
}

// A polyline of three points from `start` turning by `turn` degrees at the middle one.
std::vector<SubPoint> bent(double x, double y, double heading_deg, double turn_deg, double length) {
    const double h = deg(heading_deg), t = deg(heading_deg + 180 - turn_deg);
    const double mx = x + length * std::cos(h), my = y + length * std::sin(h);
    return {to_sub(x, y), to_sub(mx, my), to_sub(mx + length * std::cos(t + kPi), my + length * std::sin(t + kPi))};
}

struct Result {
    long inside = 0, missed = 0, extra = 0, join = 0;
};
Result check(const std::vector<SubPoint>& pts, double width, RowRange rows = {}) {
    std::vector<uint32_t> px(kJoinsW * kJoinsH, 0);
    const Canvas c(px.data(), kJoinsW, kJoinsH, kJoinsW * 4, PixelFormat::xrgb8888());
    draw_polyline(c, pts.data(), static_cast<int>(pts.size()), false, {255, 255, 255},
                  {false, static_cast<int32_t>(width * 256)}, rows);
    Result r;
    const double half = width / 2;
    for (int y = std::max(rows.y0, 0); y < std::min(rows.y1, kJoinsH); ++y)
        for (int x = 0; x < kJoinsW; ++x) {
            double d = 1e9, dj = 1e9;
            for (std::size_t i = 0; i + 1 < pts.size(); ++i) d = std::min(d, to_segment(x + 0.5, y + 0.5, pts[i], pts[i + 1]));
            for (std::size_t i = 1; i + 1 < pts.size(); ++i)
                dj = std::min(dj, std::hypot(x + 0.5 - pts[i].x / 256.0, y + 0.5 - pts[i].y / 256.0));
            // On the capsules' edge, either way: a segment reaching off the canvas is clipped to
            // it grown by its width and 2 px, its new end rounded to 1/256 px, which may turn it
            // by as much on the canvas.
            if (std::fabs(d - half) < 0.02) continue;
            const bool lit = px[static_cast<std::size_t>(y) * kJoinsW + x] != 0, in = d < half;
            r.inside += in, r.join += in && dj < width;
            r.missed += in && !lit, r.extra += lit && !in;
        }
    return r;
}

TEST(ThickJoins, EveryPixelWithinHalfTheWidthOfASegmentIsLitAndNoOther) {
    long joins = 0;
    for (double width : {2.0, 3.0, 5.5, 9.0})
        for (double turn : {170.0, 150.0, 120.0, 90.0, 45.0, 20.0, 5.0, -35.0, -100.0, -165.0})
            for (double heading : {0.0, 17.0, 45.0, 73.0, 90.0, 200.0, 301.0}) {
                const auto pts = bent(80.3, 60.7, heading, turn, 40);
                const Result r = check(pts, width);
                EXPECT_EQ(r.missed, 0) << "width " << width << " turn " << turn << " heading " << heading;
                EXPECT_EQ(r.extra, 0) << "width " << width << " turn " << turn << " heading " << heading;
                EXPECT_GT(r.inside, 40 * width) << "width " << width;  // not vacuous
                joins += r.join;
            }
    EXPECT_GT(joins, 10000);
    RecordProperty("join_pixels", static_cast<int>(joins));
}

TEST(ThickJoins, RandomPolylinesWholeAndInRowBands) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> x(-10, kJoinsW + 10), y(-10, kJoinsH + 10), w(1.2, 12);
    for (int k = 0; k < 300; k += noneuclid::test::kEmulatedStride) {
        std::vector<SubPoint> pts;
        for (int i = 0; i < 6; ++i) pts.push_back(to_sub(x(rng), y(rng)));
        const double width = w(rng);
        const Result whole = check(pts, width);
        EXPECT_EQ(whole.missed, 0) << k;
        EXPECT_EQ(whole.extra, 0) << k;
        const int y0 = static_cast<int>(rng() % kJoinsH);
        const Result band = check(pts, width, {y0, y0 + 1 + static_cast<int>(rng() % 20)});
        EXPECT_EQ(band.missed, 0) << k << " band at " << y0;
        EXPECT_EQ(band.extra, 0) << k << " band at " << y0;
    }
}

void collect(int x, int y, int, void* ctx) { static_cast<std::set<std::pair<int, int>>*>(ctx)->insert({x, y}); }

TEST(ThinJoins, EveryPointOfAPolylineIsWithinAPixelOfALitPixel) {
    std::mt19937 rng(1125);
    std::uniform_real_distribution<double> u(0, 1);
    double worst_point = 0, worst_pixel = 0;
    long folds = 0;
    for (int k = 0; k < 3000; k += noneuclid::test::kEmulatedStride) {
        // 2 to 7 points on the canvas, each turning from the last heading by any angle (a fifth
        // of them folding straight back), 0.3 to 25 px apart; open or closed.
        std::vector<SubPoint> pts;
        double px = 30 + 100 * u(rng), py = 30 + 60 * u(rng), heading = 2 * kPi * u(rng);
        const int n = 2 + static_cast<int>(6 * u(rng));
        pts.push_back(to_sub(px, py));
        for (int i = 1; i < n; ++i) {
            const bool fold = u(rng) < 0.2;
            folds += fold;
            heading += fold ? kPi : 2 * kPi * u(rng) - kPi;
            const double len = 0.3 + 24.7 * u(rng);
            px = std::clamp(px + len * std::cos(heading), 1.0, kJoinsW - 1.0);
            py = std::clamp(py + len * std::sin(heading), 1.0, kJoinsH - 1.0);
            pts.push_back(to_sub(px, py));
        }
        const bool closed = u(rng) < 0.5;
        std::set<std::pair<int, int>> lit;
        visit_polyline(kJoinsW, kJoinsH, pts.data(), n, closed, {}, collect, &lit);
        const std::size_t segments = closed ? pts.size() : pts.size() - 1;
        for (std::size_t i = 0; i < segments; ++i) {
            const SubPoint a = pts[i], b = pts[(i + 1) % pts.size()];
            const double L = std::hypot(b.x - a.x, b.y - a.y) / 256.0;
            const int steps = 1 + static_cast<int>(L / 0.02);
            for (int s = 0; s <= steps; ++s) {
                const double t = double(s) / steps;
                const double x = (a.x + t * (b.x - a.x)) / 256.0, y = (a.y + t * (b.y - a.y)) / 256.0;
                double best = 1e9;
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) {
                        const int cx = static_cast<int>(std::floor(x)) + dx, cy = static_cast<int>(std::floor(y)) + dy;
                        if (lit.count({cx, cy})) best = std::min(best, std::hypot(x - cx - 0.5, y - cy - 0.5));
                    }
                worst_point = std::max(worst_point, best);
                ASSERT_LE(best, std::sqrt(1.25) + 1e-9) << "polyline " << k << " segment " << i << " at (" << x << ", " << y << ")";
            }
        }
        for (const auto& [x, y] : lit) {
            double d = 1e9;
            for (std::size_t i = 0; i < segments; ++i) d = std::min(d, to_segment(x + 0.5, y + 0.5, pts[i], pts[(i + 1) % pts.size()]));
            worst_pixel = std::max(worst_pixel, d);
            ASSERT_LE(d, std::sqrt(0.5) + 1e-9) << "polyline " << k << " pixel (" << x << ", " << y << ")";
        }
    }
    EXPECT_GT(folds, 1000 / noneuclid::test::kEmulatedStride);
    RecordProperty("worst_point_px", std::to_string(worst_point));
    RecordProperty("worst_pixel_px", std::to_string(worst_pixel));
}

}  // namespace
