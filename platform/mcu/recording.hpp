// A recording (app/script.hpp's actions format) as the firmware plays it: the settings it can
// honour and its press, release and tap events, parsed from text into fixed arrays (no heap).
// The firmware draws what `noneuclid render --actions` draws for it, so a setting it cannot
// draw the same way (another engine, size or format, a palette, the HUD in another language or
// font or size, marks, attract mode) is refused with one sentence rather than drawn differently.
#pragma once

#include <cstddef>

#include "geometry/projection.hpp"
#include "world/action.hpp"

namespace noneuclid::mcu {

struct RecordedEvent {
    double time = 0;
    bool pressed = true;
    bool tap = false;  // press and release at once
    world::Action control = world::Action::thrust;
};

struct Recording {
    static constexpr int kMaxEvents = 256;
    char scene[24] = "kiosk";
    geo::Projection projection = geo::Projection::azimuthal_equidistant;
    bool aa = false;
    bool hud = false;  // the HUD, in English with the built-in font (which the recording must name)
    bool named_font = false, named_lang = false;  // "font builtin", "lang en" were given
    long best = 0;    // the game's high score the HUD shows
    long frames = 60;  // steps after the first frame (render's default)
    int count = 0;
    RecordedEvent events[kMaxEvents];  // sorted by time, ties in file order
};

// Parses `text` (NUL-terminated; its lines are changed in place). False, with one sentence in
// `why`, on anything the firmware would not draw as render does.
bool parse_recording(char* text, Recording& out, char* why, std::size_t why_size);

}  // namespace noneuclid::mcu
