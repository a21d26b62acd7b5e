// Thick aliased polylines without notches at their joins: every pixel whose centre lies within
// half the line's width of one of the polyline's segments (the union of the segments' capsules,
// computed here in double from the same sub-pixel points) is lit, and no other, for sharp,
// right-angled and shallow turns, several widths, whole and in row bands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "render/canvas.hpp"
#include "render/raster.hpp"

using namespace noneuclid::render;

namespace {

constexpr int kW = 160, kH = 120;

// The distance from (x, y) to the segment a-b, px.
double to_segment(double x, double y, SubPoint a, SubPoint b) {
    const double ax = a.x / 256.0, ay = a.y / 256.0, bx = b.x / 256.0, by = b.y / 256.0;
    const double dx = bx - ax, dy = by - ay, L2 = dx * dx + dy * dy;
    const double t = L2 > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / L2, 0.0, 1.0) : 0.0;
    return std::hypot(x - ax - t * dx, y - ay - t * dy);
}

// A polyline of three points from `start` turning by `turn` degrees at the middle one.
std::vector<SubPoint> bent(double x, double y, double heading_deg, double turn_deg, double length) {
    const double h = heading_deg * M_PI / 180, t = (heading_deg + 180 - turn_deg) * M_PI / 180;
    const double mx = x + length * std::cos(h), my = y + length * std::sin(h);
    return {to_sub(x, y), to_sub(mx, my), to_sub(mx + length * std::cos(t + M_PI), my + length * std::sin(t + M_PI))};
}

struct Result {
    long inside = 0, missed = 0, extra = 0, join = 0;
};
Result check(const std::vector<SubPoint>& pts, double width, RowRange rows = {}) {
    std::vector<uint32_t> px(kW * kH, 0);
    const Canvas c(px.data(), kW, kH, kW * 4, PixelFormat::xrgb8888());
    draw_polyline(c, pts.data(), static_cast<int>(pts.size()), false, {255, 255, 255},
                  {false, static_cast<int32_t>(width * 256)}, rows);
    Result r;
    const double half = width / 2;
    for (int y = std::max(rows.y0, 0); y < std::min(rows.y1, kH); ++y)
        for (int x = 0; x < kW; ++x) {
            double d = 1e9, dj = 1e9;
            for (std::size_t i = 0; i + 1 < pts.size(); ++i) d = std::min(d, to_segment(x + 0.5, y + 0.5, pts[i], pts[i + 1]));
            for (std::size_t i = 1; i + 1 < pts.size(); ++i)
                dj = std::min(dj, std::hypot(x + 0.5 - pts[i].x / 256.0, y + 0.5 - pts[i].y / 256.0));
            // On the capsules' edge, either way: a segment reaching off the canvas is clipped to
            // it grown by its width and 2 px, its new end rounded to 1/256 px, which may turn it
            // by as much on the canvas.
            if (std::fabs(d - half) < 0.02) continue;
            const bool lit = px[static_cast<std::size_t>(y) * kW + x] != 0, in = d < half;
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
    std::uniform_real_distribution<double> x(-10, kW + 10), y(-10, kH + 10), w(1.2, 12);
    for (int k = 0; k < 300; ++k) {
        std::vector<SubPoint> pts;
        for (int i = 0; i < 6; ++i) pts.push_back(to_sub(x(rng), y(rng)));
        const double width = w(rng);
        const Result whole = check(pts, width);
        EXPECT_EQ(whole.missed, 0) << k;
        EXPECT_EQ(whole.extra, 0) << k;
        const int y0 = static_cast<int>(rng() % kH);
        const Result band = check(pts, width, {y0, y0 + 1 + static_cast<int>(rng() % 20)});
        EXPECT_EQ(band.missed, 0) << k << " band at " << y0;
        EXPECT_EQ(band.extra, 0) << k << " band at " << y0;
    }
}

}  // namespace
