// The rasteriser: every pixel of aliased lines against an independent reference, coverage of
// anti-aliased lines, clipping with canary borders and odd strides in every pixel format,
// lines far off the canvas, polylines, the shaded outside of the limit circle, row bands
// (RowRange) against the whole line as the reference. The pixel formats: test_pixel_formats.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "pixel_formats.hpp"
#include "render/canvas.hpp"
#include "render/raster.hpp"

using namespace noneuclid::render;
using noneuclid::test::kFormatCount;
using noneuclid::test::kFormats;

namespace {


// A buffer with a canary border: `pad` canary rows above and below, `pad` canary pixels left
// and right of each row, and an odd number of spare bytes at the end of each row (stride).
struct CanaryCanvas {
    int w, h, pad;
    PixelFormat f;
    std::ptrdiff_t stride;
    std::vector<uint8_t> bytes;
    static constexpr uint8_t kCanary = 0xA5;
    CanaryCanvas(int w_, int h_, PixelFormat f_, int pad_ = 3) : w(w_), h(h_), pad(pad_), f(f_) {
        stride = static_cast<std::ptrdiff_t>((w + 2 * pad) * f.bytes_per_pixel() + 3);  // odd
        bytes.assign(static_cast<std::size_t>(stride * (h + 2 * pad)), kCanary);
        Canvas c = canvas();
        c.clear({0, 0, 0});
    }
    Canvas canvas() { return Canvas(bytes.data() + pad * stride + pad * f.bytes_per_pixel(), w, h, stride, f); }
    // True if every byte outside the canvas still holds the canary.
    bool canary_intact() const {
        const int bpp = f.bytes_per_pixel();
        for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t>(bytes.size()); ++i) {
            const std::ptrdiff_t row = i / stride, col = i % stride;
            const bool in_rows = row >= pad && row < pad + h;
            const bool in_cols = col >= pad * bpp && col < (pad + w) * bpp;
            if (in_rows && in_cols) continue;
            if (bytes[static_cast<std::size_t>(i)] != kCanary) return false;
        }
        return true;
    }
};

// The pixels that are not black.
std::set<std::pair<int, int>> lit(const Canvas& c) {
    std::set<std::pair<int, int>> s;
    const uint32_t black = c.format().pack({0, 0, 0});
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x)
            if (c.get_word(x, y) != black) s.insert({x, y});
    return s;
}

// The reference for an aliased line: along the major axis, each pixel whose centre coordinate
// lies in [start, end), the pixel containing the exact line point there (computed in long
// double, rounded down), plus the pixels containing the two end points. *ties counts the
// columns whose exact line point lies on a pixel boundary (where rounding down decides).
std::set<std::pair<int, int>> reference_line(SubPoint a, SubPoint b, int w, int h, long* ties = nullptr) {
    std::set<std::pair<int, int>> s;
    const long double x0 = a.x / 256.0L, y0 = a.y / 256.0L, x1 = b.x / 256.0L, y1 = b.y / 256.0L;
    const bool xm = std::fabs(x1 - x0) >= std::fabs(y1 - y0);
    const long double u0 = xm ? x0 : y0, u1 = xm ? x1 : y1, v0 = xm ? y0 : x0, v1 = xm ? y1 : x1;
    auto add = [&](long long x, long long y) {
        if (x >= 0 && y >= 0 && x < w && y < h) s.insert({static_cast<int>(x), static_cast<int>(y)});
    };
    if (u0 != u1) {
        for (long long i = static_cast<long long>(std::floor(std::fmin(u0, u1))) - 1; i <= std::ceil(std::fmax(u0, u1)) + 1; ++i) {
            const long double c = i + 0.5L;
            const bool in = u1 > u0 ? (c >= u0 && c < u1) : (c <= u0 && c > u1);
            if (!in) continue;
            const long double v = v0 + (c - u0) * (v1 - v0) / (u1 - u0);
            const long long j = static_cast<long long>(std::floor(v));
            if (ties && v == std::floor(v)) ++*ties;
            xm ? add(i, j) : add(j, i);
        }
    }
    add(static_cast<long long>(std::floor(x0)), static_cast<long long>(std::floor(y0)));
    add(static_cast<long long>(std::floor(x1)), static_cast<long long>(std::floor(y1)));
    return s;
}

