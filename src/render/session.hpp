// One running world on a display: controls in (buttons, keys, the attract-mode autopilot),
// one fixed step of 1/60 s and one drawn frame out. The platform loops (fbdev kiosk, X11
// window) own the display, the input fds and the clock; this owns everything portable, so
// every display behaves the same. Allocates nothing per frame.
//
// Order within a frame, the same as `noneuclid render --actions`: the controls due now are
// applied (each world action reported to the recorder with the world time), then the world
// steps, then the frame is drawn. A recording therefore replays bit for bit with render.
#pragma once

#include <cstdint>
#include <cstdio>
#include <iterator>

#include "render/draw_world.hpp"
#include "render/parallel_frame.hpp"
#include "render/hud.hpp"
#include "world/attract.hpp"
#include "world/controls.hpp"

namespace noneuclid::render {

// Receives every world action as it takes effect (time = world time before the step).
class ActionRecorder {
public:
    virtual ~ActionRecorder() = default;
    virtual void action(double time, bool press, world::Action a) = 0;
    virtual void note(double time, const char* what) = 0;  // non-world controls, attract on/off
};

// Writes world actions in the actions-file format (world/actions.hpp) that
// `noneuclid render --actions` replays; other controls and attract mode as comments.
class FileRecorder final : public ActionRecorder {
public:
    explicit FileRecorder(std::FILE* f) : f_(f) {}
    void action(double time, bool press, world::Action a) override {
        std::fprintf(f_, "%.9f %s %s\n", time, press ? "press" : "release", world::action_name(a));
    }
    void note(double time, const char* what) override { std::fprintf(f_, "# %.9f %s\n", time, what); }

private:
    std::FILE* f_;
};

struct SessionOptions {
    DrawOptions draw;
    bool hud = true;
    const char* scene_name = "";
    const char* controls = "thrust  left/right  curvature +/-  preset  reset";
    world::AttractOptions attract{0, 40, 0.25};  // idle_seconds 0: off
};

template <class W>
class Session {
public:
    using T = typename W::scalar;

    // `pool` (optional, started once by the caller): draw each frame over its threads, the same
    // pixels as one thread (draw_world's threaded overload).
    Session(const world::Scene& scene, const SessionOptions& o, const Font& font, ActionRecorder* recorder = nullptr,
            WorkerPool* pool = nullptr)
        : world(scene), options(o), font_(font), recorder_(recorder), pool_(pool && pool->size() > 1 ? pool : nullptr),
          autopilot_(o.attract, scene.curvature_rate) {
        scratch_.prepare(world);
        if (pool_) parallel_.prepare(world, *pool_);
    }

    W world;
    SessionOptions options;
    bool quit = false;
    double fps = 0;  // shown by the HUD when > 0

    bool attract() const { return autopilot_.active(); }

    // A button or key. Returns false once quit was asked for.
    bool control(world::InputEvent e) {
        world::InputEvent ap[8];
        if (e.pressed || user_held_any()) {
            const int n = autopilot_.interrupt(world.time, ap);
            if (n > 0) note("attract off");
            for (int i = 0; i < n; ++i) apply(ap[i]);
        }
        user_held_[static_cast<int>(e.control)] = e.pressed;
        apply(e);
        return !quit;
    }

    // The autopilot's controls, the step, the picture.
    void frame(const Canvas& canvas) {
        world::InputEvent ap[8];
        if (user_held_any()) autopilot_.interrupt(world.time, ap);  // a held button is not idle
        const bool was = autopilot_.active();
        const int n = autopilot_.frame(world.time, static_cast<double>(world.K), ship_speed(), ap);
        if (!was && autopilot_.active()) note("attract on");
        for (int i = 0; i < n; ++i) apply(ap[i]);
        world.step(T(1.0 / 60));
        draw(canvas);
    }

    void draw(const Canvas& canvas) {
        if (pool_) draw_world(canvas, world, options.draw, parallel_, *pool_);
        else draw_world(canvas, world, options.draw, scratch_);
        if (!options.hud) return;
        HudInfo info;
        info.K = static_cast<double>(world.K);
        info.fps = fps;
        info.scene = options.scene_name;
        info.projection = geo::projection_name(options.draw.projection);
        info.controls = autopilot_.active() ? "attract mode: press any button to fly" : options.controls;
        draw_hud(canvas, font_, info);
    }

private:
    void apply(world::InputEvent e) {
        world::Action a{};
        if (world::control_action(e.control, a)) {
            if (e.pressed == world.held(a) && a != world::Action::reset && a != world::Action::next_preset) return;
            if (recorder_) recorder_->action(world.time, e.pressed, a);
            if (e.pressed) world.press(a);
            else world.release(a);
            return;
        }
        if (!e.pressed) return;
        switch (e.control) {
            case world::Control::projection: {
                const int count = static_cast<int>(std::size(geo::kProjections));
                int i = 0;
                while (i < count && geo::kProjections[i] != options.draw.projection) ++i;
                options.draw.projection = geo::kProjections[(i + 1) % count];
                note("projection");
                break;
            }
            case world::Control::hud: options.hud = !options.hud; break;
            case world::Control::quit: quit = true; break;
            default: break;
        }
    }
    void note(const char* what) {
        if (recorder_) recorder_->note(world.time, what);
    }
    bool user_held_any() const {
        for (bool h : user_held_)
            if (h) return true;
        return false;
    }
    double ship_speed() const {
        for (const auto& b : world.bodies)
            if (b.desc->controlled) return static_cast<double>(b.speed);
        return 1e9;  // nothing to fly: never thrust
    }

    const Font& font_;
    ActionRecorder* recorder_;
    WorkerPool* pool_;
    world::Autopilot autopilot_;
    DrawScratch<T> scratch_;
    ParallelScratch<T> parallel_;
    bool user_held_[world::kControlCount] = {};
};

}  // namespace noneuclid::render
