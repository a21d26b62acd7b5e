// What the two libgpiod backends (gpio_v1.cpp, gpio_v2.cpp) share: checking the configuration,
// finding the chip among config.chips, the error sentences, and the button state machine that
// turns kernel edges into press/release events (with the optional software debounce) through a
// fixed queue. Internal to platform/linux; not part of the input.hpp contract.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "linux/event_queue.hpp"
#include "linux/input.hpp"

namespace noneuclid::platform::gpio_detail {

// One sentence if the configuration cannot work whatever the hardware (no buttons, no chip
// named, a line given twice, an absurd debounce), else empty.
std::string check_config(const GpioConfig& config);

// "GPIO line 17 (thrust, header pin 11)".
std::string describe_line(const GpioButton& button);

// The /dev/gpiochipN devices present, in numeric order (dev_dir is for tests).
std::vector<std::string> list_chips(const std::string& dev_dir = "/dev");

// What a backend reports about one chip device: 0 and its label and line count, or an errno.
struct ChipInfo {
    std::string label;
    unsigned num_lines = 0;
};
using ChipProbe = int (*)(const std::string& path, ChipInfo& info);

// The chip to use: the first entry of config.chips that names an existing chip, a label
// (compared with every /dev/gpiochipN's label) or a path. Returns false with one sentence
// otherwise (no such label: what was tried and what exists; no permission; not a chip).
bool find_chip(const GpioConfig& config, ChipProbe probe, std::string& path, ChipInfo& info,
               std::string& error, const std::string& dev_dir = "/dev");

// A sentence for a failed line request (errno `err`; consumer from the line info, may be empty).
std::string request_error(const GpioButton& button, const std::string& chip, int err,
                          const std::string& consumer);
// A sentence for a line offset beyond the chip.
std::string line_range_error(const GpioButton& button, const std::string& chip, unsigned num_lines);
// The permission sentence for a device.
std::string permission_error(const std::string& what);

// Buttons' reported state, software debounce and a fixed event queue. Sized at open; the
// per-read functions allocate nothing.
//
// Debounce (debounce_ns > 0) acts on the leading edge: the first edge that changes a button's
// state is reported at once (no added latency for a press), then the button is deaf for
// debounce_ns; when that window closes its level is read again and any difference reported
// (and a new window opened). A bouncing press gives one press; a press shorter than the window
// still gives its release when the window closes.
class ButtonTracker {
public:
    void init(const GpioConfig& config, int64_t debounce_ns);
    // The level read at open (true = pressed); queued as a press for the first read().
    void set_initial(int index, bool pressed);
    // An edge from the kernel: `pressed` is the logical level it reports.
    void edge(int index, bool pressed, int64_t now_ns);
    // Closes the debounce windows that ended by now_ns; level(index) reads a button's level
    // (true = pressed, false = released; a read error counts as "unchanged").
    template <class LevelFn>
    void expire(int64_t now_ns, LevelFn&& level) {
        for (int i = 0; i < count_; ++i) {
            if (until_[i] < 0 || now_ns < until_[i]) continue;
            until_[i] = -1;
            int l = level(i);
            if (l < 0) continue;
            if ((l != 0) != reported_[i]) change(i, l != 0, now_ns);
        }
    }
    // Room left in the queue (read at most this many kernel events).
    int space() const { return queue_.space(); }
    // Moves up to max queued events to out, oldest first.
    int pop(world::InputEvent* out, int max) { return queue_.pop(out, max); }
    // The earliest open debounce window's end, or -1.
    int64_t deadline() const;
    int count() const { return count_; }

    static constexpr int kQueue = 64;

private:
    void push(int index, bool pressed);
    void change(int index, bool pressed, int64_t now_ns);

    int count_ = 0;
    int64_t debounce_ns_ = 0;
    std::vector<world::Action> control_;
    std::vector<bool> reported_;
    std::vector<int64_t> until_;  // end of the debounce window, -1: none
    EventQueue<kQueue> queue_;
};

}  // namespace noneuclid::platform::gpio_detail
