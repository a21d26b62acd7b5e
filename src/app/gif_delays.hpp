// The delays of render --gif's frames: each frame shown for as long as the world time it
// stands for, in the whole centiseconds a GIF frame's 16-bit delay holds, rounded so that their
// sum follows the world time (frame n ends at round(n · per-frame time), within a centisecond),
// and at least 2 (what GIF viewers take as the shortest). The sum is kept in 64 bits: a run of
// 10⁸ frames of 655.35 s each does not overflow it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace noneuclid::app {

// The longest delay a GIF frame can have: 65535 centiseconds.
inline constexpr double kGifMaxFrameSeconds = 655.35;

class GifDelays {
public:
    // `seconds`: the world time one GIF frame stands for, at most kGifMaxFrameSeconds (render
    // refuses more before the run).
    explicit GifDelays(double seconds) : centiseconds_(seconds * 100) {}
    // The next frame's delay, in centiseconds: 2 to 65535.
    int next() {
        ++frames_;
        const int64_t due = std::llround(static_cast<double>(frames_) * centiseconds_);
        const int64_t delay = std::clamp<int64_t>(due - given_, 2, 65535);
        given_ += delay;
        return static_cast<int>(delay);
    }
    int64_t total() const { return given_; }

private:
    double centiseconds_;
    int64_t frames_ = 0, given_ = 0;
};

}  // namespace noneuclid::app
