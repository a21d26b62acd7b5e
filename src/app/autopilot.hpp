// Attract mode: when nobody has pressed a button for a while, an autopilot flies the ship and
// sweeps K slowly from -1 to +1 and back (like the paper's figure 17), until a button is
// pressed. It acts only through the same controls the buttons send (press/release of thrust,
// left, curvature_up, ...), so what it does is recorded and replayed like any visitor's
// presses, and it reads no clock: the frame loop tells it the world time.
//
// The sweep: the world changes K at the scene's curvature_rate while curvature up/down is
// held; the autopilot holds it for a fraction of the frames (a Bresenham accumulator), so K
// moves at 2 / sweep_seconds per second on average, turning at the ends. The flight: a gentle
// left turn held for 0.6 s every 5 s, and thrust whenever the ship is slower than
// `cruise_speed` (the world has no drag, so thrusting on a timer would speed up for ever).
#pragma once

#include <cmath>

#include "world/controls.hpp"

namespace noneuclid::app {

using world::Control;
using world::InputEvent;

struct AttractOptions {
    double idle_seconds = 120;  // 0: never
    double sweep_seconds = 40;  // K from -1 to +1
    double cruise_speed = 0.25; // world units per second
};

class Autopilot {
public:
    Autopilot() = default;
    Autopilot(AttractOptions o, double curvature_rate) : o_(o), rate_(curvature_rate) {}

    bool active() const { return active_; }

    // A real button or key was pressed or released at world time `t`: leave attract mode.
    // Writes the controls to release (what the autopilot held) plus a reset tap into `out`
    // (at most 8) and returns how many; the caller applies them before the visitor's event.
    int interrupt(double t, InputEvent* out) {
        last_input_ = t;
        if (!active_) return 0;
        active_ = false;
        int n = release_all(out);
        out[n++] = {Control::reset, true};
        out[n++] = {Control::reset, false};
        return n;
    }

    // Once per frame, before the step: the controls to press or release now (at most 8).
    // `t` is the world time, `K` the current curvature, `ship_speed` the controlled body's.
    int frame(double t, double K, double ship_speed, InputEvent* out) {
        int n = 0;
        if (!active_) {
            if (o_.idle_seconds <= 0 || t - last_input_ < o_.idle_seconds) return 0;
            active_ = true, since_ = t, accumulator_ = 0;
            dir_ = K >= 1 - 1e-6 ? -1 : 1;
        }
        const double tt = t - since_;
        // Sweep direction flips at the ends.
        if (dir_ > 0 && K >= 1 - 1e-6) dir_ = -1;
        else if (dir_ < 0 && K <= -1 + 1e-6) dir_ = 1;
        // Duty: the fraction of frames with curvature held, for 2 / sweep_seconds per second.
        const double duty = rate_ > 0 ? std::fmin(1.0, 2.0 / (o_.sweep_seconds * rate_)) : 0;
        accumulator_ += duty;
        const bool hold_k = accumulator_ >= 1;
        if (hold_k) accumulator_ -= 1;
        n += set(dir_ > 0 ? Control::curvature_up : Control::curvature_down, hold_k, out + n);
        n += set(dir_ > 0 ? Control::curvature_down : Control::curvature_up, false, out + n);
        n += set(Control::left, std::fmod(tt, 5.0) >= 4.4, out + n);
        n += set(Control::thrust, ship_speed < o_.cruise_speed, out + n);
        return n;
    }

private:
    static constexpr Control kHeld[] = {Control::thrust, Control::left, Control::curvature_up, Control::curvature_down};
    static int slot(Control c) {
        for (int i = 0; i < 4; ++i)
            if (kHeld[i] == c) return i;
        return 0;
    }
    int set(Control c, bool down, InputEvent* out) {
        bool& h = held_[slot(c)];
        if (h == down) return 0;
        h = down;
        *out = {c, down};
        return 1;
    }
    int release_all(InputEvent* out) {
        int n = 0;
        for (Control c : kHeld) n += set(c, false, out + n);
        return n;
    }

    AttractOptions o_;
    double rate_ = 0.5;
    bool active_ = false;
    double last_input_ = 0, since_ = 0, accumulator_ = 0;
    int dir_ = 1;
    bool held_[4] = {};
};

}  // namespace noneuclid::app
