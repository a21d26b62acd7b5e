// The actions: everything a button, a key, a script or the attract-mode autopilot can ask for,
// in one table: its name (board files, scripts, recordings, the C interface and the page name
// it), whether it acts on its press or while held, whether it is the world's (every kind of
// world takes those, kinds/kind.hpp) or the display's own, the desktop's and the page's keys,
// and the key a plain keyboard kiosk binds it to (boards/generic.toml, checked against this
// table by a test). Adding an action is a row here and its case where it acts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace noneuclid::world {

// Held actions (thrust, the turns, curvature up and down, fire, the strengths) act while held;
// the others once, on the press. Fire shoots on its press and again each cooldown while held
// (world/game.hpp); in a scene without a game it does nothing. Instrument cycles the live
// instrument (world/instruments.hpp); while one is on, fire drops a mark where the ship is.
// Strength up and down turn an uneven world's bumps (src/uneven); a world of constant K has
// none. The world's actions come first; the order is the numbering the page and the C
// interface use, so a new action goes at the end of its group.
enum class Action : uint8_t {
    thrust, left, right, curvature_up, curvature_down, preset, reset, hyperbolic, flat, spherical,
    fire, instrument, strength_up, strength_down,
    pitch_up, pitch_down, roll_left, roll_right,  // the 3D world's ship (src/space)
    projection, hud, quit, mute,  // the display's: next projection, HUD on/off, leave, sound off/on
};

struct ActionRow {
    const char* name;
    bool on_press;  // acts once on its press (else while held)
    bool world;     // the world's (else the display's)
    // The desktop window's and the page's keys, separated by spaces: a printable character is
    // that key (X11's keysym and the page's KeyboardEvent.key alike), a word an X11 keysym name
    // (XStringToKeysym; the page maps those it has: Up, Left, Right, Escape, space, Control_L/R).
    const char* keys;
    int evdev;  // the Linux input key code a keyboard kiosk binds (boards/generic.toml); 0: none
};

inline constexpr ActionRow kActions[] = {
    {"thrust", false, true, "Up w W KP_Up", 103},            // KEY_UP
    {"left", false, true, "Left a A KP_Left", 105},          // KEY_LEFT
    {"right", false, true, "Right d D KP_Right", 106},       // KEY_RIGHT
    {"curvature_up", false, true, "+ = ] KP_Add", 13},       // KEY_EQUAL (+)
    {"curvature_down", false, true, "- [ KP_Subtract", 12},  // KEY_MINUS
    {"preset", true, true, "", 57},                          // KEY_SPACE
    {"reset", true, true, "r R", 19},                        // KEY_R
    {"hyperbolic", true, true, "1 KP_1", 0},
    {"flat", true, true, "2 KP_2", 0},
    {"spherical", true, true, "3 KP_3", 0},
    {"fire", false, true, "space Control_L Control_R", 29},  // KEY_LEFTCTRL
    {"instrument", true, true, "m M", 0},
    {"strength_up", false, true, ". >", 0},
    {"strength_down", false, true, ", <", 0},
    {"pitch_up", false, true, "i I Prior", 104},     // KEY_PAGEUP
    {"pitch_down", false, true, "k K Next", 109},    // KEY_PAGEDOWN
    {"roll_left", false, true, "q Q", 16},           // KEY_Q
    {"roll_right", false, true, "e E", 18},          // KEY_E
    {"projection", true, false, "p P", 25},  // KEY_P
    {"hud", true, false, "h H", 35},         // KEY_H
    {"quit", true, false, "Escape", 1},      // KEY_ESC
    {"mute", true, false, "n N", 0},
};
inline constexpr int kActionCount = sizeof kActions / sizeof kActions[0];
inline constexpr int kWorldActionCount = 18;
static_assert(static_cast<int>(Action::mute) + 1 == kActionCount, "an action without its row");
static_assert(kActions[kWorldActionCount - 1].world && !kActions[kWorldActionCount].world, "the world's actions first");

inline constexpr const ActionRow& action_row(Action a) { return kActions[static_cast<int>(a)]; }
inline constexpr const char* action_name(Action a) { return action_row(a).name; }
inline constexpr bool acts_on_press(Action a) { return action_row(a).on_press; }
inline constexpr bool is_world_action(Action a) { return static_cast<int>(a) < kWorldActionCount; }

inline bool parse_action(std::string_view s, Action& out) {
    for (int i = 0; i < kActionCount; ++i)
        if (s == kActions[i].name) {
            out = static_cast<Action>(i);
            return true;
        }
    return false;
}

// f(word) for each of action i's key words (ActionRow::keys); true if f said true for one.
template <class F>
bool any_key(int i, F&& f) {
    std::string_view k = kActions[i].keys;
    while (!k.empty()) {
        const std::size_t end = k.find(' ');
        if (f(k.substr(0, end))) return true;
        k = end == std::string_view::npos ? std::string_view{} : k.substr(end + 1);
    }
    return false;
}

// An action pressed or released, as the input backends (platform/linux) deliver them.
struct InputEvent {
    Action control = Action::thrust;
    bool pressed = false;
};

}  // namespace noneuclid::world
