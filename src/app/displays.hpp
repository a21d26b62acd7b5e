// The displays `noneuclid run` shows a world on, one row each: its name (--display, a
// recording's display), its line in --help, the platform's kind (platform::choose_display picks
// one when not told) and how it is opened. A new display is its implementation of the display
// contract (app/display.hpp) and one row here.
#pragma once

#include <memory>
#include <string>

#include "app/display.hpp"
#include "app/platform.hpp"

namespace noneuclid::app {

struct Options;

struct DisplayRow {
    platform::DisplayKind kind;
    const char* name;
    const char* help;
    bool kiosk;  // the kiosk's: it takes a board (--board, --input) and draws at the device's size
    // Opens it for options o (the kiosk: board b); null with one sentence in `error`.
    std::unique_ptr<Display> (*open)(const Options& o, const files::Board& b, std::string& error);
};

// The rows (app/displays.cpp).
const DisplayRow* display_rows(std::size_t& count);
// The row of `kind`, or of the display named `name`; null if none.
const DisplayRow* display_row(platform::DisplayKind kind);
const DisplayRow* display_named(const std::string& name);

}  // namespace noneuclid::app
