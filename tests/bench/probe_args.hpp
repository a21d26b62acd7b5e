// The instruction-count probes' canvas words (space_probe, uneven_probe): WxH, at least 16 each
// way, and FORMAT rgb565|xrgb8888|rgb888 (anything else: rgb565).
#pragma once

#include <cstdio>
#include <cstring>

#include "render/canvas.hpp"

namespace noneuclid::probe {

inline bool canvas_words(const char* size, const char* format, int& w, int& h, render::PixelFormat& f) {
    if (std::sscanf(size, "%dx%d", &w, &h) != 2 || w < 16 || h < 16) return false;
    f = render::PixelFormat::rgb565();
    if (std::strcmp(format, "xrgb8888") == 0) f = render::PixelFormat::xrgb8888();
    if (std::strcmp(format, "rgb888") == 0) f = render::PixelFormat::rgb888();
    return true;
}

}  // namespace noneuclid::probe
