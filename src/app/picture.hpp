// A still picture of a world (`noneuclid render`, the demo, the golden-image tests): the scene
// run for o.frames steps of o.dt with the scripted events, then its last frame drawn, or with a
// time-lapse (o.timelapse = EVERY) every EVERY-th frame's bodies laid over the earlier ones on
// the last frame's backdrop and grid, as in the paper's figures 14-17; the HUD over it if on.
#pragma once

#include "app/display.hpp"
#include "app/options.hpp"
#include "app/script.hpp"
#include "render/font.hpp"
#include "world/scene.hpp"

namespace noneuclid::app {

struct PictureResult {
    double K = 0;          // at the last frame
    long frame = 0;        // steps taken
    bool stopped = false;  // a stop signal came (platform::catch_stop_signals): nothing drawn
};

// Draws into `out` (allocated here: o.width x o.height in o.format). `script` may be null.
PictureResult render_picture(const Options& o, const world::Scene& scene, const Script* script,
                             const render::Font& font, Picture& out);

}  // namespace noneuclid::app
