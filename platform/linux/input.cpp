// The board's buttons opened as input sources, and the poll loop behind `noneuclid buttons`.
#include <poll.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "linux/input.hpp"

namespace noneuclid::platform {

bool open_board_inputs(const files::Board& b, const std::string& mode, std::vector<std::unique_ptr<InputSource>>& out,
                       std::string& error) {
    if (mode == "none") return true;
    const bool want_gpio = mode == "gpio" || (mode == "auto" && b.has_gpio());
    const bool want_keys = mode == "evdev" || (mode == "auto" && b.has_keys());
    if (mode == "gpio" && !b.has_gpio()) {
        error = "the board " + b.name + " (" + b.file +
                ") wires no GPIO buttons: add 'gpio = N' to its [[button]] tables, or use --input evdev.";
        return false;
    }
    if (mode == "evdev" && !b.has_keys()) {
        error = "the board " + b.name + " (" + b.file +
                ") names no key codes: add 'key = N' to its [[button]] tables, or use --input gpio.";
        return false;
    }
    if (want_gpio) {
        GpioConfig g;
        g.chips = b.chips;
        g.debounce_ms = static_cast<unsigned>(b.debounce_ms);
        for (const auto& bb : b.buttons)
            if (bb.gpio >= 0) g.buttons.push_back({bb.control, static_cast<unsigned>(bb.gpio), bb.pin});
        auto src = open_gpio(g, error);
        if (!src) {
            error += ".";
            return false;
        }
        std::fprintf(stderr, "noneuclid: %s\n", src->describe().c_str());
        out.push_back(std::move(src));
    }
    if (want_keys) {
        EvdevConfig e;
        e.device = b.evdev_device;
        e.grab = b.grab;
        for (const auto& bb : b.buttons)
            if (bb.key >= 0) e.keys.push_back({bb.control, static_cast<unsigned>(bb.key)});
        std::string why;
        auto src = open_evdev(e, why);
        if (!src) {
            if (mode == "evdev" || !want_gpio) {
                error = why + ".";
                return false;
            }
            std::fprintf(stderr, "noneuclid: no keys (%s); the GPIO buttons are enough.\n", why.c_str());
        } else {
            std::fprintf(stderr, "noneuclid: %s\n", src->describe().c_str());
            out.push_back(std::move(src));
        }
    }
    return true;
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

int print_buttons(const files::Board& board, const std::string& input, long events, double timeout) {
    std::vector<std::unique_ptr<InputSource>> inputs;
    std::string error;
    if (!open_board_inputs(board, input, inputs, error)) {
        std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
        return 2;
    }
    if (inputs.empty()) {
        std::fprintf(stderr, "noneuclid: the board has no buttons to listen to: give it [[button]] tables.\n");
        return 2;
    }
    if (inputs.size() > 1)
        std::fprintf(stderr, "noneuclid: listening to the first input only; choose with --input gpio or evdev.\n");
    return print_input_events(*inputs.front(), events, timeout, stdout);
}

}  // namespace noneuclid::platform
