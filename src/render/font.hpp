// Bitmap fonts: a built-in 6x8 font and PC Screen Fonts (PSF1/PSF2, the Linux console's
// format), and text drawn onto a canvas, clipped.
//
// Glyphs are indexed by code point: character c uses glyph c when c < glyph_count, otherwise
// the glyph for '?'. A PSF font with a Unicode table (the Linux console's Lat15-*, Uni2-*, ...)
// is read through it for the code points below 256 (ASCII and Latin-1, which German and French
// need): c uses the glyph the table gives it, '?' when it gives none; the rest show '?'.
//
// No heap, no OS: parse_psf only reads bytes the caller has loaded (see platform/files/
// console_font.hpp), and a Font points into those bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "render/canvas.hpp"

namespace noneuclid::render {

struct Font {
    int width = 0, height = 0;  // cell size in pixels (the advance; glyphs include their spacing)
    int glyph_count = 0;
    int bytes_per_row = 0;  // (width + 7) / 8
    // Glyph i's rows: glyphs + i * height * bytes_per_row; in each row the most significant bit
    // of the first byte is the leftmost pixel.
    const uint8_t* glyphs = nullptr;
    // A PSF font's Unicode table, for code points 0..255: the glyph of each (kNoGlyph: none).
    static constexpr uint16_t kNoGlyph = 0xFFFF;
    bool mapped = false;  // false: code point = glyph index
    uint16_t latin[256] = {};

    // Whether pixel (x, y) of glyph `glyph` is set; false outside the glyph or the font.
    bool pixel(int glyph, int x, int y) const;
    // The glyph for a character: the table's when the font has one, else c itself when
    // c < glyph_count; else the glyph for '?' (-1 only for a font without glyphs).
    int glyph_for(char32_t c) const;
};

// A built-in font: 6x8 cells, 5x7 glyphs with a column of spacing on the right and a row below
// (used only by the descenders of g j p q y and the comma, and the cedilla). ASCII 32..126 and
// the Latin-1 letters of German and French (ä ö ü ß, é è ê à ç î ô û ù ë ï and their capitals,
// with ° and ²); the other indices below 256 hold '?'. The table is constant data (no start-up code).
const Font& builtin_font();
// Whether the built-in font has a glyph of its own for c (not the '?' it shows otherwise).
bool builtin_font_draws(char32_t c);

// Parses a PSF1 or PSF2 font held in data[0..size). On success `out` points into `data`, which
// the caller keeps alive and unchanged for as long as `out` is used. On failure returns false,
// leaves `out` unchanged and sets `error` to one sentence (e.g. "not a PSF font (bad magic
// number)").
bool parse_psf(const uint8_t* data, std::size_t size, Font& out, std::string& error);

// Draws `text` (UTF-8; each code point one cell) with the top-left of its first cell at (x, y),
// each font pixel as a scale x scale block (scale < 1 counts as 1) in `color`; unset pixels are
// left alone. '\n' starts a new line: back to x, down font.height * scale. Clipped to the canvas:
// nothing is written outside it, whatever x, y and scale are. Returns the width in pixels of the
// longest line (saturating at INT_MAX). Allocates nothing.
int draw_text(const Canvas& canvas, const Font& font, int x, int y, std::string_view text,
              Rgb color, int scale = 1);

// `text` wrapped to `width` pixels at its separators (`sep`: "  " between a legend's items, " "
// between words), from x, lines `line` pixels apart: the first line's top at y (top), or the
// last line's (not top: text that ends at y, as the HUD's legend does). A line longer than
// `width` with no separator is drawn whole (and clipped). Returns the number of lines.
// Allocates nothing: a line at a time in a fixed buffer (511 bytes; longer lines are cut).
int draw_wrapped(const Canvas& c, const Font& font, const char* text, const char* sep, Rgb color, int scale, int x,
                 int width, int line, int y, bool top);

// What draw_wrapped would draw, without drawing: its lines and the width of the widest.
struct Wrapped {
    int lines = 0, widest = 0;
};
Wrapped measure_wrapped(const Font& font, const char* text, const char* sep, int scale, int width);

// The width draw_text returns for the same text, without drawing.
int text_width(const Font& font, std::string_view text, int scale = 1);

}  // namespace noneuclid::render
