// Pixel formats: every colour packed and unpacked again, the byte-per-channel formats holding
// the same colours, and blending in every format against its arithmetic.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "pixel_formats.hpp"
#include "render/canvas.hpp"
#include "render/raster.hpp"

using namespace noneuclid::render;
using noneuclid::test::kFormats;

namespace {

TEST(Raster, PixelFormatsRoundTrip) {
    for (const PixelFormat& f : kFormats) {
        ASSERT_TRUE(f.supported()) << f.name;
        for (int v = 0; v < 256; ++v) {
            const Rgb c{static_cast<uint8_t>(v), static_cast<uint8_t>(255 - v), static_cast<uint8_t>(v * 7)};
            const Rgb back = f.unpack(f.pack(c));
            auto expect = [](uint8_t x, int len) {  // top bits kept, replicated downward
                int keep = x >> (8 - len) << (8 - len), out = keep;
                for (int filled = len; filled < 8; filled += len) out |= out >> filled;
                return static_cast<uint8_t>(out);
            };
            EXPECT_EQ(back.r, expect(c.r, f.red.length)) << f.name << " " << v;
            EXPECT_EQ(back.g, expect(c.g, f.green.length)) << f.name << " " << v;
            EXPECT_EQ(back.b, expect(c.b, f.blue.length)) << f.name << " " << v;
        }
        // Every word of the 16-bit formats survives unpack then pack.
        if (f.bits_per_pixel == 16) {
            for (uint32_t w = 0; w < 65536; ++w) ASSERT_EQ(f.pack(f.unpack(w)), w) << f.name;
        }
        EXPECT_EQ(f.unpack(f.pack({255, 255, 255})), (Rgb{255, 255, 255})) << f.name;
    }
    // The memory layout fbdev describes: xrgb8888 blue first in memory, rgb888 too, rgb565
    // red in the top bits of a little-endian 16-bit word.
    uint8_t px[4] = {};
    Canvas(px, 1, 1, 4, PixelFormat::xrgb8888()).set(0, 0, {0x11, 0x22, 0x33});
    EXPECT_EQ(px[0], 0x33);
    EXPECT_EQ(px[2], 0x11);
    Canvas(px, 1, 1, 3, PixelFormat::rgb888()).set(0, 0, {0x44, 0x55, 0x66});
    EXPECT_EQ(px[0], 0x66);
    EXPECT_EQ(px[2], 0x44);
    Canvas(px, 1, 1, 2, PixelFormat::rgb565()).set(0, 0, {0xFF, 0, 0});
    EXPECT_EQ(px[1], 0xF8);
    EXPECT_EQ(px[0], 0x00);
    // A browser's ImageData: R, G, B, then an alpha byte always 255 (opaque).
    Canvas(px, 1, 1, 4, PixelFormat::rgba8888()).set(0, 0, {0x11, 0x22, 0x33});
    EXPECT_EQ(px[0], 0x11);
    EXPECT_EQ(px[1], 0x22);
    EXPECT_EQ(px[2], 0x33);
    EXPECT_EQ(px[3], 0xFF);
}

// The web page draws in rgba8888 and must show what `render` writes from xrgb8888: after the
// same drawing (anti-aliased and wide lines crossing each other, the shaded outside), the
// 32-bit formats of byte channels hold the same colour in every pixel, and rgba8888's alpha
// is 255 in every pixel.
TEST(Raster, ByteChannelFormatsHoldTheSameColours) {
    const PixelFormat formats[] = {PixelFormat::xrgb8888(), PixelFormat::xbgr8888(), PixelFormat::rgba8888()};
    const int W = 97, H = 61;
    std::vector<std::vector<uint8_t>> pixels;
    for (const PixelFormat& f : formats) {
        ASSERT_TRUE(f.byte_channels()) << f.name;
        std::vector<uint8_t>& px = pixels.emplace_back(static_cast<std::size_t>(W * H * 4));
        const Canvas c(px.data(), W, H, W * 4, f);
        c.clear({20, 30, 40});
        std::mt19937 rng(25);
        std::uniform_real_distribution<double> x(-10, W + 10), y(-10, H + 10);
        std::uniform_int_distribution<int> level(0, 255);
        for (int k = 0; k < 400; ++k) {
            const Rgb col{static_cast<uint8_t>(level(rng)), static_cast<uint8_t>(level(rng)), static_cast<uint8_t>(level(rng))};
            const LineStyle style{k % 3 != 0, k % 4 == 0 ? 700 : 256};
            const SubPoint a = to_sub(x(rng), y(rng)), b = to_sub(x(rng), y(rng));
            draw_line(c, a, b, col, style);
        }
        shade_outside_circle(c, W / 2.0, H / 2.0, 25, {200, 100, 50}, 90);
        for (int py = 0; py < H; ++py)
            for (int px_ = 0; px_ < W; ++px_) {
                ASSERT_EQ(c.get(px_, py), Canvas(pixels[0].data(), W, H, W * 4, formats[0]).get(px_, py))
                    << f.name << " at " << px_ << "," << py;
                if (f.opaque.length) {
                    ASSERT_EQ(px[static_cast<std::size_t>((py * W + px_) * 4 + 3)], 255) << f.name;
                }
            }
    }
}

TEST(Raster, BlendingIsCorrectInEveryFormat) {
    for (const PixelFormat& f : kFormats) {
        uint8_t px[4] = {};
        Canvas c(px, 1, 1, 4, f);
        c.set(0, 0, {0, 0, 0});
        c.blend(0, 0, {255, 255, 255}, 128);  // half of white over black
        const Rgb got = c.get(0, 0);
        // the 8-bit result 128 stored in the format: within one step of the channel
        auto step = [](int len) { return 256 >> len; };
        EXPECT_NEAR(got.r, 128, step(f.red.length)) << f.name;
        EXPECT_NEAR(got.g, 128, step(f.green.length)) << f.name;
        EXPECT_NEAR(got.b, 128, step(f.blue.length)) << f.name;
        c.blend(0, 0, {10, 20, 30}, 255);
        EXPECT_EQ(c.get(0, 0), f.unpack(f.pack({10, 20, 30}))) << f.name;
    }
}

}  // namespace
