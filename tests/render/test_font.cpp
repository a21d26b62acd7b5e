// Fonts: the built-in font's glyphs, PSF1/PSF2 parsing against the bytes the test builds,
// errors as one sentence, text drawn with canary borders and odd strides against a per-pixel
// reference. Console font files and the HUD font choice: test_console_font.cpp.
#include <gtest/gtest.h>

#include <climits>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "psf_bytes.hpp"
#include "render/canvas.hpp"
#include "render/font.hpp"

using namespace noneuclid::render;
using namespace noneuclid::test;

namespace {

std::string parse_error(const std::vector<uint8_t>& bytes) {
    Font f;
    std::string error;
    EXPECT_FALSE(parse_psf(bytes.data(), bytes.size(), f, error));
    EXPECT_EQ(f.glyphs, nullptr) << "a failed parse must leave the font alone";
    EXPECT_EQ(error.find('\n'), std::string::npos);
    return error;
}

// ---------------------------------------------------------------------------------------------
// PatternCanvas canvases
// ---------------------------------------------------------------------------------------------

// A buffer with a canary border: 3 canary rows above and below, 3 canary pixels left and right
// of each row and an odd number of spare bytes ending each row. The canary bytes and the
// canvas's own starting content are patterns, so that any stray or missing write shows.
struct PatternCanvas {
    static constexpr int kPad = 3;
    int w, h;
    PixelFormat f;
    std::ptrdiff_t stride;
    std::vector<uint8_t> bytes, original;
    PatternCanvas(int w_, int h_, PixelFormat f_) : w(w_), h(h_), f(f_) {
        stride = std::ptrdiff_t((w + 2 * kPad) * f.bytes_per_pixel() + 5);
        bytes.resize(std::size_t(stride * (h + 2 * kPad)));
        for (std::size_t i = 0; i < bytes.size(); ++i)
            bytes[i] = static_cast<uint8_t>(i * 151 + 29);
        original = bytes;
    }
    std::size_t offset(int x, int y) const {
        return std::size_t((y + kPad) * stride + (x + kPad) * f.bytes_per_pixel());
    }
    Canvas canvas() { return Canvas(bytes.data() + offset(0, 0), w, h, stride, f); }
    bool inside(std::size_t i) const {
        const std::ptrdiff_t row = std::ptrdiff_t(i) / stride, col = std::ptrdiff_t(i) % stride;
        return row >= kPad && row < kPad + h && col >= kPad * f.bytes_per_pixel()
               && col < (kPad + w) * f.bytes_per_pixel();
    }
};

// The test colour {0x12, 0x34, 0x56} as little-endian bytes, worked out by hand per format.
std::vector<uint8_t> color_bytes(const PixelFormat& f) {
    if (f.is_rgb565())
        return {0xAA, 0x11};  // r 0x12>>3=2, g 0x34>>2=13, b 0x56>>3=10: 0x11AA
    if (f.is_xrgb8888())
        return {0x56, 0x34, 0x12, 0x00};
    return {0x56, 0x34, 0x12};  // rgb888: B, G, R in memory
}
constexpr Rgb kColor{0x12, 0x34, 0x56};

// Whether text drawn at (x0, y0) covers canvas pixel (px, py): the inverse of the layout, per
// pixel, in 64-bit arithmetic (ASCII text only).
bool reference_covers(const Font& font, std::string_view text, int64_t x0, int64_t y0,
                      int64_t scale, int64_t px, int64_t py) {
    const int64_t dx = px - x0, dy = py - y0;
    if (dx < 0 || dy < 0)
        return false;
    const int64_t cw = font.width * scale, ch = font.height * scale;
    int64_t line = dy / ch;
    std::size_t start = 0;
    while (line > 0) {
        const std::size_t nl = text.find('\n', start);
        if (nl == std::string_view::npos)
            return false;
        start = nl + 1;
        --line;
    }
    const std::string_view this_line = text.substr(start, text.find('\n', start) - start);
    const int64_t col = dx / cw;
    if (col >= int64_t(this_line.size()))
        return false;
    const int gx = int((dx % cw) / scale), gy = int((dy % ch) / scale);
    return font.pixel(font.glyph_for(static_cast<unsigned char>(this_line[std::size_t(col)])), gx,
                      gy);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The built-in font
// ---------------------------------------------------------------------------------------------

TEST(FontBuiltin, Layout) {
    const Font& f = builtin_font();
    EXPECT_EQ(f.width, 6);
    EXPECT_EQ(f.height, 8);
    EXPECT_EQ(f.bytes_per_row, 1);
    EXPECT_GE(f.glyph_count, 127);
    EXPECT_NE(f.glyphs, nullptr);
}

TEST(FontBuiltin, SpaceIsEmpty) {
    const Font& f = builtin_font();
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 6; ++x)
            EXPECT_FALSE(f.pixel(' ', x, y)) << x << "," << y;
}

TEST(FontBuiltin, PrintableGlyphsHaveInkAndAreDistinct) {
    const Font& f = builtin_font();
    auto bitmap = [&f](int g) {
        uint64_t bits = 0;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 6; ++x)
                bits = bits << 1 | uint64_t(f.pixel(g, x, y));
        return bits;
    };
    for (int a = 33; a <= 126; ++a) {
        EXPECT_NE(bitmap(a), 0u) << "glyph '" << char(a) << "' is empty";
        for (int b = a + 1; b <= 126; ++b)
            EXPECT_NE(bitmap(a), bitmap(b))
                << "'" << char(a) << "' and '" << char(b) << "' look alike";
    }
}

