#include "render/layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/measure_panel.hpp"

using noneuclid::lang::Text;

namespace noneuclid::render {

bool overlap(const Box& a, const Box& b) {
    if (a.empty() || b.empty()) return false;
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

double distance_to(const Box& b, double x, double y) {
    // (The box's pixels span [x, x + w) x [y, y + h): their far edges at x + w and y + h.)
    const double dx = std::max({b.x - x, 0.0, x - (b.x + b.w)}), dy = std::max({b.y - y, 0.0, y - (b.y + b.h)});
    return std::sqrt(dx * dx + dy * dy);
}

namespace {

// The width of `cells` of the font's widest cell, for a line whose text changes as the world runs.
int cells(const Font& font, int n, int scale) { return n * font.width * scale; }

// The top-left lines' box: K, the frame rate, the scene and view, the note, below the title.
Box top_left_box(const Font& font, const HudInfo& h, const HudLayout& l, int y) {
    char text[128];
    int w = 0, lines = 1;
    for (double K : {-1e-4, 1e-4, -0.5, 0.0}) {  // K at its widest, in each word
        k_line(text, sizeof text, K, h.language);
        w = std::max(w, text_width(font, text, l.scale));
    }
    if (h.fps > 0) ++lines, w = std::max(w, text_width(font, "999.9 fps", l.scale));
    if (h.scene[0] || h.projection[0]) {
        std::snprintf(text, sizeof text, "%s  %s", h.scene, h.projection);
        ++lines, w = std::max({w, text_width(font, text, l.scale), cells(font, 30, l.scale)});  // (P changes the view)
    }
    if (h.note[0]) ++lines, w = std::max(w, text_width(font, h.note, l.scale) + cells(font, 3, l.scale));
    return {l.margin, y, w, (lines - 1) * l.line + font.height * l.scale};
}

// The game's corner: the score, the level and up to ten lives, at their widest.
Box top_right_box(const Font& font, const HudInfo& h, const HudLayout& l, int width) {
    char text[96];
    std::snprintf(text, sizeof text, lang::text(Text::score, h.language), 99999999L);
    int w = text_width(font, text, l.scale);
    std::snprintf(text, sizeof text, lang::text(Text::level, h.language), 99);
    w = std::max(w, text_width(font, text, l.scale));
    const int size = font.height * l.scale;
    w = std::max(w, 10 * (size + 2 * l.scale));
    return {width - l.margin - w, l.margin, w, 2 * l.line + size + l.scale};  // (+ the ships' lines)
}

// The bottom block wrapped to `wrap`: the caption's lines over the legend's (the longer of the
// two legends), ending at the canvas's bottom margin.
Box bottom_box(const Font& font, const HudInfo& h, const HudLayout& l, int height, int wrap, int& legend_lines) {
    const Wrapped a = measure_wrapped(font, h.controls, "  ", l.scale, wrap);
    const Wrapped b = measure_wrapped(font, h.other_legend, "  ", l.scale, wrap);
    const Wrapped c = measure_wrapped(font, h.caption, " ", l.scale, wrap);
    legend_lines = std::max(a.lines, b.lines);
    const int last = height - l.margin - font.height * l.scale;  // the last legend line's top
    int top = last - (legend_lines - 1) * l.line;
    if (c.lines > 0) top = last - legend_lines * l.line - l.line / 2 - (c.lines - 1) * l.line;
    if (legend_lines + c.lines == 0) return {};
    return {l.margin, top, std::max({a.widest, b.widest, c.widest}), last + font.height * l.scale - top};
}

// The largest disc centred on the canvas, at most `side` across, that keeps `gap` pixels from
// every box.
int disc_clear_of(int width, int height, int side, int gap, const Box* boxes, int n) {
    double r = side / 2.0;
    for (int i = 0; i < n; ++i)
        if (!boxes[i].empty()) r = std::min(r, distance_to(boxes[i], width / 2.0, height / 2.0) - gap);
    return std::max(16, 2 * static_cast<int>(std::floor(r)));
}

// The panels beside the disc: the first right, the second left, each vertically centred, moved
// below the corner above it where they would meet, and left out where the side has no room.
void place_panels(const Font& font, const HudInfo& h, HudLayout& l, int width, int height) {
    const int room = (width - l.disc) / 2;
    // (A square picture has no room: the dump has the numbers.)
    if (h.panels <= 0 || room < kPanelColumns * font.width) return;
    l.panel_scale = room >= kPanelColumns * 2 * font.width && height >= 10 * 2 * font.height ? 2 : 1;
    const int w = kPanelColumns * font.width * l.panel_scale;
    const int hgt = MeasurePanel::kLines * (font.height * l.panel_scale + 2 * l.panel_scale);
    const int inset = std::max(0, (room - w) / 2);
    for (int side = 0; side < std::min(h.panels, 2); ++side) {
        const Box& corner = side == 0 ? l.top_right : l.top_left;
        Box p{side == 0 ? width - w - inset : inset, (height - hgt) / 2, w, hgt};
        const int below = std::max(corner.empty() ? 0 : corner.y + corner.h, l.title.empty() ? 0 : l.title.y + l.title.h);
        if (overlap(p, corner) || overlap(p, l.title)) p.y = below + l.line;
        if (overlap(p, l.bottom) || p.y + p.h > height) continue;  // no room between the corners
        l.panel[side] = p;
    }
}

}  // namespace

HudLayout layout_hud(int width, int height, const Font& font, const HudInfo& h) {
    HudLayout l;
    l.scale = (h.scale > 0 ? h.scale : height >= 900 ? 2 : 1) * (h.large ? 2 : 1);
    l.margin = 6 * l.scale, l.line = font.height * l.scale + 2 * l.scale;
    l.title_scale = 2 * l.scale;
    const int side = std::min(width, height), gap = 2 + 2 * l.scale;
    int y = l.margin;
    if (h.title[0]) {
        l.title = {l.margin, y, text_width(font, h.title, l.title_scale), font.height * l.title_scale};
        y += l.title.h + l.line / 2;
    }
    if (h.on) {
        l.top_left = top_left_box(font, h, l, y);
        if (h.game.on) l.top_right = top_right_box(font, h, l, width);
    }
    // The bottom block beside the disc (in the column its full size leaves) or across the width.
    l.wrap = width - 2 * l.margin;
    Box boxes[4] = {l.title, l.top_left, l.top_right, {}};
    int legend_lines = 0;
    if (h.on) boxes[3] = bottom_box(font, h, l, height, l.wrap, legend_lines);
    l.disc = disc_clear_of(width, height, side, gap, boxes, 4);
    const int column = (width - side) / 2 - 2 * l.margin;
    if (h.on && column >= cells(font, 12, l.scale)) {
        int lines = 0;
        Box beside[4] = {l.title, l.top_left, l.top_right, bottom_box(font, h, l, height, column, lines)};
        const int disc = disc_clear_of(width, height, side, gap, beside, 4);
        if (disc > l.disc && !overlap(beside[3], l.top_left) && !overlap(beside[3], l.title))
            l.disc = disc, l.wrap = column, boxes[3] = beside[3], legend_lines = lines;
    }
    l.bottom = boxes[3];
    l.legend_lines = legend_lines;
    place_panels(font, h, l, width, height);
    return l;
}

}  // namespace noneuclid::render