TEST(Raster, AliasedLinesMatchTheReferencePixelForPixel) {
    std::mt19937 rng(1);
    std::uniform_int_distribution<int32_t> cx(0, 64 * 256 - 1), cy(0, 48 * 256 - 1);
    std::vector<uint32_t> buf(64 * 48);
    // What the sample covered: the cases the reference tells apart.
    long shallow = 0, steep = 0, axis = 0, points = 0, ties = 0, pixels = 0;
    for (int k = 0; k < 20000; ++k) {
        const SubPoint a{cx(rng), cy(rng)}, b{k % 10 == 0 ? a.x : cx(rng), k % 10 == 1 ? a.y : cy(rng)};
        std::fill(buf.begin(), buf.end(), 0);
        Canvas c(buf.data(), 64, 48, 64 * 4, PixelFormat::xrgb8888());
        draw_line(c, a, b, {255, 255, 255});
        const auto want = reference_line(a, b, 64, 48, &ties);
        // A column centre exactly on a pixel boundary in v is a tie both sides resolve by
        // rounding down, exactly; long double holds these coordinates exactly.
        ASSERT_EQ(lit(c), want) << "line (" << a.x << "," << a.y << ") -> (" << b.x << "," << b.y << ") / 256";
        const int32_t dx = std::abs(b.x - a.x), dy = std::abs(b.y - a.y);
        (dx == 0 && dy == 0 ? points : (dx == 0 || dy == 0) ? axis : dx >= dy ? shallow : steep)++;
        pixels += static_cast<long>(want.size());
    }
    // The sample is only as good as what it covers: lines of both major axes, axis-aligned ones,
    // ties, and long lines (a random line across the 64x48 canvas averages ~27 pixels).
    EXPECT_GT(shallow, 5000);
    EXPECT_GT(steep, 5000);
    EXPECT_GT(axis, 3000);  // every tenth line vertical, every tenth horizontal
    EXPECT_GT(ties, 100);
    EXPECT_GT(pixels, 20000 * 15);
    RecordProperty("shallow", static_cast<int>(shallow));
    RecordProperty("steep", static_cast<int>(steep));
    RecordProperty("axis_aligned", static_cast<int>(axis));
    RecordProperty("single_points", static_cast<int>(points));
    RecordProperty("ties", static_cast<int>(ties));
    RecordProperty("pixels", static_cast<int>(pixels));
}

TEST(Raster, AntiAliasedCoverageSumsToLengthTimesWidth) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> px(10, 190);
    std::vector<uint32_t> buf(200 * 200);
    for (int k = 0; k < 2000; ++k) {
        const double x0 = px(rng), y0 = px(rng), x1 = px(rng), y1 = px(rng);
        const double width = (k % 3 == 0) ? 2.5 : 1.0;
        std::fill(buf.begin(), buf.end(), 0);
        Canvas c(buf.data(), 200, 200, 200 * 4, PixelFormat::xrgb8888());
        const SubPoint a = to_sub(x0, y0), b = to_sub(x1, y1);
        draw_line(c, a, b, {255, 255, 255}, {true, static_cast<int32_t>(width * 256)});
        double sum = 0;
        for (uint32_t w : buf) sum += (w & 0xFF) / 255.0;
        const double L = std::hypot((b.x - a.x) / 256.0, (b.y - a.y) / 256.0);
        const double major = std::fmax(std::fabs(b.x - a.x), std::fabs(b.y - a.y)) / 256.0;
        // The band covers the whole columns from start to end: up to one column (L/major * width)
        // more or less than the exact length, plus half an 8-bit step per pixel written.
        const double per_column = width * L / std::fmax(major, 1e-9);
        EXPECT_NEAR(sum, L * width, per_column + 3 * major * 0.5 / 255 + 1e-9) << k;
    }
}

TEST(Raster, ClippingNeverWritesOutsideInAnyFormatOrStride) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> far(-3000, 3000), huge(-1e12, 1e12);
    for (const PixelFormat& f : kFormats) {
        CanaryCanvas g(37, 23, f);  // odd sizes, odd stride
        const Canvas c = g.canvas();
        for (int k = 0; k < 3000; ++k) {
            const bool h = k % 5 == 0;
            const SubPoint a = to_sub(h ? huge(rng) : far(rng), h ? huge(rng) : far(rng));
            const SubPoint b = to_sub(k % 7 == 0 ? 18.5 : far(rng), far(rng));
            const LineStyle style{k % 2 == 1, k % 3 == 0 ? 1200 : 256};
            draw_line(c, a, b, {255, 128, 7}, style);
        }
        const SubPoint loop[] = {to_sub(-5, -5), to_sub(50, 10), to_sub(10, 40), to_sub(36.9, 22.9)};
        draw_polyline(c, loop, 4, true, {1, 2, 3});
        shade_outside_circle(c, 18, 11, 10, {9, 9, 9});
        EXPECT_TRUE(g.canary_intact()) << f.name;
        EXPECT_FALSE(lit(c).empty()) << f.name << ": something was drawn";
    }
}

