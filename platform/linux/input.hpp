// Kiosk input on Linux: GPIO buttons through libgpiod (v1 or v2 API, chosen at configure
// time) and evdev key devices. Both are event-driven: the frame loop polls their fds (with its
// frame deadline, and deadline_ns() for software debounce, as the timeout) and then calls
// read(), which never blocks.
#pragma once

#include <poll.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/platform.hpp"  // monotonic_ns: the clock read() and deadline_ns() speak
#include "files/board.hpp"
#include "world/action.hpp"

namespace noneuclid::platform {

// One button wired from a GPIO line to ground (pull-up, active-low).
struct GpioButton {
    world::Action control = world::Action::thrust;
    unsigned line = 0;    // line offset on the chip (= BCM number on a Raspberry Pi)
    int header_pin = 0;   // physical pin on the 40-pin header, for messages (0: unknown)
};

struct GpioConfig {
    // Chips to try, in order: a label (pinctrl-bcm2711, gpio-sim's bank label, ...) or a path
    // (/dev/gpiochip0). The first that exists is used.
    std::vector<std::string> chips;
    std::vector<GpioButton> buttons;
    unsigned debounce_ms = 10;  // kernel debounce (v2) or software debounce (v1); 0: none
    std::string consumer = "noneuclid";
};

// One key code (linux/input-event-codes.h, e.g. 57 = KEY_SPACE) mapped to a control.
struct EvdevKey {
    world::Action control = world::Action::thrust;
    unsigned code = 0;
};

struct EvdevConfig {
    // A device path (/dev/input/eventN or /dev/input/by-id/...), or empty: every
    // /dev/input/event* that has EV_KEY and at least one of the wanted codes.
    std::string device;
    std::vector<EvdevKey> keys;
    bool grab = true;  // EVIOCGRAB, so the keys do not also reach the console
};

class InputSource {
public:
    virtual ~InputSource() = default;
    // One line for the start-up log, e.g. "gpio: pinctrl-bcm2711 (/dev/gpiochip0), 6 buttons,
    // libgpiod 1.6, software debounce 10 ms".
    virtual std::string describe() const = 0;
    // The fds to poll() for POLLIN; writes at most `max`, returns how many.
    virtual int fds(pollfd* out, int max) = 0;
    // Reads whatever is pending without blocking and writes at most `max` events, oldest first;
    // returns how many. `now_ns` is CLOCK_MONOTONIC. The first call also reports the levels read
    // at open (a button already held gives a press). Allocates nothing.
    virtual int read(world::InputEvent* out, int max, int64_t now_ns) = 0;
    // CLOCK_MONOTONIC ns by which read() must be called again even without fd activity
    // (software debounce settling), or -1.
    virtual int64_t deadline_ns() const { return -1; }
};

// Open the buttons / keys; on failure return null and set `error` to one sentence naming the
// thing and the fix (busy line, no permission, no such chip or line, ...).
std::unique_ptr<InputSource> open_gpio(const GpioConfig& config, std::string& error);
std::unique_ptr<InputSource> open_evdev(const EvdevConfig& config, std::string& error);

class InputSet;
// For `noneuclid buttons` (installers checking their wiring; the system test): reads every
// source of `inputs` (linux/input_set.hpp) and prints one line per event to `out`,
// "press thrust" / "release thrust", flushed at once. Returns 0 after max_events events (0: no
// limit) or after timeout_seconds (0: none); non-zero, with one sentence on stderr, if polling
// fails, a device keeps failing or every device has gone away.
int print_input_events(InputSet& inputs, long max_events, double timeout_seconds, std::FILE* out);

// Which libgpiod API this build uses ("1.6.3 (v1 API)", "2.1.3 (v2 API)") or "none".
const char* gpiod_version();

// The board's buttons as input sources: `mode` gpio, evdev, none or auto (GPIO if the board wires
// any, plus key devices if it names keys and one is present). Says what it opened, one line
// each, on stderr. False with one sentence in `error`.
bool open_board_inputs(const files::Board& board, const std::string& mode,
                       std::vector<std::unique_ptr<InputSource>>& out, std::string& error);

}  // namespace noneuclid::platform
