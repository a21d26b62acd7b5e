// Where the HUD's parts go on a canvas, and how large the shown disc may be so that none of them
// crosses it: the title (a figure's label), the top-left lines (K, frame rate, scene and view,
// the kind's note), the game's corner (top right), the bottom block (a lesson's caption over the
// controls' legend) and the instruments' panels (beside the disc). The disc stays centred and
// fills the smaller side where the parts fit around it; where they do not (a square canvas, a
// legend too long for the corners) it shrinks until they clear it. The bottom block wraps to the
// column beside the disc or to the whole width, whichever leaves the larger disc. Lines whose
// text changes as the world runs (K, the frame rate, the note, the game's numbers) and the two
// legends (the user's and attract mode's) are laid out at their widest, so that the disc keeps
// its size while the world moves. The game's middle screen ("press fire", "game over") is drawn
// over the world on purpose and is not laid out. Allocates nothing.
#pragma once

#include "render/font.hpp"
#include "render/hud.hpp"

namespace noneuclid::render {

struct Box {
    int x = 0, y = 0, w = 0, h = 0;
    bool empty() const { return w <= 0 || h <= 0; }
};
// Whether two boxes share a pixel (an empty box shares none).
bool overlap(const Box& a, const Box& b);
// The distance from (x, y) to the box's nearest point (0 inside it).
double distance_to(const Box& b, double x, double y);

struct HudLayout {
    int scale = 1, margin = 6, line = 10;  // pixels per font pixel, the edge's margin, a line's height
    int disc = 0;                          // the shown disc's diameter, px (geo::ScreenMap::of)
    int wrap = 0;                          // the width the bottom block's lines wrap to
    int legend_lines = 0;                  // the legend's lines (the longer legend's), under the caption
    int title_scale = 2, panel_scale = 1;
    Box title, top_left, top_right, bottom;
    Box panel[2];  // the instruments' first (right of the disc) and second (left); empty: no room
    static constexpr int kBoxes = 6;
    const Box& box(int i) const {
        const Box* all[kBoxes] = {&title, &top_left, &top_right, &bottom, &panel[0], &panel[1]};
        return *all[i];
    }
};

// The layout of `h` (with h.on false only its title and panels) on a canvas of width x height.
HudLayout layout_hud(int width, int height, const Font& font, const HudInfo& h);

}  // namespace noneuclid::render
