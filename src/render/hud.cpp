#include "render/hud.hpp"

#include <cstdio>

namespace noneuclid::render {

const char* curvature_word(double K) { return K > 1e-5 ? "spherical" : (K < -1e-5 ? "hyperbolic" : "flat"); }

void draw_hud(const Canvas& c, const Font& font, const HudInfo& h, Rgb color, Rgb dim) {
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
