// Every pixel format a canvas supports, for the tests that run in each.
#pragma once

#include <cstddef>

#include "render/canvas.hpp"

namespace noneuclid::test {

inline const render::PixelFormat kFormats[] = {render::PixelFormat::rgb565(),   render::PixelFormat::bgr565(),
                                               render::PixelFormat::xrgb8888(), render::PixelFormat::xbgr8888(),
                                               render::PixelFormat::rgb888(),   render::PixelFormat::bgr888(),
                                               render::PixelFormat::rgba8888()};
inline constexpr std::size_t kFormatCount = sizeof(kFormats) / sizeof(kFormats[0]);

}  // namespace noneuclid::test
