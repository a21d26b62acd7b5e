// A kiosk's input sources (GPIO lines, evdev keys: linux/input.hpp) read and polled as one, for
// both their users: the kiosk's display, which reads them until the frame is due, and
// `noneuclid buttons`, which prints them. read() takes what every source has now; wait() sleeps
// in one poll() over every source's fds until one has input, a source's own deadline (software
// debounce) or the caller's, whichever comes first. Allocates nothing after construction.
#pragma once

#include <poll.h>

#include <cstdint>
#include <string>
#include <vector>

#include "linux/input.hpp"

namespace noneuclid::platform {

class InputSet {
public:
    // The sources are not owned and must outlive the set.
    explicit InputSet(std::vector<InputSource*> sources) : sources_(std::move(sources)) {}

    bool empty() const { return sources_.empty(); }
    // Reads whatever every source has pending, oldest first within each, without blocking:
    // at most `max` events into `out`; returns how many. `now_ns` is CLOCK_MONOTONIC.
    int read(world::InputEvent* out, int max, int64_t now_ns);

    enum class Woke {
        ready,    // input may be pending, or a deadline came: read again
        errors,   // a device reported errors in two waits in a row (unplugged?): `error` says so
        gone,     // every device has gone away and nothing is due: `error` says so
        failed,   // poll() itself failed: `error` says so
    };
    // Sleeps until a source has input, a source's deadline, or `until_ns` (-1: none), whichever
    // comes first; a stop signal ends it early (ready). A device in error gets one more round
    // for read() to drop it (evdev does when a device is unplugged).
    Woke wait(int64_t until_ns, std::string& error);

private:
    static constexpr int kMaxFds = 32;
    std::vector<InputSource*> sources_;
    pollfd fds_[kMaxFds] = {};
    int errors_in_a_row_ = 0;
};

}  // namespace noneuclid::platform
