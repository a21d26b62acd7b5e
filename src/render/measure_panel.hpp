// The instruments' readings on the screen (docs/measure.md): one panel of short lines per
// instrument that is on, beside the disc (the first on the right, the next on the left), in the
// HUD's font at twice its size where the side has room (on the kiosk's 800x480, characters 32
// pixels tall: legible from two metres). A construction the instrument cannot measure shows its
// sentence, never a NaN. Nothing where the sides have no room for it (a square picture).
// Allocates nothing.
#pragma once

#include "render/canvas.hpp"
#include "render/font.hpp"
#include "world/instruments.hpp"
#include "lang/lang.hpp"

namespace noneuclid::render {

// The panel's width in characters: its longest line ("area 0.433 FE", "d(s) 0.480 LE"). At
// twice the built-in font's 6 pixels, 156 pixels: the 160 beside the kiosk's 480-pixel disc.
inline constexpr int kPanelColumns = 13;

// The readings' lines: a label, the value (angles to 0.1°, lengths, areas and ratios to 0.001)
// and its unit: ° for an angle, the language's abbreviation of the world's unit of length for a
// length and of its square for an area (unit_length and unit_area in lang/texts.hpp: u, u²).
struct MeasurePanel {
    static constexpr int kLines = 10, kWidth = 48;
    int lines = 0;
    char text[kLines][kWidth] = {};
};

// A reading's numbers as the panel shows them, without the panel's other lines (the worksheet's
// blanks and its key's values, app/worksheet.hpp): a label ("A", "sum", "area"), the value
// rounded and its unit ("°", the language's "u²", "" for a ratio). None while the instrument
// waits for marks or cannot measure.
struct PanelReading {
    char label[16] = {}, value[16] = {}, unit[8] = {};
};
struct PanelReadings {
    static constexpr int kMax = 8;
    int count = 0;
    PanelReading row[kMax];
};
PanelReadings panel_readings(const world::GaugeReading& r, lang::Language language = lang::Language::en);

// The panel's lines for a reading.
MeasurePanel measure_panel(const world::GaugeReading& r, lang::Language language = lang::Language::en);
// Draws it in the box render/layout.hpp keeps for it (HudLayout::panel), at `scale`: nothing
// where the box is empty.
struct Box;
void draw_measure_panel(const Canvas& c, const Font& font, const MeasurePanel& p, const Box& at, int scale,
                        Rgb color = {255, 225, 140}, Rgb dim = {170, 175, 190});

}  // namespace noneuclid::render
