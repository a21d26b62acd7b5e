// A canvas: a view of pixel memory described like the kernel's fbdev describes a framebuffer
// (struct fb_var_screeninfo: bits_per_pixel and red/green/blue offset + length), so that the
// same rasteriser writes into a RAM back buffer, an mmapped /dev/fb0 or a PNG's rows.
//
// Rows are `stride` bytes apart (fbdev's line_length; may exceed width * bytes per pixel).
// Pixels are little-endian words of 16, 24 or 32 bits. Fast paths exist for RGB565 and
// XRGB8888; every other 16/24/32-bit layout (RGB888, BGR orders, ...) goes through the
// general packer. A format may name bits that every pixel keeps set: the alpha byte of a
// browser's RGBA8888, which must be opaque. The canvas owns nothing: no heap, no OS.
#pragma once

#include <cstddef>
#include <cstdint>

namespace noneuclid::render {

struct Rgb {
    uint8_t r = 0, g = 0, b = 0;
    friend constexpr bool operator==(Rgb, Rgb) = default;
};

struct Channel {
    uint8_t offset = 0, length = 0;  // bit position of the least significant bit, width in bits
};

struct PixelFormat {
    uint8_t bits_per_pixel = 32;
    Channel red, green, blue;
    const char* name = "custom";
    Channel opaque{};  // bits set in every pixel (an alpha channel kept opaque), or none


    static constexpr PixelFormat rgb565() { return {16, {11, 5}, {5, 6}, {0, 5}, "rgb565"}; }
    static constexpr PixelFormat bgr565() { return {16, {0, 5}, {5, 6}, {11, 5}, "bgr565"}; }
    static constexpr PixelFormat xrgb8888() { return {32, {16, 8}, {8, 8}, {0, 8}, "xrgb8888"}; }
    static constexpr PixelFormat xbgr8888() { return {32, {0, 8}, {8, 8}, {16, 8}, "xbgr8888"}; }
    // 24-bit: bytes in memory B, G, R (little-endian word 0xRRGGBB), as fbdev reports red at 16.
    static constexpr PixelFormat rgb888() { return {24, {16, 8}, {8, 8}, {0, 8}, "rgb888"}; }
    static constexpr PixelFormat bgr888() { return {24, {0, 8}, {8, 8}, {16, 8}, "bgr888"}; }
    // A browser canvas's ImageData: bytes in memory R, G, B, A, with A always 255.
    static constexpr PixelFormat rgba8888() { return {32, {0, 8}, {8, 8}, {16, 8}, "rgba8888", {24, 8}}; }

    constexpr int bytes_per_pixel() const { return bits_per_pixel / 8; }
    constexpr bool is_rgb565() const {
        return bits_per_pixel == 16 && red.offset == 11 && red.length == 5 && green.offset == 5 &&
               green.length == 6 && blue.offset == 0 && blue.length == 5 && opaque.length == 0;
    }
    constexpr bool is_xrgb8888() const {
        return bits_per_pixel == 32 && red.offset == 16 && red.length == 8 && green.offset == 8 &&
               green.length == 8 && blue.offset == 0 && blue.length == 8 && opaque.length == 0;
    }
    // 32 bits with each colour an 8-bit channel on a byte of its own (xrgb8888, xbgr8888,
    // rgba8888): the rasteriser blends these with one integer formula, so that they all hold the
    // same colours after the same drawing.
    constexpr bool byte_channels() const {
        auto byte = [](Channel c) { return c.length == 8 && c.offset % 8 == 0; };
        return bits_per_pixel == 32 && byte(red) && byte(green) && byte(blue) && red.offset != green.offset &&
               green.offset != blue.offset && red.offset != blue.offset;
    }
    // The same word size, channels and opaque bits (the name aside).
    constexpr bool same_layout(const PixelFormat& o) const {
        auto same = [](Channel a, Channel b) { return a.offset == b.offset && a.length == b.length; };
        return bits_per_pixel == o.bits_per_pixel && same(red, o.red) && same(green, o.green) && same(blue, o.blue) &&
               opaque_bits() == o.opaque_bits();
    }
    // The formats the canvas can pack: 16, 24 or 32 bits, channels of 1..8 bits inside the word.
    constexpr bool supported() const {
        auto ok = [this](Channel c) { return c.length >= 1 && c.length <= 8 && c.offset + c.length <= bits_per_pixel; };
        return (bits_per_pixel == 16 || bits_per_pixel == 24 || bits_per_pixel == 32) && ok(red) && ok(green) && ok(blue) &&
               (opaque.length == 0 || ok(opaque));
    }
    // The bits every pixel word has set.
    constexpr uint32_t opaque_bits() const {
        return opaque.length == 0 ? 0 : ((opaque.length >= 32 ? ~0u : (1u << opaque.length) - 1) << opaque.offset);
    }

