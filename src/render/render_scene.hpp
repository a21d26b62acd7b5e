// Running a world and drawing it: the last frame, or (time-lapse) every EVERY-th frame's bodies
// laid over the earlier ones on the last frame's backdrop and grid, as in the paper's
// figures 14-17. Shared by `noneuclid render` and the golden-image tests.
#pragma once

#include <cstdint>
#include <vector>

#include "render/draw_world.hpp"
#include "world/actions.hpp"

namespace noneuclid::render {

struct RenderJob {
    long frames = 60;
    double dt = 1.0 / 60;
    long timelapse = 0;  // 0: the last frame only
    DrawOptions draw;
};

// Runs `world` for job.frames steps with the scripted events and draws into `canvas` (whose
// memory the caller owns; the time-lapse layer is allocated here, once).
template <class W>
void render_scene(W& world, const Canvas& canvas, const RenderJob& job,
                  const std::vector<world::ActionEvent>& events = {}) {
    using T = typename W::scalar;
    DrawScratch<T> scratch;
    scratch.prepare(world);
    std::vector<uint8_t> trail;
    Canvas layer;
    DrawOptions bodies_only = job.draw;
    bodies_only.grids = false;
    if (job.timelapse > 0) {
        trail.resize(static_cast<std::size_t>(canvas.stride()) * static_cast<std::size_t>(canvas.height()));
        layer = Canvas(trail.data(), canvas.width(), canvas.height(), canvas.stride(), canvas.format());
        layer.clear(job.draw.background);
    }
    std::size_t next = world::apply_actions(world, events, 0, 0.0);
    const T dt(job.dt);
    for (long f = 0;; ++f) {
        if (job.timelapse > 0 && f % job.timelapse == 0) draw_world(layer, world, bodies_only, scratch, false);
        if (f == job.frames) break;
        world.step(dt);
        next = world::apply_actions(world, events, next, world.time);
    }
    DrawOptions last = job.draw;
    if (job.timelapse > 0) last.bodies = false;
    draw_world(canvas, world, last, scratch);
    if (job.timelapse > 0) {  // the bodies' trail over the final backdrop and grid
        const uint32_t bg = canvas.format().pack(job.draw.background);
        for (int y = 0; y < canvas.height(); ++y)
            for (int x = 0; x < canvas.width(); ++x)
                if (layer.get_word(x, y) != bg) canvas.set_word(x, y, layer.get_word(x, y));
    }
}

}  // namespace noneuclid::render
