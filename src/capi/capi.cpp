// The C interface (noneuclid.h): each function checks its arguments, says what was wrong in one
// sentence (the thread's nw_last_error), and never lets an exception out.
#include "capi/noneuclid.h"

#include <cstdint>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <string_view>

#include "capi/world_handle.hpp"
#include "kinds/step.hpp"
#include "files/scene_file.hpp"
#include "files/text_file.hpp"
#include "geometry/projection.hpp"
#include "render/palette.hpp"
#include "world/budget.hpp"
#include "world/quote.hpp"
#include "world/ranges.hpp"

static_assert(NW_VERSION_MAJOR == NONEUCLID_VERSION_MAJOR && NW_VERSION_MINOR == NONEUCLID_VERSION_MINOR &&
                  NW_VERSION_PATCH == NONEUCLID_VERSION_PATCH,
              "noneuclid.h's NW_VERSION_* are the project's version (CMakeLists.txt): change them together");

struct nw_world {
    std::unique_ptr<noneuclid::capi::WorldHandle> world;
    noneuclid::render::DrawOptions draw;
    noneuclid::kinds::StepClock clock;  // nw_advance's seconds not yet stepped
};

namespace {

using namespace noneuclid;

// The longest name (engine, control, format, projection, scene) read from the caller.
constexpr std::size_t kNameLimit = 256;
// The largest side of a canvas nw_draw takes.
constexpr int kMaxSide = 8192;
constexpr long kMaxSteps = 1000000;

thread_local char t_error[512] = "";

nw_status fail(nw_status s, const std::string& sentence) {
    std::snprintf(t_error, sizeof t_error, "%s", sentence.c_str());
    return s;
}
nw_status null_arg(const char* function, const char* what) {
    return fail(NW_ERR_NULL, std::string(function) + ": " + what + " is null: pass a valid pointer.");
}

// f(), with any exception turned into a status and a sentence.
template <class F>
nw_status guarded(const char* function, F&& f) {
    try {
        return f();
    } catch (const std::bad_alloc&) {
        return fail(NW_ERR_MEMORY, std::string(function) + ": out of memory: free some, or make the scene smaller.");
    } catch (const std::exception& e) {
        return fail(NW_ERR_INTERNAL, std::string(function) + ": " + world::printable(e.what(), world::kSentenceLimit) +
                                         " (a bug: please report it).");
    } catch (...) {
        return fail(NW_ERR_INTERNAL, std::string(function) + ": an unknown exception (a bug: please report it).");
    }
}

// The caller's name, read up to its NUL or kNameLimit bytes (strnlen is POSIX's, not C++'s).
std::string_view name_of(const char* s) {
    std::size_t n = 0;
    while (n < kNameLimit && s[n] != '\0') ++n;
    return {s, n};
}

bool find_format(std::string_view name, render::PixelFormat& out) {
    using P = render::PixelFormat;
    for (const P& f : {P::xrgb8888(), P::rgb565(), P::rgb888(), P::bgr565(), P::xbgr8888(), P::bgr888(), P::rgba8888()})
        if (name == f.name) return out = f, true;
    return false;
}
const char* const kFormatList = "xrgb8888, rgb565, rgb888, bgr565, xbgr8888, bgr888 or rgba8888";

using capi::capi_engine;

nw_status parse_engine(const char* function, const char* engine, world::EngineKind& out) {
    out = world::kDefaultEngine;
    if (!engine) return NW_OK;
    if (world::parse_engine(name_of(engine), out) && capi_engine(out)) return NW_OK;
    return fail(NW_ERR_NAME, std::string(function) + ": no engine " + world::quote(name_of(engine)) +
                                 " in the C interface: name fixed or double, or pass NULL for fixed.");
}

// The world of a scene already read: checked against the world's budget and ranges, as the
// program checks a scene it loads (app/setup.cpp).
nw_status make_world(const char* function, world::Scene& scene, world::EngineKind engine, nw_world** out) {
    std::string why;
    if (!world::within_budget(scene, why) || !world::within_ranges(scene, why))
        return fail(NW_ERR_SCENE, std::string(function) + ": the scene: " + why + ".");
    kinds::KindChoice kind;  // (its kind is chosen whether or not it has the engine)
    const bool has_engine = kinds::choose_kind(scene, &engine, kind, why);
    if (!kinds::kind_can(kind.kind).c_interface)  // (the uneven and 3D worlds: not in this interface's version yet)
        return fail(NW_ERR_SCENE, std::string(function) + ": the scene is " + kinds::kind_help(kind.kind) +
                                      ", which this interface does not run yet: use a scene of constant K in the plane.");
    if (!has_engine)
        return fail(NW_ERR_SCENE, std::string(function) + ": " + why + ".");
    auto w = std::make_unique<nw_world>();
    w->world = capi::make_world_handle(kind, scene);
    const render::PaletteFrame frame = render::palette_frame(w->draw.palette);
    w->draw.background = frame.background, w->draw.outside = frame.outside, w->draw.rim = frame.rim;
    *out = w.release();
    return NW_OK;
}

}  // namespace

