// A still picture of a world (`noneuclid render`, the demo, the golden-image tests): the scene
// run for o.frames steps of o.dt with the scripted events, then its last frame drawn, or with a
// time-lapse (o.timelapse = EVERY) every EVERY-th frame's bodies (and every o.timelapse_grids-th
// frame's grid, coloured by K) laid over the earlier ones on the last frame's backdrop and grid,
// as in the paper's figures 14-17; the HUD over it if on. Frames along the way can go to a
// FrameSink (the animated GIF). And the paper's figures (app/figures.hpp): panels side by side.
#pragma once

#include "app/display.hpp"
#include "app/figures.hpp"
#include "app/options.hpp"
#include "app/script.hpp"
#include "render/font.hpp"
#include "world/instruments.hpp"
#include "world/scene.hpp"

namespace noneuclid::app {

struct PictureResult {
    double K = 0;          // at the last frame
    long frame = 0;        // steps taken
    bool stopped = false;  // a stop signal came (platform::catch_stop_signals): nothing drawn
    bool refused = false;  // the FrameSink refused a frame (it says why): nothing drawn
    // The instruments that are on, read at the last frame (a worksheet's key).
    static constexpr int kMaxReadings = 4;
    int readings = 0;
    world::GaugeReading reading[kMaxReadings];
};

// Takes the pictures of a run as it goes: the picture as render_picture would draw it, had the
// run ended at world frame `frame`. False ends the run.
class FrameSink {
public:
    virtual bool frame(const render::Canvas& c, long frame) = 0;

protected:
    ~FrameSink() = default;
};

// Told how far a run has come, after each step (render's progress line on a terminal).
class Progress {
public:
    virtual void at(long frame, long frames) = 0;

protected:
    ~Progress() = default;
};

// Draws into `out` (allocated here: o.width x o.height in o.format). `script` may be null; so may
// `frames`, which otherwise gets frame 0 and every `every`-th frame after it, and `progress`.
PictureResult render_picture(const Options& o, const world::Scene& scene, const Script* script,
                             const render::Font& font, Picture& out, FrameSink* frames = nullptr, long every = 1,
                             Progress* progress = nullptr);

// Figure f: its panels side by side (each base.width x base.height, 8 px apart), each its scene
// at the panel's K (app/figures.hpp) drawn by render_picture with base's engine, format and HUD,
// and labelled with its K in the built-in font. Allocates `out`.
PictureResult render_figure(const Figure& f, const Options& base, const render::Font& font, Picture& out);

}  // namespace noneuclid::app