TEST(FontBuiltin, GlyphsKeepToTheirBox) {
    // 5x7 glyphs: the right column is spacing; the bottom row only for descenders and ','.
    const Font& f = builtin_font();
    const std::string_view descenders = "gjpqy,";
    for (int c = 32; c <= 126; ++c) {
        for (int y = 0; y < 8; ++y)
            EXPECT_FALSE(f.pixel(c, 5, y)) << "'" << char(c) << "' row " << y;
        if (descenders.find(char(c)) == std::string_view::npos) {
            for (int x = 0; x < 6; ++x)
                EXPECT_FALSE(f.pixel(c, x, 7)) << "'" << char(c) << "' column " << x;
        }
    }
    bool any_descends = false;
    for (char c : descenders)
        for (int x = 0; x < 5; ++x)
            any_descends |= f.pixel(c, x, 7);
    EXPECT_TRUE(any_descends);
}

TEST(FontBuiltin, ShapesSpotChecked) {
    const Font& f = builtin_font();
    auto rows = [&f](char c) {
        std::vector<std::string> r;
        for (int y = 0; y < 8; ++y) {
            std::string s;
            for (int x = 0; x < 5; ++x)
                s += f.pixel(c, x, y) ? '#' : '.';
            r.push_back(s);
        }
        return r;
    };
    const std::vector<std::string> t = {"#####", "..#..", "..#..", "..#..",
                                        "..#..", "..#..", "..#..", "....."};
    const std::vector<std::string> minus = {".....", ".....", ".....", "#####",
                                            ".....", ".....", ".....", "....."};
    const std::vector<std::string> l = {"#....", "#....", "#....", "#....",
                                        "#....", "#....", "#####", "....."};
    EXPECT_EQ(rows('T'), t);
    EXPECT_EQ(rows('-'), minus);
    EXPECT_EQ(rows('L'), l);
}

TEST(FontBuiltin, GlyphForCodePoints) {
    const Font& f = builtin_font();
    EXPECT_EQ(f.glyph_for(U'A'), 'A');
    EXPECT_EQ(f.glyph_for(U'~'), '~');
    EXPECT_EQ(f.glyph_for(U'\u00e9'), 0xE9);  // é: drawn (German and French)
    EXPECT_EQ(f.glyph_for(U'\U0001F600'), '?');
    // Action characters and DEL look like '?'.
    for (int c : {0, 9, 27, 31, 127})
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 6; ++x)
                EXPECT_EQ(f.pixel(f.glyph_for(char32_t(c)), x, y), f.pixel('?', x, y));
    // Out-of-range queries are simply unset.
    EXPECT_FALSE(f.pixel(-1, 0, 0));
    EXPECT_FALSE(f.pixel(f.glyph_count, 0, 0));
    EXPECT_FALSE(f.pixel('T', -1, 0));
    EXPECT_FALSE(f.pixel('T', 6, 0));
    EXPECT_FALSE(f.pixel('T', 0, 8));
    EXPECT_EQ(Font{}.glyph_for(U'A'), -1);
}

// ---------------------------------------------------------------------------------------------
// PSF parsing
// ---------------------------------------------------------------------------------------------

