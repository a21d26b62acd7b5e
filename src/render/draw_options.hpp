// What a drawn frame shows and how: the projection, the lines' style, the backdrop's colours,
// which bodies are drawn, the palette.
#pragma once

#include <cstdint>

#include "geometry/geometry.hpp"
#include "render/canvas.hpp"
#include "render/palette.hpp"
#include "render/raster.hpp"

namespace noneuclid::render {

struct DrawOptions {
    geo::Projection projection = geo::Projection::azimuthal_equidistant;
    bool antialias = false;
    int32_t line_width = kSub;  // 1/256 px
    bool shade_outside = true;
    Rgb background{6, 8, 14};
    Rgb outside{26, 30, 44};
    Rgb rim{200, 205, 215};  // the limit circle's line
    bool rim_line = true;    // draw the limit circle
    bool grids = true;   // draw grid bodies
    bool bodies = true;  // draw the other bodies
    bool tint_grids = false;  // draw grid bodies in grid_tint rather than their own colour
    Rgb grid_tint{};
    Palette palette = Palette::scene;
    int disc = 0;  // the shown disc's diameter in px (0: the canvas's smaller side; render/layout.hpp)  // the lines' colours (render/palette.hpp; the frame's: set them above)
};

}  // namespace noneuclid::render
