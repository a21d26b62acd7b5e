// The heads-up display: K with "spherical / flat / hyperbolic", the frame rate, the scene and
// projection, and the controls' legend the caller supplies (wrapped to the width), in a bitmap
// font (a PSF console font when the platform found one, the built-in one otherwise), at twice
// its size for a large HUD, where render/layout.hpp puts it (the disc shrunk to clear it). With a game: the score, level and lives top-right (the lives as little
// ships), and in the middle the "press fire" screen, the game-over screen with the score, or
// the new level's number and K. Allocates nothing.
#pragma once

#include <cstddef>

#include "render/canvas.hpp"
#include "render/font.hpp"
#include "geometry/projection.hpp"
#include "lang/lang.hpp"

namespace noneuclid::render {

// The game's part of the HUD (world/game.hpp), as plain numbers.
struct HudGame {
    enum Screen : uint8_t { none, ready, over, new_level };  // what the middle of the screen shows
    bool on = false;
    Screen screen = none;
    long score = 0, best = 0;  // best: the high score before this game, or this one if higher
    bool new_best = false;     // the game just over beat the high score
    int lives = 0, level = 0;
};

struct HudInfo {
    HudGame game;
    double K = 0;
    double fps = 0;            // <= 0: not shown (a still picture)
    const char* scene = "";
    const char* projection = "";
    const char* controls = "";  // the bottom line: the controls' legend, from the app
    const char* note = "";      // a line under the scene's (the earth's zoom: its view in km)
    bool large = false;         // twice the text's size (docs/accessibility.md)
    int scale = 0;              // pixels per font pixel (0: 2 on a canvas 900 tall or more, else 1)
    const char* caption = "";   // a lesson step's caption: wrapped above the legend, in the text's colour
    lang::Language language = lang::Language::en;  // of the HUD's own words (the caller's are given translated)
    bool on = true;             // the HUD's lines are shown (false: only the title and the panels)
    const char* title = "";     // a figure's label, top-left at twice the text's size, shown even with on false
    const char* other_legend = "";  // the legend shown at other times (attract mode's): laid out as the widest
    int panels = 0;             // the instruments' panels drawn beside the disc (0 to 2)
};

// "spherical", "flat" or "hyperbolic" (in `language`): the sign of K, flat within half a
// Q16.16 step of 0.
const char* curvature_word(double K, lang::Language language = lang::Language::en);

// The HUD's first line: "K = +0.442 /u²  spherical", K per the language's unit of area.
void k_line(char* out, std::size_t size, double K, lang::Language language);

// The projection's name as the HUD says it, in `language`.
const char* projection_words(geo::Projection p, lang::Language language);

struct HudLayout;  // render/layout.hpp

// Draws the HUD's lines (and its title) where `l` (layout_hud of the same info) puts them.
void draw_hud(const Canvas& c, const Font& font, const HudInfo& h, const HudLayout& l, Rgb color = {220, 225, 235},
              Rgb dim = {140, 150, 170});

}  // namespace noneuclid::render
