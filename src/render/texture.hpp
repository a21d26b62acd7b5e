// Textures on the canvas: an image's texels packed once into the canvas's pixel format
// (PackedTexture, refreshed without allocating when the format changes), where a texture
// coordinate lands in the image (TexelMap: nearest texel or bilinear, the image repeated), and
// writing a body's pixels (PixelWriter: a word, a blend, a run of one colour). Used by the fill
// (render/fill.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "render/canvas.hpp"
#include "world/image.hpp"

namespace noneuclid::render {

// An image packed into a canvas format: words[y * width + x] is texel (x, y) as the canvas
// stores it, so the nearest texel is one load and one store.
struct PackedTexture {
    const world::Image* image = nullptr;
    int width = 0, height = 0;
    std::vector<uint32_t> words;
    PixelFormat format{};
    bool packed = false;
    // Sized for `im` (allocates; at prepare time).
    void make(const world::Image& im);
    // Packed for `f`, unless it already is (no allocation).
    void pack_for(const PixelFormat& f);
};

// Where texture coordinate s (across) lands in [0, size): repeated. Cheap when s is already in
// range, as it is for every pixel of a body whose texture_scale is 1 or more.
inline int wrap_texel(int64_t s, int size) {
    if (static_cast<uint64_t>(s) < static_cast<uint64_t>(size)) return static_cast<int>(s);
    const int64_t m = s % size;
    return static_cast<int>(m < 0 ? m + size : m);
}

// 0x00RRGGBB texels blended by the fractions fs, ft (0..256) of the way from a to b (across)
// and from the top pair to the bottom pair: bilinear filtering.
inline Rgb bilinear(uint32_t a, uint32_t b, uint32_t c, uint32_t d, int fs, int ft) {
    auto ch = [&](int shift) {
        const int ta = static_cast<int>((a >> shift) & 255), tb = static_cast<int>((b >> shift) & 255);
        const int tc = static_cast<int>((c >> shift) & 255), td = static_cast<int>((d >> shift) & 255);
        const int top = ta * (256 - fs) + tb * fs, bottom = tc * (256 - fs) + td * fs;
        return static_cast<uint8_t>((top * (256 - ft) + bottom * ft + (1 << 15)) >> 16);
    };
    return {ch(16), ch(8), ch(0)};
}

// The colour of texture coordinate (s, t), in texels with 8 fractional bits, across from the
// image's left edge and down from its top: the nearest texel's packed word, or (bilinear) the
// four texels about it blended and packed.
struct TexelMap {
    const PackedTexture* tex = nullptr;
    bool bilinear = false;
    uint32_t word(int64_t s8, int64_t t8) const {
        const PackedTexture& p = *tex;
        if (!bilinear) {
            const int x = wrap_texel(s8 >> 8, p.width), y = wrap_texel(t8 >> 8, p.height);
            return p.words[static_cast<std::size_t>(y) * static_cast<std::size_t>(p.width) + static_cast<std::size_t>(x)];
        }
        return p.format.pack(rgb(s8, t8));
    }
    Rgb rgb(int64_t s8, int64_t t8) const {
        const PackedTexture& p = *tex;
        if (!bilinear) return p.format.unpack(word(s8, t8));
        const int64_t s = s8 - 128, t = t8 - 128;  // from the texels' centres
        const int x0 = wrap_texel(s >> 8, p.width), x1 = wrap_texel((s >> 8) + 1, p.width);
        const int y0 = wrap_texel(t >> 8, p.height), y1 = wrap_texel((t >> 8) + 1, p.height);
        const world::Image& im = *p.image;
        return render::bilinear(im.at(x0, y0), im.at(x1, y0), im.at(x0, y1), im.at(x1, y1), static_cast<int>(s & 255),
                                static_cast<int>(t & 255));
    }
};

// Writes a body's pixels into a canvas row: a word, a word blended with coverage alpha (0..255),
// a run of one word. The canvas's fast formats (RGB565, XRGB8888) store words directly.
struct PixelWriter {
    const Canvas& c;
    void put(int x, int y, uint32_t w) const {
        uint8_t* p = c.row(y);
        switch (c.format().bits_per_pixel) {
            case 16: {
                const uint16_t h = static_cast<uint16_t>(w);
                std::memcpy(p + 2 * x, &h, 2);
                break;
            }
            case 32: std::memcpy(p + 4 * x, &w, 4); break;
            default: c.set_word(x, y, w); break;
        }
    }
    void blend(int x, int y, uint32_t w, int alpha) const {
        if (alpha >= 255) return put(x, y, w);
        c.blend(x, y, c.format().unpack(w), alpha);
    }
    // Pixels [x0, x1) of row y set to w.
    void run(int y, int x0, int x1, uint32_t w) const;
};

}  // namespace noneuclid::render
