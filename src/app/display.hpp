// The display contract: what the frame loop (app/frame_loop.hpp) needs of a screen, as
// raylib's platforms and LVGL's flush callback have it. A display gives a canvas to draw the
// next frame into, presents it, delivers its input (buttons, keys) until a deadline, and says
// when it is closing. The kiosk's framebuffer (platform/linux), the X11 window
// (platform/desktop) and the headless memory display (app/memory_display.hpp, written to PNG)
// implement it, and nothing else: pacing, the frame rate, recording, attract mode, threads
// and the HUD are the frame loop's and the session's, the same for all of them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "render/canvas.hpp"
#include "world/action.hpp"

namespace noneuclid::app {

// Where a display delivers its input.
class InputSink {
public:
    virtual void input(world::InputEvent e) = 0;

protected:
    ~InputSink() = default;
};

// A copy of what a display shows (for --screenshot): pixels and a canvas over them.
struct Picture {
    std::vector<uint8_t> pixels;
    render::Canvas canvas;
};

class Display {
public:
    virtual ~Display() = default;

    // The canvas to draw the next frame into. Its size may change between frames (a window
    // resized by the user); its memory stays valid until the next present() or wait().
    virtual render::Canvas canvas() = 0;
    // Shows what was drawn into canvas().
    virtual void present() = 0;
    // Delivers input to `sink` until the clock (platform::monotonic_ns) reaches deadline_ns,
    // sleeping in between; at least once, without waiting, when the deadline has passed.
    // Returns early when closing() becomes true or a stop signal comes. False on a failure it
    // has reported in one sentence on stderr.
    virtual bool wait(int64_t deadline_ns, InputSink& sink) = 0;
    // The user closed the window. (A stop signal is the frame loop's: platform::stop_signal.)
    virtual bool closing() const = 0;
    // present() waits for the screen's refresh, so the loop need not sleep.
    virtual bool paced_by_refresh() const { return false; }
    // False for a display nobody watches (headless): frames follow each other without waiting.
    virtual bool realtime() const { return true; }
    // What the display shows now, read back from where it shows it (the X server, the
    // framebuffer's memory). False with one sentence in `error` if it cannot.
    virtual bool read_back(Picture& out, std::string& error) = 0;
    // One line about the display for --stats, e.g. "MIT-SHM", or "".
    virtual std::string stats_note() const { return {}; }
    // The HUD's controls legend: "keys" (a keyboard) or "buttons" (a kiosk's).
    virtual const char* legend() const = 0;
};

}  // namespace noneuclid::app