TEST(Raster, LinesOffTheCanvasOrWithHugeCoordinatesWriteNothing) {
    CanaryCanvas g(40, 30, PixelFormat::rgb565());
    const Canvas c = g.canvas();
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    const std::pair<SubPoint, SubPoint> lines[] = {
        {to_sub(-100, -100), to_sub(-1, 500)},       // left of the canvas
        {to_sub(45, -10), to_sub(1e9, 1e9)},          // right
        {to_sub(-1e300, 5), to_sub(-1e300, 20)},      // absurdly far
        {to_sub(nan, 3), to_sub(5, nan)},             // NaN maps far outside
        {to_sub(-inf, -inf), to_sub(-inf, 1e6)},
        {to_sub(0, -3), to_sub(39.9, -1.6)},          // just above (a 1-px band ends at -1.1)
    };
    for (const auto& [a, b] : lines) {
        draw_line(c, a, b, {255, 255, 255});
        draw_line(c, a, b, {255, 255, 255}, {true, 256});
        if (a.y != to_sub(0, -3).y) draw_line(c, a, b, {255, 255, 255}, {false, 2000});  // 7.8 px wide
    }
    EXPECT_TRUE(lit(c).empty());
    EXPECT_TRUE(g.canary_intact());
    // A line across with both ends absurdly far: only its visible part is drawn, in time.
    draw_line(c, to_sub(-1e12, 15.5), to_sub(1e12, 15.5), {255, 255, 255});
    EXPECT_EQ(lit(c).size(), 40u);
    EXPECT_TRUE(g.canary_intact());
}

void count_visit(int x, int y, int, void* ctx) { (*static_cast<std::map<std::pair<int, int>, int>*>(ctx))[{x, y}]++; }

TEST(Raster, PolylinesPlotSharedPointsOnce) {
    // Polylines that never come back over themselves (x increasing by >= 3 px per point, any
    // slope): the pixel of every shared point is visited at most once. (Two segments meeting at
    // an acute angle may still both cross a pixel next to their shared point: that is their
    // geometry, not the shared point.)
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> py(0, 60), step(3, 12);
    long shared_points_visited = 0;
    for (int k = 0; k < 500; ++k) {
        SubPoint pts[6];
        double x = step(rng) - 2;
        for (SubPoint& p : pts) p = to_sub(x, py(rng)), x += step(rng);
        std::map<std::pair<int, int>, int> counts;
        visit_polyline(64, 64, pts, 6, false, {}, count_visit, &counts);
        for (int i = 1; i < 6; ++i) {
            const std::pair<int, int> v{pts[i].x >> 8, pts[i].y >> 8};
            const auto it = counts.find(v);  // (the half-open rule may leave it to a neighbour)
            ASSERT_LE(it == counts.end() ? 0 : it->second, 1) << "polyline " << k << " point " << i;
            shared_points_visited += it != counts.end();
        }
    }
    // Most shared points do get their pixel (the check above is not vacuous): of 500 * 5.
    EXPECT_GT(shared_points_visited, 1500);
    RecordProperty("shared_points_visited", static_cast<int>(shared_points_visited));
    // A closed square: 4 segments, every pixel of its outline exactly once.
    const SubPoint sq[] = {to_sub(10.5, 10.5), to_sub(20.5, 10.5), to_sub(20.5, 20.5), to_sub(10.5, 20.5)};
    std::map<std::pair<int, int>, int> counts;
    visit_polyline(64, 64, sq, 4, true, {}, count_visit, &counts);
    EXPECT_EQ(counts.size(), 40u);
    for (const auto& [p, n] : counts) EXPECT_EQ(n, 1);
}

TEST(Raster, ThickLinesAndTheShadedOutside) {
    std::vector<uint32_t> buf(40 * 30, 0);
    Canvas c(buf.data(), 40, 30, 40 * 4, PixelFormat::xrgb8888());
    draw_line(c, to_sub(5, 10.5), to_sub(30, 10.5), {255, 255, 255}, {false, 3 * 256});
    std::set<int> rows;
    for (auto [x, y] : lit(c)) rows.insert(y);
    EXPECT_EQ(rows, (std::set<int>{9, 10, 11}));
    std::fill(buf.begin(), buf.end(), 0);
    shade_outside_circle(c, 20, 15, 12.3, {255, 255, 255});
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) {
            const bool outside = std::hypot(x + 0.5 - 20, y + 0.5 - 15) >= 12.3;
            EXPECT_EQ(c.get_word(x, y) != 0, outside) << x << "," << y;
        }
}

