// What a button, a key or the attract-mode autopilot can ask for: the world's actions (held or
// tapped, see world.hpp) plus the display's own commands. Board files name them; the input
// backends (platform/linux) deliver them as press/release events.
#pragma once

#include <cstdint>
#include <string>

#include "world/action.hpp"

namespace noneuclid::world {

enum class Control : uint8_t {
    thrust, left, right, curvature_up, curvature_down, preset, reset,  // = world::Action, same order
    hyperbolic, flat, spherical, fire, instrument, strength_up, strength_down,
    projection,  // next projection (on press)
    hud,         // HUD on/off (on press)
    quit,        // leave the program (on press; for keyboards, not kiosk buttons)
    mute,        // sound off/on (on press; app/sound.hpp)
};
inline constexpr int kControlCount = 18;
static_assert(static_cast<int>(Control::thrust) == static_cast<int>(Action::thrust) &&
              static_cast<int>(Control::left) == static_cast<int>(Action::turn_left) &&
              static_cast<int>(Control::right) == static_cast<int>(Action::turn_right) &&
              static_cast<int>(Control::curvature_up) == static_cast<int>(Action::curvature_up) &&
              static_cast<int>(Control::curvature_down) == static_cast<int>(Action::curvature_down) &&
              static_cast<int>(Control::preset) == static_cast<int>(Action::next_preset) &&
              static_cast<int>(Control::reset) == static_cast<int>(Action::reset) &&
              static_cast<int>(Control::spherical) == static_cast<int>(Action::spherical) &&
              static_cast<int>(Control::fire) == static_cast<int>(Action::fire) &&
              static_cast<int>(Control::instrument) == static_cast<int>(Action::instrument) &&
              static_cast<int>(Control::strength_down) == static_cast<int>(Action::strength_down) &&
              static_cast<int>(Control::projection) == kActionCount,
              "the first controls are the world's actions, in the same order");

inline const char* control_name(Control c) {
    static const char* const names[] = {"thrust",     "left", "right",     "curvature_up", "curvature_down",
                                        "preset",     "reset", "hyperbolic", "flat",        "spherical",
                                        "fire",       "instrument", "strength_up", "strength_down", "projection", "hud",
                                        "quit",       "mute"};
    static_assert(sizeof names / sizeof names[0] == kControlCount, "a control without its name");
    return names[static_cast<int>(c)];
}
inline bool parse_control(const std::string& s, Control& out) {
    for (int i = 0; i < kControlCount; ++i)
        if (s == control_name(static_cast<Control>(i))) {
            out = static_cast<Control>(i);
            return true;
        }
    return false;
}
// The world action a control is, if it is one.
inline bool control_action(Control c, Action& out) {
    if (static_cast<int>(c) >= kActionCount) return false;
    out = static_cast<Action>(c);
    return true;
}

struct InputEvent {
    Control control = Control::thrust;
    bool pressed = false;
};

}  // namespace noneuclid::world
