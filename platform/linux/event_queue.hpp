// A fixed-size queue of input events, oldest first: what the GPIO backends (ButtonTracker)
// and evdev hold between the kernel's events and the frame loop's read(). No allocation.
#pragma once

#include "world/action.hpp"

namespace noneuclid::platform {

template <int N>
class EventQueue {
public:
    static constexpr int kCapacity = N;
    int size() const { return size_; }
    int space() const { return N - size_; }
    void clear() { head_ = size_ = 0; }
    // Dropped when full; callers read from the kernel only what fits (space()).
    void push(world::InputEvent e) {
        if (size_ == N) return;
        queue_[(head_ + size_) % N] = e;
        ++size_;
    }
    // Moves up to max events to out, oldest first; returns how many.
    int pop(world::InputEvent* out, int max) {
        int n = 0;
        while (n < max && size_ > 0) {
            out[n++] = queue_[head_];
            head_ = (head_ + 1) % N;
            --size_;
        }
        return n;
    }

private:
    world::InputEvent queue_[N];
    int head_ = 0, size_ = 0;
};

}  // namespace noneuclid::platform
