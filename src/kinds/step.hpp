// The world's step, one for every kind and every driver: each step is kStepSeconds of world
// time (the session's default dt, render's and dump's, the C interface's and the firmware's),
// and StepClock turns elapsed seconds (a caller's uneven frame times) into whole steps, carrying
// the remainder to the next call, so that the world always moves in equal fixed steps and a
// recording replays it exactly.
#pragma once

#include <cmath>

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

}  // namespace noneuclid::kinds
