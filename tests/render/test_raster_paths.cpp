// The rasteriser's and the backdrop's fast paths write what the plain loops write, bit for
// bit: draw_polyline (32-bit loops, byte offsets, skipped checks) against the generic 64-bit
// loop behind visit_polyline; the backdrop as spans against Canvas::clear +
// shade_outside_circle, and its limit circle line against the band around the circle; its
// rows kept from frame to frame against its rows computed as drawn; fill_span against the
// pixels one by one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "render/draw_world.hpp"
#include "test_common.hpp"

namespace {

using namespace noneuclid;
using fx::fixed;
using test::kPi;

TEST(FastPaths, BackdropSpansAreClearPlusShade) {
    for (render::PixelFormat f : {render::PixelFormat::rgb565(), render::PixelFormat::xrgb8888(), render::PixelFormat::rgb888()})
        for (auto [w, h] : {std::pair{800, 480}, std::pair{33, 97}, std::pair{1, 1}, std::pair{480, 480}, std::pair{101, 40}})
            for (double R : {kPi, 1.0, 0.3})
                for (bool shade : {true, false}) {
                    const std::size_t stride = static_cast<std::size_t>(w * f.bytes_per_pixel() + 8);
                    std::vector<uint8_t> x(stride * static_cast<std::size_t>(h), 0xAB), y = x;
                    const render::Canvas cx(x.data(), w, h, static_cast<std::ptrdiff_t>(stride), f);
                    const render::Canvas cy(y.data(), w, h, static_cast<std::ptrdiff_t>(stride), f);
                    render::DrawOptions o;
                    o.shade_outside = shade;
                    o.rim_line = false;
                    const auto m = render::ScreenMap<double>::of(cx, 0.0, R, o.projection);
                    render::draw_backdrop(cx, m, o);
                    cy.clear(o.background);
                    if (shade) render::shade_outside_circle(cy, m.cx, m.cy, m.rim, o.outside);
                    ASSERT_EQ(x, y) << w << "x" << h << " R " << R << " shade " << shade;
                }
}

// The limit circle's line in the backdrop: aliased, exactly the pixels whose centre lies within
// half the line's width of the circle (those within 1e-9 px of that band's edges, where the
// test's hypot and the backdrop's square root may round apart, left out); anti-aliased, each
// pixel's coverage, 1 - (distance - half width) clamped, blended over the backdrop, to within
// one level. Every row band drawn on its own gives the same picture.
TEST(FastPaths, TheLimitCircleLineIsTheBandAroundTheCircle) {
    const render::PixelFormat f = render::PixelFormat::xrgb8888();
    for (auto [w, h] : {std::pair{800, 480}, std::pair{101, 40}, std::pair{480, 480}})
        for (int32_t width : {256, 640})
            for (bool aa : {false, true}) {
                std::vector<uint32_t> px(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
                const render::Canvas c(px.data(), w, h, static_cast<std::ptrdiff_t>(w) * 4, f);
                render::DrawOptions o;
                o.antialias = aa, o.line_width = width;
                const auto m = render::ScreenMap<double>::of(c, 0.0, 3.0, o.projection);
                render::draw_backdrop(c, m, o);
                const double half = width / 512.0;
                long ring = 0;
                for (int y = 0; y < h; ++y)
                    for (int x = 0; x < w; ++x) {
                        const double d = std::hypot(x + 0.5 - static_cast<double>(m.cx), y + 0.5 - static_cast<double>(m.cy));
                        const render::Rgb base = d < m.rim ? o.background : o.outside;
                        const render::Rgb got = c.get(x, y);
                        if (!aa) {
                            const double off = std::fabs(d - m.rim);
                            if (std::fabs(off - half) < 1e-9 || std::fabs(d - m.rim) < 1e-9) continue;
                            const render::Rgb want = off < half || (off == half && d > m.rim) ? o.rim : base;
                            ASSERT_TRUE(got == want) << w << "x" << h << " pixel " << x << "," << y;
                            ring += off < half;
                        } else {
                            const double cover = std::clamp(half + 0.5 - std::fabs(d - m.rim), 0.0, 1.0);
                            auto mix = [cover](uint8_t a, uint8_t b) { return a + (b - a) * cover; };
                            ASSERT_NEAR(got.r, mix(base.r, o.rim.r), 1.01) << x << "," << y;
                            ASSERT_NEAR(got.g, mix(base.g, o.rim.g), 1.01) << x << "," << y;
                            ASSERT_NEAR(got.b, mix(base.b, o.rim.b), 1.01) << x << "," << y;
                            ring += cover > 0;
                        }
                    }
                EXPECT_GT(ring, 2 * 3.14 * m.rim * half) << w << "x" << h;  // the line is there
                std::vector<uint32_t> bands(px.size(), 0);
                const render::Canvas cb(bands.data(), w, h, static_cast<std::ptrdiff_t>(w) * 4, f);
                for (int y0 = 0; y0 < h; y0 += 7) render::draw_backdrop_rows(cb, render::limit_circle(m), o, y0, y0 + 7);
                ASSERT_EQ(px, bands) << w << "x" << h;
            }
}

// The backdrop's rows kept (BackdropRows, reserved for the canvas's height, as the firmware
// does) draw what the rows computed as drawn do, and are computed again when the circle, the
// options or the canvas change between frames; with too little room reserved they are not used.
TEST(FastPaths, KeptBackdropRowsDrawTheSamePixels) {
    const render::PixelFormat f = render::PixelFormat::rgb565();
    render::BackdropRows kept;
    kept.reserve(480);
    int frames = 0;
    for (auto [w, h] : {std::pair{240, 240}, std::pair{101, 40}, std::pair{480, 480}, std::pair{240, 240}})
        for (double R : {kPi, 0.3})
            for (int32_t width : {256, 640})
                for (bool aa : {false, true})
                    for (bool shade : {true, false})
                        for (bool rim : {true, false}) {
                            std::vector<uint16_t> x(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 1), y = x;
                            const render::Canvas cx(x.data(), w, h, static_cast<std::ptrdiff_t>(w) * 2, f);
                            const render::Canvas cy(y.data(), w, h, static_cast<std::ptrdiff_t>(w) * 2, f);
                            render::DrawOptions o;
                            o.antialias = aa, o.line_width = width, o.shade_outside = shade, o.rim_line = rim;
                            const auto m = render::ScreenMap<double>::of(cx, 0.0, R, o.projection);
                            render::draw_backdrop(cx, m, o);
                            ASSERT_NE(kept.rows(cy, render::limit_circle(m), o), nullptr);
                            render::draw_backdrop(cy, m, o, &kept);
                            ASSERT_EQ(x, y) << w << "x" << h << " R " << R << " width " << width << " aa " << aa;
                            ++frames;
                        }
    EXPECT_EQ(frames, 128);
    render::BackdropRows small;
    small.reserve(100);
    std::vector<uint16_t> px(240 * 240);
    const render::Canvas c(px.data(), 240, 240, 480, f);
    EXPECT_EQ(small.rows(c, render::LimitCircle{120, 120, 120}, render::DrawOptions{}), nullptr);
}

// What draw_polyline writes, built from visit_polyline's pixels: the generic 64-bit loop (no
// byte offsets, no 32-bit error terms, no skipped checks), each pixel set or blended through
// the Canvas's own word access and Canvas::blend (which the fast blends must equal).
struct VisitInto {
    const render::Canvas* c;
    render::Rgb color;
};
void put_visited(int x, int y, int alpha, void* ctx) {
    const auto& v = *static_cast<VisitInto*>(ctx);
    if (alpha >= 255) return v.c->set(x, y, v.color);
    v.c->blend(x, y, v.color, alpha);
}

// A sub-pixel coordinate along one axis of a canvas `side` px long: mostly on it, often near or
// over its borders, sometimes far off or at the ends of the int32 range.
int32_t random_coordinate(std::mt19937& rng, int side) {
    const uint32_t kind = rng() % 16;
    const int32_t s = side * 256;
    if (kind < 8) return static_cast<int32_t>(rng() % static_cast<uint32_t>(s));
    if (kind < 12) return static_cast<int32_t>(rng() % 2048) - 1024 + (rng() % 2 ? 0 : s);  // a border, +-4 px
    if (kind == 12) return static_cast<int32_t>(rng() % (8u << 20)) - (4 << 20);               // +-16384 px
    if (kind == 13) return static_cast<int32_t>(rng());                                          // anywhere in int32
    if (kind == 14) return rng() % 2 ? INT32_MAX : INT32_MIN + 1;
    return (rng() % 2 ? 1 : -1) * (1 << 30);  // to_sub's saturation
}

TEST(FastPaths, RasterIntoACanvasIsTheGenericLoop) {
    const render::PixelFormat formats[] = {render::PixelFormat::rgb565(),   render::PixelFormat::bgr565(),
                                           render::PixelFormat::xrgb8888(), render::PixelFormat::xbgr8888(),
                                           render::PixelFormat::rgb888(),   render::PixelFormat::bgr888(),
                                           render::PixelFormat::rgba8888()};
    // Small canvases (the 32-bit paths) and ones over 8192 px on a side (the 64-bit ones).
    const std::pair<int, int> sizes[] = {{61, 37}, {203, 120}, {5, 300}, {9000, 3}, {2, 8300}};
    const render::LineStyle styles[] = {{false, 256}, {false, 100}, {true, 256}, {false, 700}, {true, 600}};
    std::mt19937 rng(7);
    long lines = 0;
    for (const auto& f : formats)
        for (auto [w, h] : sizes) {
            const int bpp = f.bytes_per_pixel();
            const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(w) * bpp + 5;  // odd spare bytes
            // Random bytes under the lines (blends see them) and around the canvas; the lines pile up.
            std::vector<uint8_t> a(static_cast<std::size_t>(stride) * static_cast<std::size_t>(h) + 64);
            for (auto& x : a) x = static_cast<uint8_t>(rng());
            std::vector<uint8_t> b = a;
            const render::Canvas ca(a.data() + 32, w, h, stride, f), cb(b.data() + 32, w, h, stride, f);
            for (int k = 0; k < 300; ++k) {
                const int n = 1 + static_cast<int>(rng() % 6);
                const bool near = rng() % 3 == 0;  // short segments: a polyline on a curve
                render::SubPoint pts[6];
                for (int i = 0; i < n; ++i) {
                    pts[i] = {random_coordinate(rng, w), random_coordinate(rng, h)};
                    if (near && i > 0)
                        pts[i] = {static_cast<int32_t>(std::clamp<int64_t>(int64_t{pts[i - 1].x} + static_cast<int>(rng() % 4096) - 2048, INT32_MIN + 1, INT32_MAX)),
                                  static_cast<int32_t>(std::clamp<int64_t>(int64_t{pts[i - 1].y} + static_cast<int>(rng() % 4096) - 2048, INT32_MIN + 1, INT32_MAX))};
                }
                // Half the polylines on a grid of half pixels: lines through pixel corners and
                // centres, where the error term meets its bound exactly (ties).
                if (rng() % 2)
                    for (int i = 0; i < n; ++i) pts[i].x &= ~127, pts[i].y &= ~127;
                const render::LineStyle style = styles[rng() % 5];
                const bool closed = rng() % 4 == 0;
                const render::Rgb color{static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng())};
                const bool as_line = n == 2 && rng() % 2 == 0;  // with its end points: the open polyline
                // Two lines in three into a row band (a thread's share of draw_world): thin lines
                // past its edges take the 32-bit loop, visit_polyline cuts them exactly in 64 bits.
                render::RowRange rows;
                if (rng() % 3 != 0) {
                    const int a0 = static_cast<int>(rng() % static_cast<uint32_t>(h + 6)) - 3,
                              a1 = static_cast<int>(rng() % static_cast<uint32_t>(h + 6)) - 3;
                    rows = {std::min(a0, a1), std::max(a0, a1) + (rng() % 4 == 0 ? 1 : 0)};
                }
                if (as_line)
                    render::draw_line(ca, pts[0], pts[1], color, style, true, rows);
                else
                    render::draw_polyline(ca, pts, n, closed, color, style, rows);
                VisitInto v{&cb, color};
                render::visit_polyline(w, h, pts, n, closed && !as_line, style, put_visited, &v, rows);
                ASSERT_EQ(a, b) << f.name << " " << w << "x" << h << " line " << k << " n " << n << " (" << pts[0].x << ","
                                << pts[0].y << ") -> (" << pts[n > 1 ? 1 : 0].x << "," << pts[n > 1 ? 1 : 0].y
                                << ") aa " << style.antialias << " width " << style.width << " rows " << rows.y0
                                << ".." << rows.y1;
                ++lines;
            }
        }
    EXPECT_EQ(lines, 7 * 5 * 300);
}

TEST(FastPaths, SpansAreThePixelsOneByOne) {
    std::mt19937 rng(48);
    for (const auto& f : {render::PixelFormat::rgb565(), render::PixelFormat::rgb888(), render::PixelFormat::xrgb8888()}) {
        const int bpp = f.bytes_per_pixel();
        for (int n = 0; n <= 200; ++n)
            for (int start : {0, 1, 3}) {
                const uint32_t word = f.pack({static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng())});
                const int w = start + n + 2;
                std::vector<uint8_t> x(static_cast<std::size_t>(w * bpp), 0x5A), y = x;
                const render::Canvas cy(y.data(), w, 1, w * bpp, f);
                render::detail::fill_span(x.data() + start * bpp, n, render::detail::SpanPattern(word, bpp));
                for (int i = start; i < start + n; ++i) cy.set_word(i, 0, word);
                ASSERT_EQ(x, y) << f.name << " n " << n << " from " << start;
            }
    }
}

}  // namespace