// ---- row bands ----------------------------------------------------------------------------

// Line patterns for the band tests: random end points on and around the canvas, points far off
// it and huge ones, horizontal, vertical and diagonal lines, end points on pixel centres and
// edges, single points; polylines of 1 to 6 points, open and closed.
struct Pattern {
    std::vector<SubPoint> pts;
    bool closed;
};
Pattern random_pattern(std::mt19937& rng, int w, int h) {
    std::uniform_int_distribution<int> kind(0, 9), count(1, 6), coin(0, 1);
    std::uniform_int_distribution<int32_t> sx(-20 * 256, (w + 20) * 256), sy(-20 * 256, (h + 20) * 256);
    std::uniform_int_distribution<int32_t> px(-2, w + 2), py(-2, h + 2), small(-6 * 256, 6 * 256);
    Pattern p;
    p.closed = coin(rng) == 1;
    const int n = count(rng);
    for (int i = 0; i < n; ++i) {
        SubPoint q{sx(rng), sy(rng)};
        const SubPoint prev = p.pts.empty() ? q : p.pts.back();
        switch (kind(rng)) {
            case 0: q.y = prev.y; break;                                   // horizontal
            case 1: q.x = prev.x; break;                                   // vertical
            case 2: q = {prev.x + (q.x - prev.x), prev.y + (q.x - prev.x)}; break;  // 45 degrees
            case 3: q = {px(rng) * 256 + 128, py(rng) * 256 + 128}; break;  // a pixel centre
            case 4: q = {px(rng) * 256, py(rng) * 256}; break;              // a pixel corner
            case 5: q = {prev.x + small(rng), prev.y + small(rng)}; break;  // short
            case 6: q = prev; break;                                       // a point
            case 7: q = to_sub(coin(rng) ? 3e6 : -3e6, py(rng)); break;    // far off, crossing
            case 8: q = {q.x, coin(rng) ? (h + 400) * 256 : -400 * 256}; break;  // steep, off
            default: break;
        }
        p.pts.push_back(q);
    }
    return p;
}
const LineStyle kBandStyles[] = {{false, 256}, {false, 384}, {false, 3 * 256}, {true, 256}, {true, 640}, {true, 100}};

struct Visit {
    int x, y, a;
    friend bool operator==(const Visit&, const Visit&) = default;
};
void record_visit(int x, int y, int a, void* ctx) { static_cast<std::vector<Visit>*>(ctx)->push_back({x, y, a}); }

