// Part of the rasteriser (raster.cpp, which alone includes it): where pixels go (a canvas of
// 2, 3 or 4 bytes per pixel, or a visitor), the Plotter that sends them there within the
// canvas and a row band, and the integer arithmetic of the columns a line crosses.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>

#include "render/canvas.hpp"
#include "render/raster.hpp"

namespace noneuclid::render {
namespace {

static_assert(std::endian::native == std::endian::little, "pixel words are stored little-endian");

// x / 255 rounded to the nearest whole number, for x <= 255 * 255, by shifts.
constexpr uint32_t div255_rounded(uint32_t x) {
    x += 128;
    return (x + (x >> 8)) >> 8;
}
constexpr bool div255_exact() {
    for (uint32_t x = 0; x <= 255 * 255; ++x)
        if (div255_rounded(x) != (x + 127) / 255) return false;
    return true;
}
static_assert(div255_exact(), "div255_rounded is x / 255 rounded for every product of two 8-bit values");

// Where pixels go: into a canvas (one instantiation per pixel size, writing whole words, with
// integer blends for RGB565 and for 32-bit words of byte channels, xrgb8888 and the browser's
// rgba8888 alike), or to a visitor (tests, counting).
template <int Bpp>
struct CanvasSink {
    static constexpr int bytes = Bpp;
    const Canvas& c;
    Rgb color;
    uint32_t word;
    uint8_t* base;
    std::ptrdiff_t stride;
    bool fast565, fast8888;
    uint32_t rs, gs, bs, fill;  // fast8888: the channels' shifts, and the bits pack() sets besides
    uint32_t channels;          // fast8888: the channels' bits
    uint64_t lanes;             // fast8888: the colour's word, a byte to each 16-bit lane (spread)
    uint64_t lanes565;          // fast565: the colour's r, g and b in lanes 0, 1 and 2
    CanvasSink(const Canvas& canvas, Rgb col)
        : c(canvas), color(col), word(canvas.format().pack(col)), base(canvas.row(0)), stride(canvas.stride()),
          fast565(canvas.format().is_rgb565()), fast8888(canvas.format().byte_channels()),
          rs(canvas.format().red.offset), gs(canvas.format().green.offset), bs(canvas.format().blue.offset),
          fill(canvas.format().opaque_bits()), channels(0xFFu << rs | 0xFFu << gs | 0xFFu << bs), lanes(spread(word)),
          lanes565(color.r | uint64_t{color.g} << 16 | uint64_t{color.b} << 32) {}
    // The four bytes of a word, each in a 16-bit lane of its own, and back.
    static uint64_t spread(uint32_t w) {
        uint64_t x = w;
        x = (x | x << 16) & 0x0000FFFF0000FFFFull;
        return (x | x << 8) & 0x00FF00FF00FF00FFull;
    }
    static uint32_t gather(uint64_t x) {
        x = (x | x >> 8) & 0x0000FFFF0000FFFFull;
        return static_cast<uint32_t>(x | x >> 16);
    }
    // Canvas::blend's d + (s - d) a / 255 rounded to the nearest level, on four 8-bit channels
    // in 16-bit lanes at once (so that every format holds the same colours), as
    // (s a + d (255 - a)) / 255 rounded by div255_rounded: the same, since 255 is odd and
    // (s - d) a / 255 is never a half, whichever way a tie would go. Never beyond s. No lane
    // carries into the next: s a + d (255 - a) + 128 plus its top byte is at most 65407.
    static uint64_t mix_lanes(uint64_t S, uint64_t D, uint32_t a) {
        constexpr uint64_t LFF = 0x00FF00FF00FF00FFull;
        const uint64_t t = S * a + D * (255 - a) + 0x0080008000800080ull;
        return ((t + ((t >> 8) & LFF)) >> 8) & LFF;  // div255_rounded
    }
    int width() const { return c.width(); }
    int height() const { return c.height(); }
    uint8_t* at(int x, int y) const { return base + y * stride + x * Bpp; }
    void opaque(int x, int y) const { store(y * stride + x * Bpp); }
    void store(std::ptrdiff_t offset) const {
        uint8_t* p = base + offset;
        if constexpr (Bpp == 4) {
            std::memcpy(p, &word, 4);
        } else if constexpr (Bpp == 2) {
            const uint16_t w = static_cast<uint16_t>(word);
            std::memcpy(p, &w, 2);
        } else {
            p[0] = static_cast<uint8_t>(word), p[1] = static_cast<uint8_t>(word >> 8), p[2] = static_cast<uint8_t>(word >> 16);
        }
    }
    // Whether blend_at can blend this canvas's pixels: 32-bit words of byte channels, or RGB565.
    bool direct() const {
        if constexpr (Bpp == 4) return fast8888;
        if constexpr (Bpp == 2) return fast565;
        return false;
    }
    // The pixel at p blended with coverage alpha in 1..254, for a direct() canvas: Canvas::blend's
    // unpack, mix and pack in integers (RGB565's channels widened with their top bits replicated).
    [[gnu::always_inline]] void blend_at(uint8_t* p, uint32_t a) const {
        if constexpr (Bpp == 4) {
            uint32_t d;
            std::memcpy(&d, p, 4);
            const uint32_t out = fill | (gather(mix_lanes(lanes, spread(d), a)) & channels);  // pack({r, g, b})
            std::memcpy(p, &out, 4);
        } else if constexpr (Bpp == 2) {
            uint16_t d;
            std::memcpy(&d, p, 2);
            const uint64_t r5 = d >> 11, g6 = (d >> 5) & 0x3F, b5 = d & 0x1F;
            const uint64_t D = (r5 << 3 | r5 >> 2) | (g6 << 2 | g6 >> 4) << 16 | (b5 << 3 | b5 >> 2) << 32;
            const uint64_t m = mix_lanes(lanes565, D, a);  // r, g, b in lanes 0, 1, 2
            const uint16_t out = static_cast<uint16_t>((m & 0xF8) << 8 | (m >> 16 & 0xFC) << 3 | (m >> 32 & 0xFF) >> 3);
            std::memcpy(p, &out, 2);
        } else {
            (void)p, (void)a;
        }
    }
    void blend(int x, int y, int alpha) const {
        if (alpha >= 255) return opaque(x, y);
        if (direct()) return blend_at(at(x, y), static_cast<uint32_t>(alpha));
        c.blend(x, y, color, alpha);
    }
};
struct VisitSink {
    int w, h;
    PixelVisitor visit;
    void* context;
    int width() const { return w; }
    int height() const { return h; }
    void opaque(int x, int y) const { visit(x, y, 255, context); }
    void blend(int x, int y, int alpha) const { visit(x, y, alpha, context); }
};

// Sends pixels to the sink, skipping a pixel equal to the one just written (shared polyline
// points) or to a sharp join's pixel just written (join()), and anything outside the canvas or
// the row band [row0, row1).
template <class Sink>
struct Plotter {
    const Sink& sink;
    int row0, row1;     // the rows written: [row0, row1), within the canvas
    bool banded;        // [row0, row1) is less than the whole canvas
    bool swap = false;  // (u, v) are (y, x)
    static constexpr int kNone = -1 << 30;
    int last_x = kNone, last_y = kNone;
    int join_x = kNone, join_y = kNone;    // a sharp join's pixel, until the next segment's first
    int first_x = kNone, first_y = kNone;  // the first pixel written (a closed polyline's last join)