TEST(FontPsf, Psf1) {
    for (uint8_t mode : {0x00, 0x01, 0x02, 0x03}) {
        std::vector<uint8_t> bytes = make_psf1(16, mode);
        if (mode & 2)
            bytes.insert(bytes.end(), {0x41, 0x00, 0xFF, 0xFF});  // a Unicode table, ignored
        Font f;
        std::string error;
        ASSERT_TRUE(parse_psf(bytes.data(), bytes.size(), f, error)) << error;
        EXPECT_EQ(f.width, 8);
        EXPECT_EQ(f.height, 16);
        EXPECT_EQ(f.bytes_per_row, 1);
        EXPECT_EQ(f.glyph_count, (mode & 1) ? 512 : 256);
        EXPECT_EQ(f.glyphs, bytes.data() + 4);
        expect_font_matches_pattern(f);
    }
}

TEST(FontPsf, Psf2) {
    for (uint32_t headersize : {32u, 40u}) {
        for (uint32_t width : {1u, 8u, 10u, 16u, 64u}) {
            Psf2 p;
            p.width = width;
            p.headersize = headersize;
            const std::vector<uint8_t> bytes = make_psf2(p);
            Font f;
            std::string error;
            ASSERT_TRUE(parse_psf(bytes.data(), bytes.size(), f, error)) << error;
            EXPECT_EQ(f.width, int(width));
            EXPECT_EQ(f.height, 12);
            EXPECT_EQ(f.bytes_per_row, int((width + 7) / 8));
            EXPECT_EQ(f.glyph_count, 100);
            EXPECT_EQ(f.glyphs, bytes.data() + headersize);
            expect_font_matches_pattern(f);
            EXPECT_FALSE(
                f.pixel(5, int(width), 0));  // padding bits beyond the width are not pixels
        }
    }
}

// A font's Unicode table (the console's Lat15-* and Uni2-* fonts have one): code points below
// 256 are drawn with the glyph it names; sequences are skipped; the rest, and what it does not
// name, show its '?'. PSF2 writes the table in UTF-8, PSF1 in 16-bit words.
TEST(FontPsf, UnicodeTablesMapLatin1) {
    // glyph 10: é and the sequence e + combining acute (skipped); 20: A and Å; 30: '?'.
    Psf2 p;
    p.count = 100;
    std::vector<uint8_t> v = make_psf2(p);
    put32(v, 12, 1);  // has a Unicode table
    for (int g = 0; g < 100; ++g) {
        if (g == 10) v.insert(v.end(), {0xC3, 0xA9, 0xFE, 'e', 0xCC, 0x81});
        if (g == 20) v.insert(v.end(), {'A', 0xC3, 0x85});
        if (g == 30) v.push_back('?');
        v.push_back(0xFF);
    }
    Font f;
    std::string error;
    ASSERT_TRUE(parse_psf(v.data(), v.size(), f, error)) << error;
    EXPECT_EQ(f.glyph_for(U'é'), 10);
    EXPECT_EQ(f.glyph_for(U'A'), 20);
    EXPECT_EQ(f.glyph_for(U'Å'), 20);
    EXPECT_EQ(f.glyph_for(U'e'), 30);   // only in a sequence
    EXPECT_EQ(f.glyph_for(U'B'), 30);   // not in the table: '?'
    EXPECT_EQ(f.glyph_for(U'€'), 30);   // past Latin-1
    EXPECT_EQ(text_width(f, "é€"), 2 * f.width);

    // PSF1: 256 glyphs of 8 rows, the table in little-endian words, 0xFFFE before a sequence.
    std::vector<uint8_t> w = make_psf1(8, 0x02);
    const auto word = [&w](unsigned x) { w.push_back(uint8_t(x)), w.push_back(uint8_t(x >> 8)); };
    const std::size_t table_at = w.size();
    for (int g = 0; g < 256; ++g) {
        if (g == 3) word(0xE9), word(0xFFFE), word('e'), word(0x301);
        if (g == 200) word('?');
        if (g == 65) word('A');
        word(0xFFFF);
    }
    Font f1;
    ASSERT_TRUE(parse_psf(w.data(), w.size(), f1, error)) << error;
    EXPECT_EQ(f1.glyph_for(U'é'), 3);
    EXPECT_EQ(f1.glyph_for(U'A'), 65);
    EXPECT_EQ(f1.glyph_for(U'e'), 200);
    // A table cut short (anywhere after glyph 3's entry, 16 bytes in) maps what it has and reads
    // nothing past the end (ASan would say so).
    for (std::size_t cut = w.size(); cut >= table_at + 16; cut -= 7) {
        std::vector<uint8_t> part(w.begin(), w.begin() + std::ptrdiff_t(cut));
        Font fc;
        ASSERT_TRUE(parse_psf(part.data(), part.size(), fc, error)) << error;
        EXPECT_EQ(fc.glyph_for(U'é'), 3);
    }
    // Without the table flag, the glyph index is the code point, as before.
    std::vector<uint8_t> plain = make_psf1(8, 0x00);
    Font f0;
    ASSERT_TRUE(parse_psf(plain.data(), plain.size(), f0, error)) << error;
    EXPECT_EQ(f0.glyph_for(U'é'), 0xE9);
}

