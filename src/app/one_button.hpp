// One-button mode (docs/accessibility.md): the whole program played with fire alone, for people
// who can press only one switch. The ship turns on its own (left held, as a scanning switch
// interface sweeps); a press of fire held past kHoldSeconds thrusts until it is let go; a
// shorter press is a tap: it fires in a scene with the game (and so starts a game on the "press
// fire" screen), and elsewhere moves K to the next preset. What it sends are the world's own
// actions, so a recording of a one-button run replays without the mode.
#pragma once

#include "world/action.hpp"

namespace noneuclid::app {

class OneButton {
public:
    static constexpr double kHoldSeconds = 0.4;

    // Fire pressed or let go at world time t: the controls to apply (at most 2) into out.
    int fire(bool pressed, double t, bool game, world::InputEvent* out) {
        if (pressed) {
            held_ = true, since_ = t;
            return 0;
        }
        if (!held_) return 0;
        held_ = false;
        if (thrusting_) {
            thrusting_ = false;
            out[0] = {world::Action::thrust, false};
            return 1;
        }
        const world::Action tap = game ? world::Action::fire : world::Action::preset;
        out[0] = {tap, true}, out[1] = {tap, false};
        return 2;
    }
    // Before a step at world time t: the turn kept held (turning: whether it is now), and thrust
    // once fire has been held long enough. At most 2 controls into out.
    int step(double t, bool turning, world::InputEvent* out) {
        int n = 0;
        if (!turning) out[n++] = {world::Action::left, true};
        if (held_ && !thrusting_ && t - since_ >= kHoldSeconds) {
            thrusting_ = true;
            out[n++] = {world::Action::thrust, true};
        }
        return n;
    }

private:
    bool held_ = false, thrusting_ = false;
    double since_ = 0;
};

}  // namespace noneuclid::app
