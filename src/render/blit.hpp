// Copying a finished frame to the display: the RAM back buffer to the framebuffer, once per
// frame. Same size and pixel format on both sides; rows may have different strides (fbdev's
// line_length is often wider than xres * bytes). One memcpy when both are contiguous, else one
// per row. Allocates nothing.
#pragma once

#include <cstring>

#include "render/canvas.hpp"

namespace noneuclid::render {

// Copies min(width) x min(height) pixels of `src` into `dst`; formats must be equal.
inline void copy_canvas(const Canvas& src, const Canvas& dst) {
    const int w = src.width() < dst.width() ? src.width() : dst.width();
    const int h = src.height() < dst.height() ? src.height() : dst.height();
    if (w <= 0 || h <= 0) return;
    const std::size_t row_bytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(src.format().bytes_per_pixel());
    if (src.stride() == dst.stride() && static_cast<std::size_t>(src.stride()) == row_bytes) {
        std::memcpy(dst.row(0), src.row(0), row_bytes * static_cast<std::size_t>(h));
        return;
    }
    for (int y = 0; y < h; ++y) std::memcpy(dst.row(y), src.row(y), row_bytes);
}

}  // namespace noneuclid::render
