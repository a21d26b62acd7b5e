// Palettes (docs/accessibility.md): how a frame's colours are chosen. `scene` draws every body
// in its own colour (the scene's or scene file's); `colour-blind` and `high-contrast` draw by
// what a line is (the ship, an asteroid, a bullet, another body, a grid line, an instrument),
// so that the roles stay apart for everyone:
//  - colour-blind: Okabe and Ito's colours, every pair of line colours (and each against the
//    background) at least 15 apart in CIELAB (CIE76) under normal vision and simulated
//    protanopia, deuteranopia and tritanopia (17 at worst: the most seven of their colours
//    reach); a grid line keeps its own brightness in reddish purple, so the Earth's coast stays
//    brighter than its graticule;
//  - high-contrast: a black background and every line and the HUD's text at 7:1 or more
//    against it (WCAG's AAA contrast ratio), a grid line in its own hue, raised to that.
// The tests check both claims against the published simulation matrices and on drawn pixels.
#pragma once

#include <cstdint>

#include "render/canvas.hpp"
#include "world/palette_names.hpp"

namespace noneuclid::render {

// The palettes and their names are world/palette_names.hpp's (a board file reads them there,
// below the renderer); here they are the renderer's own names too.
using world::Palette, world::kPalettes, world::PaletteRow, world::kPaletteRows;
using world::palette_name, world::palette_help, world::parse_palette, world::palette_names;

// What a line is, for a palette: world::BodyKind's order (render/body_points.hpp checks it).
enum class LineRole : uint8_t { body, ship, asteroid, bullet, grid, instrument };

// A line's colour in palette p: its own colour in the scene palette, else its role's.
Rgb palette_line(Palette p, LineRole role, Rgb own);

// The frame's other colours in palette p: the disc's background, outside the limit circle, the
// limit circle's line, and the HUD's text (bright and dim).
struct PaletteFrame {
    Rgb background{6, 8, 14}, outside{26, 30, 44}, rim{200, 205, 215};
    Rgb text{220, 225, 235}, dim{140, 150, 170};
};
PaletteFrame palette_frame(Palette p);

}  // namespace noneuclid::render
