#include "render/font.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <utility>

namespace noneuclid::render {

namespace {


// ---------------------------------------------------------------------------------------------
// PSF
// ---------------------------------------------------------------------------------------------
constexpr int kMaxWidth = 64, kMaxHeight = 128, kMinGlyphs = 95;
// Keeps glyph offsets (glyph * height * bytes_per_row <= 2^20 * 128 * 8) inside int.
constexpr uint32_t kMaxGlyphs = 1u << 20;

uint32_t le32(const uint8_t* p) {
    return uint32_t{p[0]} | uint32_t{p[1]} << 8 | uint32_t{p[2]} << 16 | uint32_t{p[3]} << 24;
}

std::string truncated(const char* what, uint64_t expected, std::size_t found) {
    return "the PSF font is truncated: " + std::to_string(expected) + " bytes of " + what
           + " expected, " + std::to_string(found) + " found";
}

// ---------------------------------------------------------------------------------------------
// Text
// ---------------------------------------------------------------------------------------------

// The next code point of UTF-8 text at s[i], advancing i; U+FFFD for a malformed sequence
// (which then consumes one byte).
char32_t next_code_point(std::string_view s, std::size_t& i) {
    const auto byte = [&](std::size_t k) {
        return static_cast<unsigned char>(s[k]);
    };
    const unsigned char b0 = byte(i);
    if (b0 < 0x80) {
        ++i;
        return b0;
    }
    int extra = 0;
    char32_t c = 0, min = 0;
    if ((b0 & 0xE0) == 0xC0) {
        extra = 1, c = b0 & 0x1F, min = 0x80;
    } else if ((b0 & 0xF0) == 0xE0) {
        extra = 2, c = b0 & 0x0F, min = 0x800;
    } else if ((b0 & 0xF8) == 0xF0) {
        extra = 3, c = b0 & 0x07, min = 0x10000;
    } else {
        ++i;
        return 0xFFFD;
    }
    if (s.size() - i <= std::size_t(extra)) {
        ++i;
        return 0xFFFD;
    }
    for (int k = 1; k <= extra; ++k) {
        const unsigned char b = byte(i + std::size_t(k));
        if ((b & 0xC0) != 0x80) {
            ++i;
            return 0xFFFD;
        }
        c = c << 6 | (b & 0x3F);
    }
    if (c < min || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) {
        ++i;
        return 0xFFFD;
    }
    i += std::size_t(extra) + 1;
    return c;
}

// Offsets grow by at most one cell (<= 64 * INT_MAX) past this cap, so int64 arithmetic on pen
// positions never overflows and anything beyond it is far outside any canvas.
constexpr int64_t kOffsetCap = int64_t{1} << 40;

void draw_glyph(const Canvas& canvas, const Font& font, int glyph, int64_t left, int64_t top,
                int64_t scale, uint32_t word) {
    // (the rows the canvas holds: all of them, but in a band of a frame)
    const int64_t w = canvas.width(), h = std::min(canvas.height(), canvas.bottom()), t = canvas.top();
    if (left >= w || top >= h || left + font.width * scale <= 0 || top + font.height * scale <= t)
        return;
    for (int gy = 0; gy < font.height; ++gy) {
        const int64_t y0 = std::max<int64_t>(top + gy * scale, t);
        const int64_t y1 = std::min<int64_t>(top + (gy + 1) * scale, h);
        if (y0 >= y1)
            continue;
        for (int gx = 0; gx < font.width; ++gx) {
            if (!font.pixel(glyph, gx, gy))
                continue;
            const int64_t x0 = std::max<int64_t>(left + gx * scale, 0);
            const int64_t x1 = std::min<int64_t>(left + (gx + 1) * scale, w);
            for (int64_t y = y0; y < y1; ++y)
                for (int64_t x = x0; x < x1; ++x)
                    canvas.set_word(int(x), int(y), word);
        }
    }
}

// Walks the text cell by cell; draws when `canvas` is given. Returns the longest line's width.
int layout(const Canvas* canvas, const Font& font, int x, int y, std::string_view text, Rgb color,
           int scale) {
    const int64_t s = std::max(scale, 1);
    const int64_t advance = font.width * s, line_height = font.height * s;
    const uint32_t word = canvas ? canvas->format().pack(color) : 0;
    int64_t line = 0, down = 0, longest = 0;
    for (std::size_t i = 0; i < text.size();) {
        const char32_t c = next_code_point(text, i);
        if (c == U'\n') {
            longest = std::max(longest, line);
            line = 0;
            if (down <= kOffsetCap)
                down += line_height;
            continue;
        }
        if (line > kOffsetCap)
            continue;  // counted as saturated already
        if (canvas && down <= kOffsetCap)
            draw_glyph(*canvas, font, font.glyph_for(c), x + line, y + down, s, word);
        line += advance;
    }
    longest = std::max(longest, line);
    return int(std::min<int64_t>(longest, INT_MAX));
}


// A PSF font's Unicode table (after its glyphs): for each glyph in turn, the code points it
// shows (PSF1: 16-bit little-endian; PSF2: UTF-8), then sequences (after 0xFFFE / 0xFE) that
// are skipped, ended by 0xFFFF / 0xFF. Fills out.latin for code points below 256, the first
// glyph naming one winning. A table cut short maps what it has.
void read_unicode_table(const uint8_t* p, std::size_t n, bool psf1, Font& out) {
    for (uint16_t& g : out.latin) g = Font::kNoGlyph;
    out.mapped = true;
    const auto map = [&out](char32_t c, int glyph) {
        if (c < 256 && out.latin[c] == Font::kNoGlyph) out.latin[c] = uint16_t(glyph);
    };
    std::size_t i = 0;
    for (int glyph = 0; glyph < out.glyph_count && glyph < Font::kNoGlyph && i < n; ++glyph) {
        bool sequence = false;
        if (psf1) {
            for (; i + 1 < n; i += 2) {
                const unsigned v = unsigned(p[i]) | unsigned(p[i + 1]) << 8;
                if (v == 0xFFFF) break;
                if (v == 0xFFFE) sequence = true;
                else if (!sequence) map(v, glyph);
            }
            i += 2;
        } else {
            const std::string_view s(reinterpret_cast<const char*>(p), n);
            while (i < n && p[i] != 0xFF) {
                if (p[i] == 0xFE) {
                    sequence = true, ++i;
                    continue;
                }
                const char32_t c = next_code_point(s, i);
                if (!sequence) map(c, glyph);
            }
            ++i;
        }
    }
}

}  // namespace

bool Font::pixel(int glyph, int x, int y) const {
    if (glyphs == nullptr || glyph < 0 || glyph >= glyph_count || x < 0 || x >= width || y < 0
        || y >= height)
        return false;
    const uint8_t* row =
        glyphs
        + (std::size_t(glyph) * std::size_t(height) + std::size_t(y)) * std::size_t(bytes_per_row);
    return (row[x >> 3] >> (7 - (x & 7))) & 1;
}

int Font::glyph_for(char32_t c) const {
    if (mapped) {
        if (c < 256 && latin[c] != kNoGlyph)
            return latin[c];
        if (latin[int('?')] != kNoGlyph)
            return latin[int('?')];
        return glyph_count > 0 ? 0 : -1;
    }
    if (c < char32_t(std::max(glyph_count, 0)))
        return int(c);
    if ('?' < glyph_count)
        return '?';
    return glyph_count > 0 ? 0 : -1;
}

bool parse_psf(const uint8_t* data, std::size_t size, Font& out, std::string& error) {
    const auto fail = [&error](std::string message) {
        error = std::move(message);
        return false;
    };
    if (data == nullptr)
        size = 0;
    uint64_t header = 0, width = 0, height = 0, charsize = 0, count = 0;
    const bool psf1 = size >= 2 && data[0] == 0x36 && data[1] == 0x04;
    if (psf1) {
        header = 4;
        if (size < header)
            return fail(truncated("header", header, size));
        count = (data[2] & 0x01) ? 512 : 256;
        charsize = data[3];
        height = charsize;
        width = 8;
    } else if (size >= 4 && data[0] == 0x72 && data[1] == 0xb5 && data[2] == 0x4a
               && data[3] == 0x86) {
        if (size < 32)
            return fail(truncated("header", 32, size));
        header = le32(data + 8);
        count = le32(data + 16);
        charsize = le32(data + 20);
        height = le32(data + 24);
        width = le32(data + 28);
        if (header < 32)
            return fail("the PSF2 header size is " + std::to_string(header)
                        + " bytes, less than the 32 bytes of its own fields");
        if (size < header)
            return fail(truncated("header", header, size));
    } else {
        return fail("not a PSF font (bad magic number)");
    }
    if (width < 1 || width > kMaxWidth)
        return fail("the PSF font's glyphs are " + std::to_string(width) + " pixels wide, and 1 to "
                    + std::to_string(kMaxWidth) + " are supported");
    if (height < 1 || height > kMaxHeight)
        return fail("the PSF font's glyphs are " + std::to_string(height)
                    + " pixels high, and 1 to " + std::to_string(kMaxHeight) + " are supported");
    const uint64_t bytes_per_row = (width + 7) / 8;
    if (charsize != height * bytes_per_row)
        return fail("the PSF font's glyphs take " + std::to_string(charsize) + " bytes each, but "
                    + std::to_string(height) + " rows of " + std::to_string(width) + " pixels take "
                    + std::to_string(height * bytes_per_row));
    if (count < kMinGlyphs)
        return fail("the PSF font has " + std::to_string(count) + " glyphs, fewer than the "
                    + std::to_string(kMinGlyphs) + " of printable ASCII");
    if (count > kMaxGlyphs)
        return fail("the PSF font has " + std::to_string(count) + " glyphs, more than the "
                    + std::to_string(kMaxGlyphs) + " supported");
    const uint64_t glyph_bytes = count * charsize;
    if (size - header < glyph_bytes)
        return fail(truncated("glyphs", glyph_bytes, size - header));
    out.width = int(width);
    out.height = int(height);
    out.glyph_count = int(count);
    out.bytes_per_row = int(bytes_per_row);
    out.glyphs = data + header;
    out.mapped = false;
    const bool table = psf1 ? (data[2] & 0x02) != 0 : (le32(data + 12) & 1) != 0;
    if (table)
        read_unicode_table(data + header + glyph_bytes, size - header - glyph_bytes, psf1, out);
    return true;
}

int draw_text(const Canvas& canvas, const Font& font, int x, int y, std::string_view text,
              Rgb color, int scale) {
    return layout(&canvas, font, x, y, text, color, scale);
}

namespace {
// Calls line(text) for each line of `text` wrapped to `width` pixels at its separators (the
// rule draw_wrapped and measure_wrapped share).
template <class Line>
void wrap_lines(const Font& font, const char* text, const char* sep, int scale, int width, Line&& line) {
    const std::size_t sep_len = std::strlen(sep);
    char buf[512];
    std::size_t len = 0;
    const char* p = text;
    while (*p) {
        const char* end = std::strstr(p, sep);
        const std::size_t item = end ? static_cast<std::size_t>(end - p) : std::strlen(p);
        char trial[512];
        std::snprintf(trial, sizeof trial, "%.*s%s%.*s", static_cast<int>(len), buf, len ? sep : "",
                      static_cast<int>(item), p);
        if (len && text_width(font, trial, scale) > width) {  // this item starts the next line
            line(static_cast<const char*>(buf));
            std::snprintf(buf, sizeof buf, "%.*s", static_cast<int>(item), p);
        } else {
            std::snprintf(buf, sizeof buf, "%s", trial);
        }
        len = std::strlen(buf);
        p += item;
        if (std::strncmp(p, sep, sep_len) == 0) p += sep_len;
        while (*p == ' ') ++p;
    }
    if (len) line(static_cast<const char*>(buf));
}
}  // namespace

Wrapped measure_wrapped(const Font& font, const char* text, const char* sep, int scale, int width) {
    Wrapped w;
    wrap_lines(font, text, sep, scale, width, [&](const char* l) {
        ++w.lines;
        w.widest = std::max(w.widest, text_width(font, l, scale));
    });
    return w;
}

int draw_wrapped(const Canvas& c, const Font& font, const char* text, const char* sep, Rgb color, int scale, int x,
                 int width, int line, int y, bool top) {
    const int lines = measure_wrapped(font, text, sep, scale, width).lines;
    int at = top ? y : y - (lines - 1) * line;
    wrap_lines(font, text, sep, scale, width, [&](const char* l) {
        draw_text(c, font, x, at, l, color, scale);
        at += line;
    });
    return lines;
}

int text_width(const Font& font, std::string_view text, int scale) {
    return layout(nullptr, font, 0, 0, text, {}, scale);
}

}  // namespace noneuclid::render