TEST(FontPsf, Errors) {
    EXPECT_EQ(parse_error({}), "not a PSF font (bad magic number)");
    EXPECT_EQ(parse_error({'P', 'K', 3, 4, 0, 0}), "not a PSF font (bad magic number)");
    EXPECT_EQ(parse_error({0x36}), "not a PSF font (bad magic number)");
    EXPECT_EQ(parse_error({0x36, 0x04}),
              "the PSF font is truncated: 4 bytes of header expected, 2 found");
    EXPECT_EQ(parse_error(make_psf1(16, 0, 100)),
              "the PSF font is truncated: 4096 bytes of glyphs expected, 100 found");
    EXPECT_EQ(parse_error(make_psf1(0, 0)),
              "the PSF font's glyphs are 0 pixels high, and 1 to 128 are supported");

    std::vector<uint8_t> short_header = make_psf2({});
    short_header.resize(20);
    EXPECT_EQ(parse_error(short_header),
              "the PSF font is truncated: 32 bytes of header expected, 20 found");
    Psf2 p;
    p.glyph_bytes = 300;
    EXPECT_EQ(parse_error(make_psf2(p)),
              "the PSF font is truncated: 2400 bytes of glyphs expected, 300 found");
    p = {};
    p.headersize = 16;
    EXPECT_EQ(parse_error(make_psf2(p)),
              "the PSF2 header size is 16 bytes, less than the 32 bytes of its own fields");
    p = {};
    p.headersize = 1000;
    p.glyph_bytes = 0;
    std::vector<uint8_t> v = make_psf2(p);
    v.resize(500);
    EXPECT_EQ(parse_error(v),
              "the PSF font is truncated: 1000 bytes of header expected, 500 found");
    p = {};
    p.charsize = 12;
    EXPECT_EQ(parse_error(make_psf2(p)),
              "the PSF font's glyphs take 12 bytes each, but 12 rows of 10 pixels take 24");
    p = {};
    p.width = 0;
    p.charsize = 12;
    EXPECT_EQ(parse_error(make_psf2(p)),
              "the PSF font's glyphs are 0 pixels wide, and 1 to 64 are supported");
    p = {};
    p.width = 65;
    EXPECT_EQ(parse_error(make_psf2(p)),
              "the PSF font's glyphs are 65 pixels wide, and 1 to 64 are supported");
    p = {};
    p.height = 129;
    EXPECT_EQ(parse_error(make_psf2(p)),
              "the PSF font's glyphs are 129 pixels high, and 1 to 128 are supported");
    p = {};
    p.count = 94;
    EXPECT_EQ(parse_error(make_psf2(p)),
              "the PSF font has 94 glyphs, fewer than the 95 of printable ASCII");
    p = {};
    p.count = 0xFFFFFFFFu;
    p.glyph_bytes = 0;
    EXPECT_EQ(parse_error(make_psf2(p)),
              "the PSF font has 4294967295 glyphs, more than the 1048576 supported");
    p = {};
    p.count = 1u << 20;
    p.glyph_bytes = 10;  // count * charsize overflows 32 bits in a naive check; not here
    p.charsize = 0;
    p.height = 128;
    p.width = 64;
    EXPECT_EQ(parse_error(make_psf2(p)),
              "the PSF font is truncated: 1073741824 bytes of glyphs expected, 10 found");

    Font f;
    std::string error;
    EXPECT_FALSE(parse_psf(nullptr, 100, f, error));
    EXPECT_EQ(error, "not a PSF font (bad magic number)");
}

// ---------------------------------------------------------------------------------------------
// Drawing text
// ---------------------------------------------------------------------------------------------