// One band: in its rows, the same pixels as the whole line, anti-aliased the same coverages in
// the same order; outside them, nothing (visited or written).
TEST(Raster, RowBandsWriteExactlyTheWholeLinesPixelsInTheirRows) {
    std::mt19937 rng(11);
    const int W = 97, H = 61;
    std::uniform_int_distribution<int> band(-5, H + 5), noise(0, 255);
    int bands_with_pixels = 0;  // the comparisons are not vacuous: most bands hold some line
    for (int k = 0; k < 3000; ++k) {
        const Pattern pat = random_pattern(rng, W, H);
        const LineStyle st = kBandStyles[k % 6];
        int y0 = band(rng), y1 = band(rng);
        if (y0 > y1) std::swap(y0, y1);
        if (k % 7 == 0) y1 = y0 + 1;  // single rows
        const int n = static_cast<int>(pat.pts.size());
        std::vector<Visit> full, part;
        visit_polyline(W, H, pat.pts.data(), n, pat.closed, st, record_visit, &full);
        visit_polyline(W, H, pat.pts.data(), n, pat.closed, st, record_visit, &part, {y0, y1});
        std::vector<Visit> want;
        for (const Visit& v : full)
            if (v.y >= y0 && v.y < y1) want.push_back(v);
        bands_with_pixels += !want.empty();
        for (const Visit& v : part) ASSERT_TRUE(v.y >= y0 && v.y < y1 && v.x >= 0 && v.x < W) << "pattern " << k;
        if (st.antialias) {
            ASSERT_EQ(part, want) << "pattern " << k << " rows " << y0 << ".." << y1;
        } else {  // aliased: the same set (a shared point may be skipped in one and not the other)
            auto key = [](const std::vector<Visit>& vs) {
                std::set<std::pair<int, int>> out;
                for (const Visit& v : vs) out.insert({v.x, v.y});
                return out;
            };
            ASSERT_EQ(key(part), key(want)) << "pattern " << k << " rows " << y0 << ".." << y1;
        }
        // The same on a canvas over a noisy background (blends depend on it), every format.
        const PixelFormat f = kFormats[static_cast<std::size_t>(k) % kFormatCount];
        CanaryCanvas a(W, H, f), b(W, H, f);
        const Canvas ca = a.canvas(), cb = b.canvas();
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const Rgb bg{static_cast<uint8_t>(noise(rng)), static_cast<uint8_t>(noise(rng)), static_cast<uint8_t>(noise(rng))};
                ca.set(x, y, bg), cb.set(x, y, bg);
            }
        std::vector<uint32_t> before;  // the background, row by row
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) before.push_back(ca.get_word(x, y));
        const Rgb col{static_cast<uint8_t>(noise(rng)), 200, 40};
        draw_polyline(ca, pat.pts.data(), n, pat.closed, col, st);
        draw_polyline(cb, pat.pts.data(), n, pat.closed, col, st, {y0, y1});
        ASSERT_TRUE(b.canary_intact());
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const bool in = y >= y0 && y < y1;
                ASSERT_EQ(cb.get_word(x, y), in ? ca.get_word(x, y) : before[static_cast<std::size_t>(y * W + x)])
                    << "pattern " << k << " pixel " << x << "," << y << " rows " << y0 << ".." << y1;
            }
        if (n == 2 && !pat.closed) {  // draw_line too, with and without its end points
            for (bool end : {true, false}) {
                CanaryCanvas c(W, H, f), d(W, H, f);
                draw_line(c.canvas(), pat.pts[0], pat.pts[1], col, st, end);
                draw_line(d.canvas(), pat.pts[0], pat.pts[1], col, st, end, {y0, y1});
                for (int y = 0; y < H; ++y)
                    for (int x = 0; x < W; ++x)
                        ASSERT_EQ(d.canvas().get_word(x, y), y >= y0 && y < y1 ? c.canvas().get_word(x, y) : f.pack({0, 0, 0}))
                            << "line " << k;
            }
        }
    }
    EXPECT_GT(bands_with_pixels, 1000);
    RecordProperty("bands_with_pixels", bands_with_pixels);
}

// Many overlapping polylines drawn band by band, each band's in the same order, over a random
// split of the rows: the same canvas as drawing them whole (what draw_world's threads do).
TEST(Raster, RowBandsTiledMakeTheSamePicture) {
    std::mt19937 rng(12);
    const int W = 131, H = 83;
    std::uniform_int_distribution<int> cut(1, 20), noise(0, 255);
    for (int k = 0; k < 300; ++k) {
        const PixelFormat f = kFormats[static_cast<std::size_t>(k) % kFormatCount];
        std::vector<Pattern> pats;
        std::vector<Rgb> cols;
        for (int i = 0; i < 25; ++i) {
            pats.push_back(random_pattern(rng, W, H));
            cols.push_back({static_cast<uint8_t>(noise(rng)), static_cast<uint8_t>(noise(rng)), static_cast<uint8_t>(noise(rng))});
        }
        const LineStyle st = kBandStyles[k % 6];
        CanaryCanvas a(W, H, f), b(W, H, f);
        for (std::size_t i = 0; i < pats.size(); ++i)
            draw_polyline(a.canvas(), pats[i].pts.data(), static_cast<int>(pats[i].pts.size()), pats[i].closed, cols[i], st);
        for (int y0 = -3; y0 < H + 3;) {
            const int y1 = y0 + (k % 5 == 0 ? 1 : cut(rng));
            for (std::size_t i = 0; i < pats.size(); ++i)
                draw_polyline(b.canvas(), pats[i].pts.data(), static_cast<int>(pats[i].pts.size()), pats[i].closed, cols[i], st, {y0, y1});
            y0 = y1;
        }
        ASSERT_TRUE(b.canary_intact());
        ASSERT_EQ(a.bytes, b.bytes) << "set " << k << " format " << f.name;
        ASSERT_NE(a.bytes, CanaryCanvas(W, H, f).bytes) << "set " << k << ": nothing was drawn, so nothing was compared";
    }
}

}  // namespace
