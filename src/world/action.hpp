// The world's actions: what the buttons and keys ask of any world (the constant-K world,
// world/world.hpp, and the uneven one, uneven/world.hpp, take the same), their names and whether
// each acts on its press or while held. world/controls.hpp adds the display's own commands.
#pragma once

#include <cstdint>
#include <string>

namespace noneuclid::world {

// What the buttons and keys ask of the world. Held actions (thrust, the turns, curvature up and
// down, fire) act while held; the others act once, on the press: the next preset, reset, and K
// set to -1, 0 or +1 (the desktop's keys 1, 2, 3). Fire shoots on its press and again each
// cooldown while held (world/game.hpp); in a scene without a game it does nothing. Instrument
// cycles the live instrument (world/instruments.hpp: triangle, circle, parallels, polygon, off);
// while one is on, fire drops a mark where the ship is instead of shooting. Strength up and down
// (held) turn an uneven world's bumps (src/uneven); a world of constant K has none.
enum class Action : uint8_t {
    thrust, turn_left, turn_right, curvature_up, curvature_down, next_preset, reset, hyperbolic, flat, spherical,
    fire, instrument, strength_up, strength_down
};
inline constexpr int kActionCount = 14;
inline const char* action_name(Action a) {
    static const char* const names[] = {"thrust", "left",       "right", "curvature_up", "curvature_down", "preset",
                                        "reset",  "hyperbolic", "flat",  "spherical",    "fire",
                                        "instrument", "strength_up", "strength_down"};
    static_assert(sizeof names / sizeof names[0] == kActionCount, "an action without its name");
    return names[static_cast<int>(a)];
}
// Whether the action acts once on its press (rather than while held).
inline bool acts_on_press(Action a) {
    return (a >= Action::next_preset && a <= Action::spherical) || a == Action::instrument;
}
inline bool parse_action(const std::string& s, Action& out) {
    for (int i = 0; i < kActionCount; ++i)
        if (s == action_name(static_cast<Action>(i))) {
            out = static_cast<Action>(i);
            return true;
        }
    return false;
}

}  // namespace noneuclid::world
