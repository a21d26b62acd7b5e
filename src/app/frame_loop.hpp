// The one frame loop, for every display: input until the frame is due, one frame of world time
// (Session::advance: one step, then the scripted events due), the picture, present; paced to a frame-rate cap (world time is the session's dt a
// frame whatever the clock says, so a recording replays exactly); the frame rate for the HUD;
// the window's size in the recording when it changes; at the end the screenshot and --stats.
// tick() is one frame, so a host that owns the loop (a browser's animation frames) can drive
// it; run() loops until done.
#pragma once

#include <cstdint>
#include <string>

#include "app/display.hpp"
#include "app/recorder.hpp"
#include "app/script.hpp"
#include "app/session.hpp"
#include "app/sound.hpp"

namespace noneuclid::app {

struct LoopOptions {
    long frames = 0;         // 0: until the display closes or a quit control comes
    double fps = 60;         // the cap, for a display someone watches
    bool stats = false;      // at the end: frames, wall time, CPU (stderr)
    std::string screenshot;  // at the end: what the display shows, as PNG ("" none)
};

// --screenshot: what `display` shows, read back and written to `path` as PNG; says "wrote PATH
// (WxH, WHERE)" or why not on stderr. 0, or 1 if it was not written.
int write_screenshot(Display& display, const std::string& path, const std::string& where);

class FrameLoop final : InputSink {
public:
    // `script` (events to play at their time) and `recorder` may be null; all must outlive it.
    FrameLoop(Display& display, Session& session, const Script* script, Recorder* recorder, const LoopOptions& o);

    // One frame: false when the loop is done (frames reached, closing, quit, an error).
    bool tick();
    // The screenshot, the statistics and the recording's end; returns the exit status.
    int finish();
    int run() {
        while (tick()) {
        }
        return finish();
    }
    long frames() const { return frames_; }
    // Where each frame's sound goes (app/sound.hpp; null: none). It must outlive the loop.
    void set_sound(SoundOut* sound) { sound_ = sound; }

private:
    void input(world::InputEvent e) override { session_.queue(e); }

    Display& display_;
    Session& session_;
    Recorder* recorder_;
    SoundOut* sound_ = nullptr;
    LoopOptions o_;
    ScriptPlayer player_;
    int64_t period_, start_, next_, fps_since_;
    long frames_ = 0, fps_frames_ = 0;
    int width_ = 0, height_ = 0;  // the canvas's size as last recorded
    bool failed_ = false;
};

}  // namespace noneuclid::app
