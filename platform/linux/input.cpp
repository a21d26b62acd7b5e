// The board's buttons opened as input sources, and the poll loop behind `noneuclid buttons`.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "linux/input.hpp"
#include "linux/input_set.hpp"

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

int print_input_events(InputSet& inputs, long max_events, double timeout_seconds, std::FILE* out) {
    if (max_events < 0) return fail("the number of events to wait for must be 0 (no limit) or more");
    if (!(timeout_seconds >= 0) || timeout_seconds > 1e9)
        return fail("the timeout must be 0 (none) or a number of seconds up to 10^9");

    constexpr int kEvents = 32;
    world::InputEvent events[kEvents];
    const int64_t start = monotonic_ns();
    const int64_t end = timeout_seconds > 0 ? start + static_cast<int64_t>(std::ceil(timeout_seconds * 1e9)) : -1;
    long printed = 0;
    for (;;) {
        const int n = inputs.read(events, kEvents, monotonic_ns());
        for (int i = 0; i < n; ++i) {
            std::fprintf(out, "%s %s\n", events[i].pressed ? "press" : "release",
                         world::action_name(events[i].control));
            if (std::fflush(out) != 0) return fail("cannot write the events", std::strerror(errno));
            if (max_events > 0 && ++printed >= max_events) return 0;
        }
        if (n == kEvents) continue;  // more may be queued
        if (end >= 0 && monotonic_ns() >= end) return 0;
        std::string error;
        if (inputs.wait(end, error) != InputSet::Woke::ready) return fail(error.c_str());
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
    std::vector<InputSource*> sources;
    for (const auto& in : inputs) sources.push_back(in.get());
    InputSet set(std::move(sources));
    return print_input_events(set, events, timeout, stdout);
}

}  // namespace noneuclid::platform
