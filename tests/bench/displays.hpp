// The two displays the frame benchmarks measure side by side: the kiosk's (800x480 RGB565) and
// a desktop's (1920x1080 XRGB8888).
#pragma once

#include "render/canvas.hpp"

struct BenchDisplay {
    const char* name;
    int w, h;
    noneuclid::render::PixelFormat f;
};

inline const BenchDisplay kBenchDisplays[] = {
    {"800x480_rgb565", 800, 480, noneuclid::render::PixelFormat::rgb565()},
    {"1920x1080_xrgb8888", 1920, 1080, noneuclid::render::PixelFormat::xrgb8888()}};
