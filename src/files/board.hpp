// Board files (TOML): what a kiosk is wired to and how it shows the world. One per board in
// boards/ (rpi-zero2w, rpi3, rpi4, rpi5, generic); docs/file-formats.md documents them.
//
//     name = "Raspberry Pi 4 Model B / 400"
//     models = ["Raspberry Pi 4", "Raspberry Pi 400"]  # /proc/device-tree/model prefixes
//     [display]
//     device = "/dev/fb0"     # framebuffer
//     fps = 60                # frame-rate cap (world time is always 1/60 s a frame)
//     scene = "kiosk"         # built-in scene or scene file
//     engine = "fixed"        # fixed, double, float
//     projection = "equidistant"
//     antialias = false
//     hud = true
//     palette = "scene"       # scene, colour-blind, high-contrast, print
//     large_hud = false       # the HUD's text twice as large
//     one_button = false      # fire alone plays
//     sound = false           # the game's sound (docs/sound.md)
//     language = ""           # en, de, fr; empty: the locale's
//     threads = 1             # drawing threads (1: the main thread only)
//     [gpio]
//     chip = ["pinctrl-bcm2711"]  # labels or /dev/gpiochipN paths, tried in order
//     debounce_ms = 10
//     [evdev]
//     device = ""             # empty: any key device that has the codes
//     grab = true
//     [attract]
//     idle_seconds = 120      # no button for this long: the autopilot flies; 0: never
//     sweep_seconds = 40      # one sweep of K from -1 to +1 (and as long back)
//     lesson = ""             # a lesson attract mode plays instead (docs/lessons.md)
//     [[button]]
//     action = "thrust"       # world::Action names
//     gpio = 17               # line offset on the chip (the BCM number on a Pi); optional
//     pin = 11                # header pin, informational (1-40)
//     key = 57                # evdev key code (KEY_SPACE); optional
#pragma once

#include <string>
#include <vector>

#include "world/action.hpp"
#include "files/scene_file.hpp"  // SceneError

namespace noneuclid::files {

struct BoardButton {
    world::Action control = world::Action::thrust;
    int gpio = -1;  // -1: not on GPIO
    int pin = 0;    // 0: not given
    int key = -1;   // -1: no key code
};

struct Board {
    std::string name = "generic";
    std::string file;  // where it was read from ("" for built-in defaults)
    std::vector<std::string> models;
    // [display]
    std::string device = "/dev/fb0";
    double fps = 60;
    std::string scene = "kiosk";
    std::string engine;  // "": none named (the kind of world's first, fixed for a world of constant K)
    std::string projection = "equidistant";
    bool antialias = false;
    bool hud = true;
    std::string palette = "scene";  // world/palette_names.hpp's names
    bool large_hud = false;
    std::string language;  // en, de, fr ("" the locale's)
    bool one_button = false;  // fire alone plays (docs/accessibility.md)
    bool sound = false;       // the game's sound (docs/sound.md): off unless the board turns it on
    int threads = 1;
    // [gpio]
    std::vector<std::string> chips;
    int debounce_ms = 10;
    // [evdev]
    std::string evdev_device;
    bool grab = true;
    // [attract]
    double idle_seconds = 120;
    double sweep_seconds = 40;
    std::string attract_lesson;  // "" attract mode flies the ship; else it plays this lesson

    std::vector<BoardButton> buttons;
    bool has_gpio() const {
        for (const BoardButton& b : buttons)
            if (b.gpio >= 0) return true;
        return false;
    }
    bool has_keys() const {
        for (const BoardButton& b : buttons)
            if (b.key >= 0) return true;
        return false;
    }
};

// Where and what: "file:line:column: message", like a scene file's errors.
using BoardError = SceneError;

bool parse_board(const std::string& text, const std::string& name, Board& out, BoardError& error);
bool load_board_file(const std::string& path, Board& out, BoardError& error);

// A board file read over `board` (a kiosk's local settings, /etc/noneuclid/board.toml): each
// key it sets replaces the board's value, its [[button]] entries (if any) replace all of the
// board's buttons, and what it leaves out stays as the board has it; `board.file` still names
// the board's own file. On failure `board` is unchanged.
bool overlay_board_file(const std::string& path, Board& board, BoardError& error);

}  // namespace noneuclid::files
