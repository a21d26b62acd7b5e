// PSF1 and PSF2 font files built byte by byte for the font tests (test_font.cpp,
// test_console_font.cpp): every byte of glyph g from pattern(g, k), so that a parsed or loaded
// font can be checked pixel by pixel against the pattern alone.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/font.hpp"

namespace noneuclid::test {


// The content of byte `k` of glyph `g`: varied, so that glyphs and rows differ.
inline uint8_t pattern(int g, int k) {
    return static_cast<uint8_t>((g * 37 + k * 11 + 5) & 0xFF);
}

inline std::vector<uint8_t> make_psf1(int height, uint8_t mode, int glyph_bytes = -1) {
    const int count = (mode & 1) ? 512 : 256;
    std::vector<uint8_t> v = {0x36, 0x04, mode, static_cast<uint8_t>(height)};
    const int n = glyph_bytes >= 0 ? glyph_bytes : count * height;
    for (int i = 0; i < n; ++i)
        v.push_back(pattern(i / height, i % height));
    return v;
}

inline void put32(std::vector<uint8_t>& v, std::size_t at, uint32_t x) {
    for (int i = 0; i < 4; ++i)
        v[at + std::size_t(i)] = static_cast<uint8_t>(x >> (8 * i));
}

struct Psf2 {
    uint32_t width = 10, height = 12, count = 100, headersize = 32;
    uint32_t charsize = 0;  // 0: height * bytes per row
    long glyph_bytes = -1;  // -1: count * charsize
};

inline std::vector<uint8_t> make_psf2(Psf2 p) {
    const uint32_t charsize = p.charsize ? p.charsize : p.height * ((p.width + 7) / 8);
    std::vector<uint8_t> v(p.headersize >= 32 ? p.headersize : 32, 0xEE);
    v[0] = 0x72, v[1] = 0xb5, v[2] = 0x4a, v[3] = 0x86;
    put32(v, 4, 0);
    put32(v, 8, p.headersize);
    put32(v, 12, 0);
    put32(v, 16, p.count);
    put32(v, 20, charsize);
    put32(v, 24, p.height);
    put32(v, 28, p.width);
    const long n = p.glyph_bytes >= 0 ? p.glyph_bytes : long(p.count) * long(charsize);
    for (long i = 0; i < n; ++i)
        v.push_back(pattern(int(i / charsize), int(i % charsize)));
    return v;
}

// Pixel (x, y) of glyph g in a font built by make_psf1/make_psf2, from the pattern alone.
inline bool pattern_pixel(int g, int x, int y, int bytes_per_row) {
    return (pattern(g, y * bytes_per_row + x / 8) >> (7 - x % 8)) & 1;
}

inline void expect_font_matches_pattern(const render::Font& f) {
    for (int g = 0; g < f.glyph_count; ++g)
        for (int y = 0; y < f.height; ++y)
            for (int x = 0; x < f.width; ++x)
                ASSERT_EQ(f.pixel(g, x, y), pattern_pixel(g, x, y, f.bytes_per_row))
                    << "glyph " << g << " pixel " << x << "," << y;
}

}  // namespace noneuclid::test
