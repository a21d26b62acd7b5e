// Screen points as render speaks of them: the geometry's sub-pixel points, screen mapping and
// curve points (geometry/screen_map.hpp), named here for the drawing code.
#pragma once

#include "geometry/screen_map.hpp"

namespace noneuclid::render {

using geo::kAntipodeMarginPx;
using geo::kBreak;
using geo::ScreenMap;
using geo::to_pixels;

}  // namespace noneuclid::render
