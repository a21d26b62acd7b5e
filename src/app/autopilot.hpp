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
// In a game it plays instead of turning on a timer: it turns toward the nearest asteroid,
// holds fire while that one is within a few degrees of the nose and in range, and holds fire
// on the "press fire" screen to start the next game. Outside a game it measures: it turns the
// live instrument on (a triangle, world/instruments.hpp) and drops a mark where the ship is
// every few seconds, so the triangle's angles and area are read while K sweeps; where there is
// no instrument (the 3D world) it only flies its tour: cruising, turning, K sweeping.
#pragma once

#include <cmath>

#include "world/action.hpp"

namespace noneuclid::app {

using world::Action;
using world::InputEvent;

struct AttractOptions {
    double idle_seconds = 120;  // 0: never
    double sweep_seconds = 40;  // K from -1 to +1
    double cruise_speed = 0.25; // world units per second
    double mark_seconds = 5;    // outside a game: a mark of the live triangle this often (after each turn)
};

// What the autopilot sees of the world each frame.
struct PilotView {
    double K = 0;
    double ship_speed = 1e9;  // the controlled body's (1e9: none, never thrust)
    bool game = false;        // the scene has a game: play it
    bool ready = false;       // its "press fire" screen
    bool target = false;      // an asteroid to aim at (and a ship to aim with)
    double aim = 0;           // its direction from the ship's nose, radians counter-clockwise
    double distance = 0;      // and its distance
    bool measuring = false;   // the live instrument is on
    bool instrument = true;   // there is one to turn on (not in the 3D world: there it only flies)
    double range = 0;         // how far a bullet flies
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
        last_input_ = t, engage_ = false;
        if (!active_) return 0;
        active_ = false;
        int n = release_all(out);
        out[n++] = {Action::reset, true};
        out[n++] = {Action::reset, false};
        return n;
    }

    // The game just ended: attract mode begins now (if it is on at all), not after the idle
    // time. Takes effect at the next frame().
    void engage() {
        if (o_.idle_seconds > 0) engage_ = true;
    }

    // Once per frame, before the step: the controls to press or release now (at most 8).
    // `t` is the world time, `v` what the autopilot sees.
    int frame(double t, const PilotView& v, InputEvent* out) {
        int n = 0;
        const double K = v.K;
        if (!active_) {
            if (!engage_ && (o_.idle_seconds <= 0 || t - last_input_ < o_.idle_seconds)) return 0;
            active_ = true, engage_ = false, since_ = t, accumulator_ = 0, next_mark_ = o_.mark_seconds;
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
        n += set(dir_ > 0 ? Action::curvature_up : Action::curvature_down, hold_k, out + n);
        n += set(dir_ > 0 ? Action::curvature_down : Action::curvature_up, false, out + n);
        if (v.game) {
            const bool aimed = v.target && std::fabs(v.aim) < 0.08 && v.distance < v.range;
            n += set(Action::left, v.target && v.aim > 0.05, out + n);
            n += set(Action::right, v.target && v.aim < -0.05, out + n);
            n += set(Action::fire, aimed || (v.ready && !held_[slot(Action::fire)]), out + n);
        } else {
            n += set(Action::left, std::fmod(tt, 5.0) >= 4.4, out + n);
            if (v.ship_speed < 1e9 && v.instrument) {  // a ship to drop the marks
                if (!v.measuring) out[n++] = {Action::instrument, true}, out[n++] = {Action::instrument, false};
                const bool mark = tt >= next_mark_;
                if (mark) next_mark_ += o_.mark_seconds;
                n += set(Action::fire, mark, out + n);
            }
        }
        n += set(Action::thrust, v.ship_speed < o_.cruise_speed, out + n);
        return n;
    }

private:
    static constexpr Action kHeld[] = {Action::thrust,         Action::left,  Action::right,
                                        Action::curvature_up,   Action::fire,
                                        Action::curvature_down};
    static constexpr int kHeldCount = 6;
    static int slot(Action c) {
        for (int i = 0; i < kHeldCount; ++i)
            if (kHeld[i] == c) return i;
        return 0;
    }
    int set(Action c, bool down, InputEvent* out) {
        bool& h = held_[slot(c)];
        if (h == down) return 0;
        h = down;
        *out = {c, down};
        return 1;
    }
    int release_all(InputEvent* out) {
        int n = 0;
        for (Action c : kHeld) n += set(c, false, out + n);
        return n;
    }

    AttractOptions o_;
    double rate_ = 0.5;
    bool active_ = false, engage_ = false;
    double last_input_ = 0, since_ = 0, accumulator_ = 0, next_mark_ = o_.mark_seconds;
    int dir_ = 1;
    bool held_[kHeldCount] = {};
};

}  // namespace noneuclid::app
