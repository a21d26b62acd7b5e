// `noneuclid run --display fbdev`: the kiosk's frame loop on the Linux framebuffer. Input
// sources (GPIO buttons, evdev keys) are polled with the next frame's deadline as the timeout,
// so the loop sleeps until a button or the frame is due; world time is 1/60 s per frame
// whatever the clock says (render::Session), so a recording replays exactly.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/geometry.hpp"
#include "linux/input.hpp"
#include "world/attract.hpp"
#include "world/scene.hpp"

namespace noneuclid::platform {

struct KioskOptions {
    std::string device = "/dev/fb0";
    long frames = 0;  // 0: until a signal (or a quit key)
    double fps = 60;  // frame-rate cap; pacing only
    bool antialias = false;
    bool hud = true;
    std::string engine = "fixed";
    geo::Projection projection = geo::Projection::azimuthal_equidistant;
    world::AttractOptions attract;
    int threads = 1;     // drawing threads (render::WorkerPool, started once); 1: none started
    std::string record;  // actions file of every world action as it took effect ("" none)
    bool stats = false;
};

// Opens the framebuffer, owns the console, runs. Returns the exit status; errors are one
// sentence on stderr.
int run_fbdev(const world::Scene& scene, const KioskOptions& options,
              std::vector<std::unique_ptr<InputSource>>& inputs);

}  // namespace noneuclid::platform
