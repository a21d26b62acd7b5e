// print_input_events: the poll loop behind `noneuclid buttons`.
#include <poll.h>
#include <time.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "linux/input.hpp"

namespace noneuclid::platform {

int64_t monotonic_ns() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

namespace {

int fail(const char* sentence, const char* detail = nullptr) {
    if (detail)
        std::fprintf(stderr, "noneuclid: %s: %s.\n", sentence, detail);
    else
        std::fprintf(stderr, "noneuclid: %s.\n", sentence);
    return 1;
}

}  // namespace

int print_input_events(InputSource& src, long max_events, double timeout_seconds, std::FILE* out) {
    if (max_events < 0) return fail("the number of events to wait for must be 0 (no limit) or more");
    if (!(timeout_seconds >= 0) || timeout_seconds > 1e9)
        return fail("the timeout must be 0 (none) or a number of seconds up to 10^9");

    constexpr int kFds = 16, kEvents = 32;
    pollfd pfds[kFds];
    world::InputEvent events[kEvents];
    const int64_t start = monotonic_ns();
    const int64_t end = timeout_seconds > 0 ? start + static_cast<int64_t>(std::ceil(timeout_seconds * 1e9)) : -1;
    long printed = 0;
    int errors_in_a_row = 0;

    for (;;) {
        int64_t now = monotonic_ns();
        const int n = src.read(events, kEvents, now);
        for (int i = 0; i < n; ++i) {
            std::fprintf(out, "%s %s\n", events[i].pressed ? "press" : "release",
                         world::control_name(events[i].control));
            if (std::fflush(out) != 0) return fail("cannot write the events", std::strerror(errno));
            if (max_events > 0 && ++printed >= max_events) return 0;
        }
        if (n == kEvents) continue;  // more may be queued

        now = monotonic_ns();
        if (end >= 0 && now >= end) return 0;
        int64_t wake = end;
        const int64_t deadline = src.deadline_ns();
        if (deadline >= 0 && (wake < 0 || deadline < wake)) wake = deadline;
        int timeout_ms = -1;
        if (wake >= 0) {
            const int64_t ms = wake > now ? (wake - now + 999999) / 1000000 : 0;
            timeout_ms = ms > INT_MAX ? INT_MAX : static_cast<int>(ms);
        }

        const int nfds = src.fds(pfds, kFds);
        int live = 0;
        for (int i = 0; i < nfds; ++i) live += pfds[i].fd >= 0;
        if (live == 0 && wake < 0)
            return fail("every input device has gone away (unplugged?): reconnect it and start again");

        const int r = poll(pfds, static_cast<nfds_t>(nfds), timeout_ms);
        if (r < 0) {
            if (errno == EINTR) continue;
            return fail("polling the input devices failed", std::strerror(errno));
        }
        // An fd in error: read() gets the chance to drop it (evdev does when a device is
        // unplugged); one still failing on the next round ends the loop instead of spinning.
        bool error = false;
        for (int i = 0; i < nfds; ++i)
            error |= pfds[i].fd >= 0 && (pfds[i].revents & (POLLERR | POLLNVAL)) && !(pfds[i].revents & POLLIN);
        if (error && errors_in_a_row++ > 0)
            return fail("an input device keeps reporting errors (unplugged, or its GPIO chip removed?): "
                        "check the connection and start again");
        if (!error) errors_in_a_row = 0;
    }
}

}  // namespace noneuclid::platform
