// The backdrop of a frame: the background, outside the limit circle the shaded area of the
// paper's figures, and the limit circle itself as a line of the frame's width in the rim colour
// (anti-aliased with the lines). Written row by row as spans of one colour, each pixel once
// (the anti-aliased circle's pixels then blended): without the circle, the same pixels as
// Canvas::clear(background) then shade_outside_circle (raster.hpp), whose column range per row
// it shares (columns_inside_circle).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "render/canvas.hpp"
#include "render/draw_options.hpp"
#include "render/screen_points.hpp"

namespace noneuclid::render {

// The limit circle on the canvas: centre and radius in px.
struct LimitCircle {
    double cx = 0, cy = 0, r = 0;
};
template <class T>
LimitCircle limit_circle(const ScreenMap<T>& m) {
    return {static_cast<double>(m.cx), static_cast<double>(m.cy), m.rim};
}

// The columns of one row of the backdrop: those inside the circle (`in`, the background's when
// the outside is shaded), and the circle's line between the circles `outer` and `inner` (of
// radius r +- half the line's width, or +- half + 1/2 anti-aliased: the pixels it blends);
// outer is empty where the row misses the line or there is none. 16 bits a column.
struct BackdropRow {
    struct Span {
        int16_t first, last;
    };
    Span in, outer, inner;
};

// Every row's BackdropRow, kept while the circle, the options and the canvas's size stay the
// same (they do from frame to frame): each row's columns take square roots and roundings in
// double, which on a core without a floating-point unit cost as much as drawing the frame's
// lines (docs/microcontroller.md). Used only where reserve() made room for the canvas's rows, so
// that drawing never allocates; otherwise the rows are computed as they are drawn. backdrop.cpp.
class BackdropRows {
public:
    void reserve(int rows) { rows_.reserve(static_cast<std::size_t>(rows)); }
    // The rows for this frame, computed when anything they depend on changed; nullptr when the
    // room reserved is too small (or the canvas too wide for 16 bits).
    const BackdropRow* rows(const Canvas& c, const LimitCircle& circle, const DrawOptions& o);

private:
    std::vector<BackdropRow> rows_;
    LimitCircle circle_;
    int32_t line_width_ = 0;
    int width_ = 0;
    bool antialias_ = false, shade_outside_ = false, rim_line_ = false;
};

// Rows [y0, y1) of the backdrop (clamped to the canvas); `rows`, if given, the canvas's every
// row's columns (BackdropRows). backdrop.cpp.
void draw_backdrop_rows(const Canvas& c, const LimitCircle& circle, const DrawOptions& o, int y0, int y1,
                        const BackdropRow* rows = nullptr);

template <class T>
void draw_backdrop(const Canvas& c, const ScreenMap<T>& m, const DrawOptions& o, BackdropRows* kept = nullptr) {
    const LimitCircle circle = limit_circle(m);
    draw_backdrop_rows(c, circle, o, c.top(), c.bottom(), kept ? kept->rows(c, circle, o) : nullptr);
}

namespace detail {
// One colour as 12 bytes of pixels held in three 32-bit words (4 pixels of 3 bytes, 6 of 2, 3
// of 4: whole pixels in any format, little-endian as set_word). A span is written from these
// words in registers as blocks the compiler turns into 16-byte vector stores, then the last
// words and bytes: no call and no load from memory per block. With 2 or 4 bytes per pixel the
// three words are one and the same (`single`), written 128 bytes per block.
struct SpanPattern {
    uint32_t w[3] = {};
    int bpp;
    bool single;
    SpanPattern(uint32_t word, int bytes_per_pixel) : bpp(bytes_per_pixel > 0 ? bytes_per_pixel : 1) {
        uint8_t bytes[12];
        for (int i = 0; i < 12; ++i) bytes[i] = static_cast<uint8_t>(word >> (8 * (i % bpp)));
        std::memcpy(w, bytes, 12);
        single = w[0] == w[1] && w[1] == w[2];
    }
};
inline void store_word(uint8_t* p, uint32_t v) { std::memcpy(p, &v, 4); }
// The last rest < 12 bytes of a span, starting at word a of the pattern (a, b, c).
inline void fill_tail(uint8_t* p, std::size_t rest, uint32_t a, uint32_t b, uint32_t c) {
    uint32_t next = a;  // the pattern word the remaining bytes start in
    if (rest >= 4) store_word(p, a), p += 4, rest -= 4, next = b;
    if (rest >= 4) store_word(p, b), p += 4, rest -= 4, next = c;
    if (rest & 2) {
        const uint16_t half = static_cast<uint16_t>(next);
        std::memcpy(p, &half, 2);
        p += 2, next >>= 16;
    }
    if (rest & 1) *p = static_cast<uint8_t>(next);
}
// n pixels of the pattern's colour from p on. Out of line, as the backdrop was tuned with it:
// inlined three times into the row loop, the wide rows (1920 px, 4 bytes) got slower on x86.
[[gnu::noinline]] inline void fill_span(uint8_t* p, int n, const SpanPattern& pat) {
    if (n <= 0) return;
    std::size_t rest = static_cast<std::size_t>(n) * static_cast<std::size_t>(pat.bpp);
    const uint32_t a = pat.w[0], b = pat.w[1], c = pat.w[2];
    if (pat.single) {
        for (std::size_t k = rest / 128; k > 0; --k, p += 128)
            for (int i = 0; i < 128; i += 4) store_word(p + i, a);
        rest %= 128;
        for (; rest >= 16; rest -= 16, p += 16) store_word(p, a), store_word(p + 4, a), store_word(p + 8, a), store_word(p + 12, a);
        for (; rest >= 4; rest -= 4, p += 4) store_word(p, a);
        return fill_tail(p, rest, a, a, a);
    }
    for (std::size_t k = rest / 48; k > 0; --k, p += 48)
        for (int i = 0; i < 48; i += 12) store_word(p + i, a), store_word(p + i + 4, b), store_word(p + i + 8, c);
    rest %= 48;
    for (; rest >= 12; rest -= 12, p += 12) store_word(p, a), store_word(p + 4, b), store_word(p + 8, c);
    fill_tail(p, rest, a, b, c);
}
}  // namespace detail

}  // namespace noneuclid::render