    Plotter(const Sink& s, RowRange rows)
        : sink(s), row0(rows.y0 > 0 ? rows.y0 : 0), row1(rows.y1 < s.height() ? rows.y1 : s.height()),
          banded(row0 > 0 || row1 < s.height()) {}

    template <class I>
    bool inside(I x, I y) const { return x >= 0 && y >= row0 && x < sink.width() && y < row1; }
    // Whether (x, y), a segment's first pixel, is new: not the last pixel written nor a sharp
    // join's pixel written just before; the join is forgotten either way.
    bool fresh(int x, int y) {
        const bool seen = (x == last_x && y == last_y) || (x == join_x && y == join_y);
        join_x = kNone;
        return !seen;
    }
    template <class I>
    void opaque(I u, I v) {
        const I x = swap ? v : u, y = swap ? u : v;
        if (!inside(x, y) || !fresh(static_cast<int>(x), static_cast<int>(y))) return;
        sink.opaque(static_cast<int>(x), static_cast<int>(y));
        last_x = static_cast<int>(x), last_y = static_cast<int>(y);
        if (first_x == kNone) first_x = last_x, first_y = last_y;
    }
    // The pixel holding a polyline's point where its segments do not step along the same axis
    // the same way (sharp_join in raster.cpp): the half-open segments on either side may both
    // stop short of it, by up to a pixel. Written unless it is the last pixel written (or,
    // `closing`: the first); the last pixel stays the previous segment's, and the next
    // segment's first pixel is checked against both.
    void join(int x, int y, bool closing) {
        if (!inside(x, y) || (x == last_x && y == last_y) || (closing && x == first_x && y == first_y)) return;
        sink.opaque(x, y);
        join_x = x, join_y = y;
    }
    void blend(int64_t u, int64_t v, int alpha) {
        const int64_t x = swap ? v : u, y = swap ? u : v;
        if (!inside(x, y)) return;
        sink.blend(static_cast<int>(x), static_cast<int>(y), alpha);
    }
    // A pixel known to be on the canvas, with no shared-point check (the loop's inner pixels).
    void raw(int64_t u, int64_t v) const {
        sink.opaque(static_cast<int>(swap ? v : u), static_cast<int>(swap ? u : v));
    }
    // Remember the segment's last pixel for the next segment's shared-point check.
    template <class I>
    void note_last(I u, I v) {
        const I x = swap ? v : u, y = swap ? u : v;
        if (inside(x, y)) last_x = static_cast<int>(x), last_y = static_cast<int>(y);
    }
};

int64_t floor_div(int64_t a, int64_t b) {  // b > 0
    const int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}
int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }  // b > 0

// The major-axis columns whose centres lie in [u0, u1) (or (u1, u0] going down), as a first
// index, a count and a step.
template <class I>
struct ColumnsOf {
    I first, count, step;
};
using Columns = ColumnsOf<int64_t>;
// floor(v / 256) and ceil(v / 256) by arithmetic shifts (C++20: >> of a negative value rounds
// toward negative infinity).
template <class I>
I floor_sub(I v) { return v >> kSubBits; }
template <class I>
I ceil_sub(I v) { return -((-v) >> kSubBits); }
template <class I>
ColumnsOf<I> columns(I u0, I u1) {
    if (u1 > u0) {
        const I a = ceil_sub<I>(u0 - kSub / 2), b = ceil_sub<I>(u1 - kSub / 2) - 1;
        return {a, b >= a ? b - a + 1 : 0, 1};
    }
    const I a = floor_sub<I>(u0 - kSub / 2), b = floor_sub<I>(u1 - kSub / 2) + 1;
    return {a, a >= b ? a - b + 1 : 0, -1};
}
// Cuts the columns to [umin, umax); false if none is left.
template <class I>
bool cut_columns(ColumnsOf<I>& col, I umin, I umax) {
    if (col.count == 0) return false;
    I last = col.first + (col.count - 1) * col.step;
    if (col.step > 0) {
        if (col.first < umin) col.first = umin;
        if (last > umax - 1) last = umax - 1;
        col.count = last - col.first + 1;
    } else {
        if (col.first > umax - 1) col.first = umax - 1;
        if (last < umin) last = umin;
        col.count = col.first - last + 1;
    }
    return col.count > 0;
}

}  // namespace
}  // namespace noneuclid::render
