// The world behind an nw_world (noneuclid.h): one World of the engine chosen, its drawing
// buffers and the list of the bodies it shows, behind an interface that does not name the
// engine, so that capi.cpp handles every engine alike. Only capi.cpp uses it.
//
// Memory: made once (the world, its draw buffers sized for it, the list's room); stepping,
// drawing and reading the bodies allocate nothing.
#pragma once

#include <memory>

#include "capi/noneuclid.h"
#include "render/canvas.hpp"
#include "render/draw_options.hpp"
#include "kinds/kinds.hpp"
#include "world/scene.hpp"

namespace noneuclid::capi {

class WorldHandle {
public:
    virtual ~WorldHandle() = default;

    virtual void step(long steps) = 0;
    virtual double time() const = 0;
    virtual long frame() const = 0;
    virtual double curvature() const = 0;
    virtual void set_curvature(double K) = 0;
    // A world action pressed or released, as the program's session applies it: a press of what
    // is held already (or a release of what is not) changes nothing, but for the actions that
    // act on each press.
    virtual void control(world::Action a, bool pressed) = 0;
    virtual void draw(const render::Canvas& c, const render::DrawOptions& o) = 0;
    // The bodies in the world (active ones), in the world's order, as files::dump_frame lists them.
    virtual int body_count() const = 0;
    virtual void body(int index, nw_body& out) const = 0;
    virtual nw_game game() const = 0;
    virtual int event_count() const = 0;
    virtual nw_event event(int index) const = 0;
};

// The engines the C interface runs: the device's, fixed point, and its reference, double. (The
// float and paper engines are for comparing numbers, in the program: each engine more is every
// template of the world and the drawing compiled once more.)
bool capi_engine(world::EngineKind engine);
// A world of `scene` on `engine`, one capi_engine accepts (allocates; may throw std::bad_alloc).
// The world of `kind` on `scene`; null for a kind whose Capabilities do not say c_interface.
std::unique_ptr<WorldHandle> make_world_handle(kinds::KindChoice kind, const world::Scene& scene);

}  // namespace noneuclid::capi
