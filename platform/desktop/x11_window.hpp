// The desktop window: plain Xlib, MIT-SHM when the server offers it (XPutImage otherwise), a
// render::Canvas whose memory is the XImage's buffer, and `noneuclid run`'s loop: fixed
// timestep (1/60 s a frame, whatever the wall clock says), keys to actions, frames paced with
// clock_nanosleep.
#pragma once

#include <string>

#include "geometry/geometry.hpp"
#include "world/scene.hpp"

namespace noneuclid::platform {

struct RunOptions {
    int width = 800, height = 480;  // the window's initial size
    long frames = 0;                // 0: until the window is closed (Esc, the window manager)
    double fps = 60;                // frame rate cap (pacing only: world time is 1/60 s a frame)
    bool antialias = false;
    bool hud = true;                // H toggles it
    std::string engine = "fixed";   // fixed, double, float, paper
    geo::Projection projection = geo::Projection::azimuthal_equidistant;
    std::string screenshot;         // at exit: the window read back from the X server, as PNG
    bool stats = false;             // at exit: frames, wall time and CPU seconds on stderr
};

// The HUD's controls line in the window.
inline constexpr const char* kDesktopControls = "arrows/WASD  +/- K  1 2 3 K=-1,0,1  P projection  H HUD  R reset  Esc";

// Opens the window on $DISPLAY and runs `scene` until Esc, the window manager's close, or
// options.frames frames. Returns the exit status (errors: one sentence on stderr, non-zero).
int run_x11(const world::Scene& scene, const RunOptions& options);

}  // namespace noneuclid::platform