TEST(FontDraw, TextWidth) {
    const Font& f = builtin_font();
    EXPECT_EQ(text_width(f, "abc"), 18);
    EXPECT_EQ(text_width(f, ""), 0);
    EXPECT_EQ(text_width(f, "abc", 3), 54);
    EXPECT_EQ(text_width(f, "abc", 0), 18);  // scale < 1 counts as 1
    EXPECT_EQ(text_width(f, "abc", -7), 18);
    EXPECT_EQ(text_width(f, "ab\nabcd\n"), 24);
    EXPECT_EQ(text_width(f, "\n\n"), 0);
    EXPECT_EQ(text_width(f, "\xc3\xa9t\xc3\xa9"), 18);  // UTF-8: one cell per code point
    EXPECT_EQ(text_width(f, "\xf0\x9f\x98\x80"), 6);    // U+1F600
    EXPECT_EQ(text_width(f, "\xff\xc3"), 12);           // malformed bytes: one cell each
    EXPECT_EQ(text_width(f, "\xc0\xaf"), 12);           // overlong '/': two cells
    EXPECT_EQ(text_width(f, "abc", INT_MAX), INT_MAX);  // saturates
    EXPECT_EQ(text_width(f, std::string(1000, 'x'), 1 << 30), INT_MAX);
    EXPECT_EQ(text_width(Font{}, "abc"), 0);
}

TEST(FontDraw, ClippedAndExactInEveryFormat) {
    Psf2 p;  // a 10x12 font: two bytes per row
    const std::vector<uint8_t> psf = make_psf2(p);
    Font wide;
    std::string error;
    ASSERT_TRUE(parse_psf(psf.data(), psf.size(), wide, error)) << error;

    const std::string_view text = "Hg!\nW_q%\n\n#j";
    const int W = 37, H = 23;
    const int64_t big = 1'000'000'000;
    const std::pair<int64_t, int64_t> positions[] = {
        {2, 3},
        {-7, -5},
        {W - 10, H - 6},
        {-3, H - 4},
        {W - 4, -9},
        {-5, 4},
        {4, -5},
        {W - 1, 2},
        {2, H - 1},
        {-big, 5},
        {big, 5},
        {5, -big},
        {5, big},
        {-big, -big},
        {big, big},
        {INT_MIN, INT_MIN},
        {INT_MAX, INT_MAX},
        {INT_MIN, 0},
        {0, INT_MAX},
    };
    for (const Font* font : {&builtin_font(), static_cast<const Font*>(&wide)}) {
        for (const PixelFormat& fmt :
             {PixelFormat::rgb565(), PixelFormat::xrgb8888(), PixelFormat::rgb888()}) {
            const std::vector<uint8_t> ink = color_bytes(fmt);
            for (int scale : {1, 2, 3, 1000, INT_MAX}) {
                for (auto [x, y] : positions) {
                    // With a huge scale, also place the text so that one block covers the canvas.
                    const int64_t xs = scale >= 1000 && x == 2 ? -int64_t(scale) / 2 : x;
                    const int64_t ys = scale >= 1000 && y == 3 ? -int64_t(scale) / 3 : y;
                    SCOPED_TRACE(std::string(fmt.name) + " font " + std::to_string(font->width)
                                 + "x" + std::to_string(font->height) + " scale "
                                 + std::to_string(scale) + " at " + std::to_string(xs) + ","
                                 + std::to_string(ys));
                    PatternCanvas g(W, H, fmt);
                    const int returned =
                        draw_text(g.canvas(), *font, int(xs), int(ys), text, kColor, scale);
                    EXPECT_EQ(returned,
                              int(std::min<int64_t>(int64_t(4) * font->width * scale, INT_MAX)));
                    for (std::size_t i = 0; i < g.bytes.size(); ++i) {
                        if (g.inside(i))
                            continue;
                        ASSERT_EQ(g.bytes[i], g.original[i])
                            << "canary byte " << i << " overwritten";
                    }
                    const int bpp = fmt.bytes_per_pixel();
                    for (int py = 0; py < H; ++py) {
                        for (int px = 0; px < W; ++px) {
                            const bool covered =
                                reference_covers(*font, text, xs, ys, scale, px, py);
                            for (int k = 0; k < bpp; ++k) {
                                const std::size_t at = g.offset(px, py) + std::size_t(k);
                                const uint8_t want = covered ? ink[std::size_t(k)] : g.original[at];
                                ASSERT_EQ(g.bytes[at], want)
                                    << "pixel " << px << "," << py << " byte " << k;
                            }
                        }
                    }
                }
            }
        }
    }
}

TEST(FontDraw, EmptyCanvasAndEmptyFont) {
    Canvas none;
    EXPECT_EQ(draw_text(none, builtin_font(), 0, 0, "abc", kColor), 18);
    PatternCanvas g(8, 8, PixelFormat::xrgb8888());
    EXPECT_EQ(draw_text(g.canvas(), Font{}, 0, 0, "abc", kColor), 0);
    EXPECT_EQ(g.bytes, g.original);
}
