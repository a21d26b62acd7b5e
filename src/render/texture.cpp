#include "render/texture.hpp"

#include "render/backdrop.hpp"

namespace noneuclid::render {

void PackedTexture::make(const world::Image& im) {
    image = &im;
    width = im.width, height = im.height;
    words.assign(im.texels.size(), 0);
    packed = false;
}

void PackedTexture::pack_for(const PixelFormat& f) {
    if (packed && format.same_layout(f)) return;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const uint32_t t = image->texels[i];
        words[i] = f.pack({static_cast<uint8_t>(t >> 16), static_cast<uint8_t>(t >> 8), static_cast<uint8_t>(t)});
    }
    format = f, packed = true;
}

void PixelWriter::run(int y, int x0, int x1, uint32_t w) const {
    if (x1 <= x0) return;
    const int bpp = c.format().bytes_per_pixel();
    detail::fill_span(c.row(y) + static_cast<std::ptrdiff_t>(x0) * bpp, x1 - x0, detail::SpanPattern(w, bpp));
}

}  // namespace noneuclid::render
