// The world's step, one for every kind and every driver: each step is kStepSeconds of world
// time (the session's default dt, render's and dump's, the C interface's and the firmware's),
// and StepClock turns elapsed seconds (a caller's uneven frame times) into whole steps, carrying
// the remainder to the next call, so that the world always moves in equal fixed steps and a
// recording replays it exactly. DueEvents and start_run/advance_run are the one order in which
// every driver (the session's frame loop, render and dump, the C interface, the firmware) plays
// a recording's events and steps the world.
#pragma once

#include <cmath>
#include <cstddef>

namespace noneuclid::kinds {

inline constexpr double kStepSeconds = 1.0 / 60;

struct StepClock {
    double dt = kStepSeconds;
    double owed = 0;  // seconds given and not yet stepped, below dt

    // The whole steps `seconds` more make (seconds >= 0, finite), the remainder kept. (The
    // rounding allowance: 60 calls of 1/60 s make 60 steps, not 59.)
    long steps_for(double seconds) {
        owed += seconds;
        const double n = std::floor(owed / dt + 1e-9);
        owed = std::fmax(owed - n * dt, 0.0);
        return static_cast<long>(n);
    }
};

// The events of a recording due by a world time, in order (app/script.hpp's ScriptEvent, the
// firmware's RecordedEvent: anything with a `time`, sorted by it): each event once, when the
// world's time reaches its own, within 1e-9 s (the times are printed to 9 decimals). The events
// are the caller's and must outlive it; nothing is allocated.
template <class Event>
class DueEvents {
public:
    DueEvents() = default;
    DueEvents(const Event* events, std::size_t count) : events_(events), count_(count) {}
    // The next event if it is due at world time `time`, else null.
    const Event* next_due(double time) {
        if (!events_ || next_ >= count_ || events_[next_].time > time + 1e-9) return nullptr;
        return &events_[next_++];
    }

private:
    const Event* events_ = nullptr;
    std::size_t count_ = 0, next_ = 0;
};

// The one order of a run: the events due at time 0 before the first frame is drawn (start_run);
// then for each next frame one step and the events due at the new time, and the frame drawn
// (advance_run). `step` is the world's step with what follows it at once (the game's events, the
// sounds' cues), `due` plays the events due at the world's time now. An event at time t thus
// acts before the first step that starts at or after t, in every driver alike.
template <class Due>
void start_run(Due&& due) {
    due();
}
template <class Step, class Due>
void advance_run(Step&& step, Due&& due) {
    step();
    due();
}

}  // namespace noneuclid::kinds
