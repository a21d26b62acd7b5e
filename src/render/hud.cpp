#include "render/hud.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>

#include "render/layout.hpp"
#include "render/raster.hpp"

using noneuclid::lang::Text;

namespace noneuclid::render {

namespace {

// A line of text centred on x.
void centred(const Canvas& c, const Font& font, int x, int y, const char* text, Rgb color, int scale) {
    draw_text(c, font, x - text_width(font, text, scale) / 2, y, text, color, scale);
}

// A life: a little ship, its nose up, `size` pixels tall, top-left at (x, y).
void life(const Canvas& c, int x, int y, int size, Rgb color) {
    const SubPoint p[3] = {to_sub(x + size * 0.35, y), to_sub(x + size * 0.7, y + size), to_sub(x, y + size)};
    draw_polyline(c, p, 3, true, color, {}, held_rows(c));
}

// The game's corner (score, level, lives) and its screen in the middle.
void draw_game(const Canvas& c, const Font& font, const HudInfo& h, int scale, int margin, int line, Rgb color, Rgb dim) {
    const HudGame& g = h.game;
    const auto t = [&h](Text name) { return lang::text(name, h.language); };
    char text[96];
    std::snprintf(text, sizeof text, t(Text::score), g.score);
    draw_text(c, font, c.width() - margin - text_width(font, text, scale), margin, text, color, scale);
    std::snprintf(text, sizeof text, t(Text::level), g.level);
    draw_text(c, font, c.width() - margin - text_width(font, text, scale), margin + line, text, dim, scale);
    const int size = font.height * scale;
    for (int i = 0; i < g.lives && i < 10; ++i)
        life(c, c.width() - margin - (i + 1) * (size + 2 * scale), margin + 2 * line, size, color);
    const int big = scale * (c.height() >= 400 ? 3 : 2), mid = c.width() / 2;
    int y = c.height() / 2 - font.height * big;
    switch (g.screen) {
        case HudGame::none: return;
        case HudGame::ready:
            centred(c, font, mid, y, t(Text::press_fire), color, big);
            y += font.height * big + line;
            std::snprintf(text, sizeof text, t(Text::best), g.best);
            centred(c, font, mid, y, text, dim, scale);
            return;
        case HudGame::over:
            centred(c, font, mid, y, t(Text::game_over), color, big);
            y += font.height * big + line;
            std::snprintf(text, sizeof text, t(g.new_best ? Text::score_new_best : Text::score), g.score);
            centred(c, font, mid, y, text, color, scale);
            if (!g.new_best) {
                std::snprintf(text, sizeof text, t(Text::best), g.best);
                centred(c, font, mid, y + line, text, dim, scale);
            }
            return;
        case HudGame::new_level:
            std::snprintf(text, sizeof text, t(Text::level), g.level);
            centred(c, font, mid, y, text, color, big);
            centred(c, font, mid, y + font.height * big + line, curvature_word(h.K, h.language), dim, scale);
            return;
    }
}

}  // namespace

const char* curvature_word(double K, lang::Language language) {
    return lang::text(K > 1e-5 ? Text::spherical : (K < -1e-5 ? Text::hyperbolic : Text::flat), language);
}

const char* projection_words(geo::Projection p, lang::Language language) {
    Text word;  // the text named as the projection is (lang/texts.hpp)
    return lang::text_named(geo::projection_name(p), word) ? lang::text(word, language) : geo::projection_name(p);
}

void k_line(char* out, std::size_t size, double K, lang::Language language) {
    // (Below a thousandth, as a zoom takes it, K keeps three digits in the exponent form.)
    std::snprintf(out, size, K != 0 && std::fabs(K) < 5e-4 ? "K = %+.2e /%s  %s" : "K = %+.3f /%s  %s", K,
                  lang::text(Text::unit_area, language), curvature_word(K, language));
}

void draw_hud(const Canvas& c, const Font& font, const HudInfo& h, const HudLayout& l, Rgb color, Rgb dim) {
    if (h.title[0]) draw_text(c, font, l.title.x, l.title.y, h.title, color, l.title_scale);
    if (!h.on) return;
    const int scale = l.scale, margin = l.margin, line = l.line;
    char text[128];
    k_line(text, sizeof text, h.K, h.language);
    int y = l.top_left.y;
    draw_text(c, font, margin, y, text, color, scale);
    y += line;
    if (h.fps > 0) {
        std::snprintf(text, sizeof text, "%.1f fps", h.fps);
        draw_text(c, font, margin, y, text, dim, scale);
        y += line;
    }
    if (h.scene[0] || h.projection[0]) {
        std::snprintf(text, sizeof text, "%s  %s", h.scene, h.projection);
        draw_text(c, font, margin, y, text, dim, scale);
        y += line;
    }
    if (h.note[0]) draw_text(c, font, margin, y, h.note, dim, scale);
    const int bottom = c.height() - margin - font.height * scale;
    draw_wrapped(c, font, h.controls, "  ", dim, scale, margin, l.wrap, line, bottom, false);
    if (h.caption[0])
        draw_wrapped(c, font, h.caption, " ", color, scale, margin, l.wrap, line, bottom - l.legend_lines * line - line / 2,
                     false);
    if (h.game.on) draw_game(c, font, h, scale, margin, line, color, dim);
}

}  // namespace noneuclid::render
