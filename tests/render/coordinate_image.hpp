// The test image of the fill tests: texel (x, y) of a 64 x 64 image holds its own coordinates (red
// 4 x, green 4 y, blue 0x80), so a drawn pixel says which texel it was read from.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>

#include "world/image.hpp"

namespace noneuclid::test {

inline std::shared_ptr<const world::Image> coordinate_image() {
    auto im = std::make_shared<world::Image>();
    im->width = im->height = 64;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) im->texels.push_back(uint32_t(4 * x) << 16 | uint32_t(4 * y) << 8 | 0x80);
    return im;
}

// Texels apart along one axis, round the image, which repeats.
inline int texel_gap(int a, int b) {
    const int d = std::abs(a - b) % 64;
    return std::min(d, 64 - d);
}

}  // namespace noneuclid::test