    // 8-bit channels to the pixel word (each channel rounded to its length).
    constexpr uint32_t pack(Rgb c) const {
        if (is_xrgb8888()) return uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b;
        if (is_rgb565()) return uint32_t(c.r >> 3) << 11 | uint32_t(c.g >> 2) << 5 | uint32_t(c.b >> 3);
        return scale_down(c.r, red) | scale_down(c.g, green) | scale_down(c.b, blue) | opaque_bits();
    }
    // The pixel word back to 8-bit channels (the top bits replicated into the low ones, so that
    // full scale is 255).
    constexpr Rgb unpack(uint32_t p) const {
        return {scale_up(p, red), scale_up(p, green), scale_up(p, blue)};
    }

private:
    static constexpr uint32_t scale_down(uint8_t v, Channel c) {
        return (uint32_t{v} >> (8 - c.length)) << c.offset;
    }
    static constexpr uint8_t scale_up(uint32_t p, Channel c) {
        const uint32_t v = (p >> c.offset) & ((1u << c.length) - 1);
        uint32_t out = v << (8 - c.length);
        for (int filled = c.length; filled < 8; filled += c.length) out |= out >> filled;  // replicate
        return static_cast<uint8_t>(out & 0xFF);
    }
};

// The formats a user names (render --format, a recording's format, the headless display), in
// the order --help lists them: the first is the default.
inline constexpr PixelFormat kNamedFormats[] = {PixelFormat::xrgb8888(), PixelFormat::rgb565(), PixelFormat::rgb888()};

class Canvas {
public:
    Canvas() = default;
    // `pixels` points at the first byte of row 0, column 0 (fbdev: add xoffset/yoffset first).
    Canvas(void* pixels, int width, int height, std::ptrdiff_t stride, PixelFormat format)
        : base_(static_cast<uint8_t*>(pixels)), width_(width), height_(height), stride_(stride), format_(format),
          bottom_(height) {}
    // A band of a picture: its rows [top, bottom) held at `pixels` (the band's first row), the
    // picture width x height, for a frame drawn a band at a time where RAM holds no whole frame
    // (the firmware). Only the band's rows may be written: draw_world keeps to them, as do the
    // HUD's text and clear(); other writers (draw_polyline without a RowRange) do not.
    static Canvas band(void* pixels, int width, int height, std::ptrdiff_t stride, PixelFormat format, int top,
                       int bottom) {
        Canvas c(pixels, width, height, stride, format);
        // (where row 0 would be, an address never read or written: computed as an integer)
        c.base_ = reinterpret_cast<uint8_t*>(reinterpret_cast<std::uintptr_t>(pixels) -
                                             static_cast<std::uintptr_t>(static_cast<std::ptrdiff_t>(top) * stride));
        c.top_ = top, c.bottom_ = bottom;
        return c;
    }

    int width() const { return width_; }
    int height() const { return height_; }
    std::ptrdiff_t stride() const { return stride_; }
    const PixelFormat& format() const { return format_; }
    uint8_t* row(int y) const { return base_ + y * stride_; }
    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
    // The rows held, [top, bottom): all of them but in a band.
    int top() const { return top_; }
    int bottom() const { return bottom_; }
    bool whole() const { return top_ <= 0 && bottom_ >= height_; }

    // Raw word access; the caller guarantees 0 <= x < width, 0 <= y < height.
    uint32_t get_word(int x, int y) const {
        const uint8_t* p = row(y) + x * format_.bytes_per_pixel();
        switch (format_.bits_per_pixel) {
            case 16: return uint32_t{p[0]} | uint32_t{p[1]} << 8;
            case 24: return uint32_t{p[0]} | uint32_t{p[1]} << 8 | uint32_t{p[2]} << 16;
            default: return uint32_t{p[0]} | uint32_t{p[1]} << 8 | uint32_t{p[2]} << 16 | uint32_t{p[3]} << 24;
        }
    }
    void set_word(int x, int y, uint32_t w) const {
        uint8_t* p = row(y) + x * format_.bytes_per_pixel();
        switch (format_.bits_per_pixel) {
            case 16: p[0] = uint8_t(w), p[1] = uint8_t(w >> 8); break;
            case 24: p[0] = uint8_t(w), p[1] = uint8_t(w >> 8), p[2] = uint8_t(w >> 16); break;
            default: p[0] = uint8_t(w), p[1] = uint8_t(w >> 8), p[2] = uint8_t(w >> 16), p[3] = uint8_t(w >> 24); break;
        }
    }
    Rgb get(int x, int y) const { return format_.unpack(get_word(x, y)); }
    void set(int x, int y, Rgb c) const { set_word(x, y, format_.pack(c)); }

    // Blends colour c over the pixel with coverage a in 0..255 (linear in the stored values:
    // result = dst + (c - dst) * a / 255, per 8-bit channel, then packed).
    void blend(int x, int y, Rgb c, int a) const {
        if (a >= 255) return set(x, y, c);
        if (a <= 0) return;
        const Rgb d = get(x, y);
        auto mix = [a](int s, int t) { return static_cast<uint8_t>(t + ((s - t) * a + (s > t ? 127 : -127)) / 255); };
        set(x, y, {mix(c.r, d.r), mix(c.g, d.g), mix(c.b, d.b)});
    }

    void clear(Rgb c) const {
        const uint32_t w = format_.pack(c);
        for (int y = top_; y < height_ && y < bottom_; ++y)
            for (int x = 0; x < width_; ++x) set_word(x, y, w);
    }

private:
    uint8_t* base_ = nullptr;
    int width_ = 0, height_ = 0;
    std::ptrdiff_t stride_ = 0;
    PixelFormat format_ = PixelFormat::xrgb8888();
    int top_ = 0, bottom_ = 0;
};

}  // namespace noneuclid::render
