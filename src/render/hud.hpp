// The heads-up display: K with "spherical / flat / hyperbolic", the frame rate, the controls,
// in a bitmap font (a PSF console font when the platform found one, the built-in one
// otherwise). Drawn top-left and bottom-left over the picture; allocates nothing.
#pragma once

#include <cstdio>

#include "render/canvas.hpp"
#include "render/font.hpp"

namespace noneuclid::render {

struct HudInfo {
    double K = 0;
    double fps = 0;            // <= 0: not shown (a still picture)
    const char* scene = "";
    const char* projection = "";
    const char* controls = "thrust  left/right  curvature +/-  preset  reset";
};

inline const char* curvature_word(double K) {
    // Within half a Q16.16 step of 0 the space is flat; the sign decides otherwise.
    return K > 1e-5 ? "spherical" : (K < -1e-5 ? "hyperbolic" : "flat");
}

inline void draw_hud(const Canvas& c, const Font& font, const HudInfo& h, Rgb color = {220, 225, 235},
                     Rgb dim = {140, 150, 170}) {
    const int scale = c.height() >= 900 ? 2 : 1;
    const int margin = 6 * scale, line = font.height * scale + 2 * scale;
    char text[96];
    std::snprintf(text, sizeof text, "K = %+.3f  %s", h.K, curvature_word(h.K));
    draw_text(c, font, margin, margin, text, color, scale);
    int y = margin + line;
    if (h.fps > 0) {
        std::snprintf(text, sizeof text, "%.1f fps", h.fps);
        draw_text(c, font, margin, y, text, dim, scale);
        y += line;
    }
    if (h.scene[0] || h.projection[0]) {
        std::snprintf(text, sizeof text, "%s  %s", h.scene, h.projection);
        draw_text(c, font, margin, y, text, dim, scale);
    }
    draw_text(c, font, margin, c.height() - margin - font.height * scale, h.controls, dim, scale);
}

}  // namespace noneuclid::render