extern "C" {

const char* nw_version(void) { return NONEUCLID_VERSION; }
int nw_version_number(void) { return NW_VERSION_NUMBER; }
const char* nw_last_error(void) { return t_error; }

nw_status nw_world_from_text(const char* text, size_t length, const char* engine, nw_world** out) {
    constexpr const char* fn = "nw_world_from_text";
    if (!out) return null_arg(fn, "out");
    *out = nullptr;
    if (!text) return null_arg(fn, "text");
    return guarded(fn, [&] {
        world::EngineKind e;
        if (const nw_status s = parse_engine(fn, engine, e)) return s;
        if (length > files::kSceneFileLimit)
            return fail(NW_ERR_SIZE, std::string(fn) + ": the scene text is " + std::to_string(length) +
                                         " bytes, over the 1 MiB a scene file may hold: make it smaller.");
        world::Scene scene;
        files::SceneError err;
        if (!files::parse_scene(std::string(text, length), "scene text", scene, err))
            return fail(NW_ERR_SCENE, err.to_string());
        return make_world(fn, scene, e, out);
    });
}

nw_status nw_world_from_name(const char* name, const char* engine, nw_world** out) {
    constexpr const char* fn = "nw_world_from_name";
    if (!out) return null_arg(fn, "out");
    *out = nullptr;
    if (!name) return null_arg(fn, "name");
    return guarded(fn, [&] {
        world::EngineKind e;
        if (const nw_status s = parse_engine(fn, engine, e)) return s;
        world::Scene scene;
        std::string why;
        if (!world::builtin_scene(std::string(name_of(name)), world::SceneParams{}, scene, &why))
            return fail(NW_ERR_SCENE, std::string(fn) + ": no built-in scene " + world::quote(name_of(name)) + ": name " +
                                          world::or_list(world::builtin_scene_names()) + ".");
        return make_world(fn, scene, e, out);
    });
}

void nw_world_free(nw_world* w) { delete w; }

nw_status nw_step(nw_world* w, long steps) {
    if (!w) return null_arg("nw_step", "the world");
    if (steps < 0 || steps > kMaxSteps)
        return fail(NW_ERR_RANGE, "nw_step: " + std::to_string(steps) + " steps: ask for 0 to 1000000 at a time.");
    return guarded("nw_step", [&] {
        w->world->step(steps);
        return NW_OK;
    });
}

nw_status nw_advance(nw_world* w, double seconds, long* steps) {
    if (!w) return null_arg("nw_advance", "the world");
    if (!(seconds >= 0 && seconds <= kMaxSteps * noneuclid::kinds::kStepSeconds)) {
        char given[64];
        std::snprintf(given, sizeof given, "%g", seconds);
        return fail(NW_ERR_RANGE, std::string("nw_advance: ") + given + " seconds: ask for 0 to 16666 at a time.");
    }
    return guarded("nw_advance", [&] {
        const long n = w->clock.steps_for(seconds);
        w->world->step(n);
        if (steps) *steps = n;
        return NW_OK;
    });
}

nw_status nw_clock(const nw_world* w, double* seconds, long* steps) {
    if (!w) return null_arg("nw_clock", "the world");
    if (seconds) *seconds = w->world->time();
    if (steps) *steps = w->world->frame();
    return NW_OK;
}

nw_status nw_curvature(const nw_world* w, double* K) {
    if (!w) return null_arg("nw_curvature", "the world");
    if (!K) return null_arg("nw_curvature", "K");
    *K = w->world->curvature();
    return NW_OK;
}

nw_status nw_set_curvature(nw_world* w, double K) {
    if (!w) return null_arg("nw_set_curvature", "the world");
    if (!(K >= -1 && K <= 1)) {
        char number[40];
        std::snprintf(number, sizeof number, "%g", K);
        return fail(NW_ERR_RANGE, std::string("nw_set_curvature: K = ") + number + ": give K in [-1, 1].");
    }
    w->world->set_curvature(K);
    return NW_OK;
}

nw_status nw_control(nw_world* w, const char* control, int pressed) {
    if (!w) return null_arg("nw_control", "the world");
    if (!control) return null_arg("nw_control", "control");
    return guarded("nw_control", [&] {
        world::Action a{};
        if (!world::parse_action(name_of(control), a) || !world::is_world_action(a)) {
            std::vector<std::string> names;
            for (int i = 0; i < world::kWorldActionCount; ++i) names.emplace_back(world::action_name(static_cast<world::Action>(i)));
            return fail(NW_ERR_NAME, "nw_control: no control " + world::quote(name_of(control)) + ": name " +
                                         world::or_list(names) + ".");
        }
        w->world->control(a, pressed != 0);
        return NW_OK;
    });
}

nw_status nw_set_view(nw_world* w, const char* projection, int antialias) {
    if (!w) return null_arg("nw_set_view", "the world");
    if (!projection) return null_arg("nw_set_view", "projection");
    return guarded("nw_set_view", [&] {
        geo::Projection p{};
        if (!geo::parse_projection_name(name_of(projection), p))
            return fail(NW_ERR_NAME, "nw_set_view: no projection " + world::quote(name_of(projection)) + ": name " +
                                         world::or_list(geo::projection_names()) + ".");
        w->draw.projection = p;
        w->draw.antialias = antialias != 0;
        return NW_OK;
    });
}

nw_status nw_format_bytes(const char* format, int* bytes) {
    if (!format) return null_arg("nw_format_bytes", "format");
    if (!bytes) return null_arg("nw_format_bytes", "bytes");
    render::PixelFormat f;
    if (!find_format(name_of(format), f))
        return fail(NW_ERR_NAME, "nw_format_bytes: no pixel format " + world::quote(name_of(format)) + ": name " +
                                     kFormatList + ".");
    *bytes = f.bytes_per_pixel();
    return NW_OK;
}

nw_status nw_draw(nw_world* w, void* pixels, size_t capacity, int width, int height, ptrdiff_t stride,
                  const char* format) {
    constexpr const char* fn = "nw_draw";
    if (!w) return null_arg(fn, "the world");
    if (!pixels) return null_arg(fn, "pixels");
    if (!format) return null_arg(fn, "format");
    render::PixelFormat f;
    if (!find_format(name_of(format), f))
        return fail(NW_ERR_NAME, std::string(fn) + ": no pixel format " + world::quote(name_of(format)) + ": name " +
                                     kFormatList + ".");
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
        return fail(NW_ERR_SIZE, std::string(fn) + ": a canvas of " + std::to_string(width) + "x" + std::to_string(height) +
                                     ": give each side 1 to 8192 pixels.");
    const std::int64_t row = std::int64_t{width} * f.bytes_per_pixel();
    if (stride == 0) stride = static_cast<ptrdiff_t>(row);
    if (stride < row)
        return fail(NW_ERR_SIZE, std::string(fn) + ": a stride of " + std::to_string(stride) + " bytes is less than a row of " +
                                     std::to_string(row) + ": give at least that, or 0.");
    const std::uint64_t needed = static_cast<std::uint64_t>(stride) * static_cast<std::uint64_t>(height - 1) +
                                 static_cast<std::uint64_t>(row);
    if (needed > capacity)
        return fail(NW_ERR_SIZE, std::string(fn) + ": the buffer holds " + std::to_string(capacity) + " bytes and the canvas needs " +
                                     std::to_string(needed) + ": pass a larger buffer or a smaller canvas.");
    return guarded(fn, [&] {
        w->world->draw(render::Canvas(pixels, width, height, stride, f), w->draw);
        return NW_OK;
    });
}

nw_status nw_body_count(const nw_world* w, int* count) {
    if (!w) return null_arg("nw_body_count", "the world");
    if (!count) return null_arg("nw_body_count", "count");
    *count = w->world->body_count();
    return NW_OK;
}

nw_status nw_body_at(const nw_world* w, int index, nw_body* out) {
    if (!w) return null_arg("nw_body_at", "the world");
    if (!out) return null_arg("nw_body_at", "out");
    const int n = w->world->body_count();
    if (index < 0 || index >= n)
        return fail(NW_ERR_RANGE, "nw_body_at: body " + std::to_string(index) + " of " + std::to_string(n) +
                                      ": give an index from 0 to nw_body_count's less one.");
    w->world->body(index, *out);
    return NW_OK;
}

nw_status nw_game_state(const nw_world* w, nw_game* out) {
    if (!w) return null_arg("nw_game_state", "the world");
    if (!out) return null_arg("nw_game_state", "out");
    *out = w->world->game();
    return NW_OK;
}

nw_status nw_event_count(const nw_world* w, int* count) {
    if (!w) return null_arg("nw_event_count", "the world");
    if (!count) return null_arg("nw_event_count", "count");
    *count = w->world->event_count();
    return NW_OK;
}

nw_status nw_event_at(const nw_world* w, int index, nw_event* out) {
    if (!w) return null_arg("nw_event_at", "the world");
    if (!out) return null_arg("nw_event_at", "out");
    const int n = w->world->event_count();
    if (index < 0 || index >= n)
        return fail(NW_ERR_RANGE, "nw_event_at: event " + std::to_string(index) + " of " + std::to_string(n) +
                                      ": give an index from 0 to nw_event_count's less one.");
    *out = w->world->event(index);
    return NW_OK;
}

}  // extern "C"
