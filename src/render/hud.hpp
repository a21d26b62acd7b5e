// The heads-up display: K with "spherical / flat / hyperbolic", the frame rate, the scene and
// projection, and a line of controls the caller supplies, in a bitmap font (a PSF console font
// when the platform found one, the built-in one otherwise). Drawn top-left and bottom-left
// over the picture; allocates nothing.
#pragma once

#include "render/canvas.hpp"
#include "render/font.hpp"

namespace noneuclid::render {

struct HudInfo {
    double K = 0;
    double fps = 0;            // <= 0: not shown (a still picture)
    const char* scene = "";
    const char* projection = "";
    const char* controls = "";  // the bottom line: the controls' legend, from the app
};

// "spherical", "flat" or "hyperbolic": the sign of K, flat within half a Q16.16 step of 0.
const char* curvature_word(double K);

void draw_hud(const Canvas& c, const Font& font, const HudInfo& h, Rgb color = {220, 225, 235},
              Rgb dim = {140, 150, 170});

}  // namespace noneuclid::render
