#include "harness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <cstring>
#include <toml++/toml.h>

#include "app/script.hpp"
#include "capi/noneuclid.h"
#include "fixed/fixed.hpp"
#include "files/board.hpp"
#include "world/action.hpp"
#include "files/dump.hpp"
#include "world/quote.hpp"
#include "world/engines.hpp"
#include "world/ranges.hpp"
#include "files/scene_file.hpp"
#include "files/toml_reader.hpp"
#include "world/world.hpp"

namespace noneuclid::fuzz {

namespace {

[[noreturn]] void broken(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz harness: %s: %s\n", what, world::printable(detail, 400).c_str());
    std::abort();
}
#define FUZZ_CHECK(cond, detail) \
    do {                         \
        if (!(cond)) broken(#cond, detail); \
    } while (0)

// One sentence a terminal shows as it is, of a bounded length, naming `file` and, for `place`,
// a line (and a column) from 1.
void check_sentence(const std::string& s, const std::string& file, long line, long column, bool place) {
    FUZZ_CHECK(world::is_plain(s), s);
    FUZZ_CHECK(s.size() <= 2000, s);
    FUZZ_CHECK(s.rfind(file + ":", 0) == 0, s);
    if (place) {
        FUZZ_CHECK(line >= 1, s);
        FUZZ_CHECK(column >= 1, s);
        FUZZ_CHECK(s.rfind(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ", 0) == 0, s);
    }
}

bool in(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

// The vertices the scene's [[grid]] tables would add (world::add_axis_grid, add_radial_grid),
// estimated from the TOML before files::parse_scene builds them. Values it cannot read are
// left to the parser, which refuses them before building that grid.
double grid_vertices(std::string_view text) {
    long line = 0, column = 0;
    std::string why;
    if (!files::tomlr::toml_guard(text, line, column, why)) return 0;  // refused before toml++
    toml::table root;
    try {
        root = toml::parse(text, std::string("estimate"));
    } catch (const toml::parse_error&) {
        return 0;
    }
    auto number = [](const toml::node* n, double fallback) {
        if (!n) return fallback;
        if (auto f = n->as_floating_point()) return f->get();
        if (auto i = n->as_integer()) return static_cast<double>(i->get());
        return std::nan("");
    };
    const double R = number(root.get("limit_radius"), std::numbers::pi);
    if (!in(R, 1e-3, 1e4)) return 0;
    const toml::array* grids = root.get("grid") ? root.get("grid")->as_array() : nullptr;
    if (!grids) return 0;
    double total = 0;
    for (const toml::node& g : *grids) {
        const toml::table* t = g.as_table();
        if (!t) break;
        const double length = number(t->get("length"), R), step = number(t->get("step"), 0.25);
        if (!in(length, 0.01, 1e4) || !in(step, 0.001, 1e4)) break;
        const double per_line = std::ceil(length / step) + 1;
        const toml::node* kind = t->get("kind");
        const bool radial = kind && kind->as_string() && kind->as_string()->get() == "radial";
        if (radial) {
            const double lines = number(t->get("lines"), 12);
            if (!in(lines, 1, 360)) break;
            total += lines * per_line;
        } else {
            const double spacing = number(t->get("spacing"), 0.5);
            if (!in(spacing, 0.01, 1e4)) break;
            total += 2 * (2 * std::floor(R / spacing) + 1) * (2 * per_line);
        }
    }
    return total;
}

bool finite_world(const auto& w) {
    using T = typename std::remove_cvref_t<decltype(w)>::scalar;
    auto ok = [](T v) { return std::isfinite(static_cast<double>(v)); };
    if (!ok(w.K)) return false;
    std::vector<geo::Polar<T>> v;
    for (const auto& b : w.bodies) {
        if (!ok(b.centre.r) || !ok(b.centre.theta) || !ok(b.facing) || !ok(b.speed) || !ok(b.travel)) return false;
        v.resize(b.local.size());
        w.vertices(b, v.data());
        for (const auto& p : v)
            if (!ok(p.r) || !ok(p.theta)) return false;
    }
    return true;
}

// Steps `w` `frames` frames with the script's events, then dumps its last frame.
template <class W>
std::string run_world(W& w, const app::Script& script, int frames, geo::Projection projection) {
    app::ScriptPlayer player(script.events);
    const double dt = 1.0 / 60;
    for (int f = 0; f < frames; ++f) {
        while (const app::ScriptEvent* e = player.next_due(w.time)) {
            const world::Action a = e->control;
            if (e->kind == app::ScriptEvent::attract_on || e->kind == app::ScriptEvent::attract_off) continue;
            if (!world::is_world_action(a)) continue;  // the view's: projection, hud
            if (e->kind == app::ScriptEvent::press || e->kind == app::ScriptEvent::tap) w.press(a);
            if (e->kind == app::ScriptEvent::release || e->kind == app::ScriptEvent::tap) w.release(a);
        }
        w.step(dt);
    }
    files::DumpOptions o;
    o.projection = projection;
    std::string line;
    files::dump_frame(w, o, line);
    FUZZ_CHECK(!line.empty() && line.back() == '\n' && line.find('\n') == line.size() - 1, line);
    return line;
}

}  // namespace

void scene(std::string_view input) {
    if (grid_vertices(input) > kMaxVertices) return;
    const std::string text(input);
    world::Scene s;
    files::SceneError e;
    if (!files::parse_scene(text, "f.toml", s, e)) {
        check_sentence(e.to_string(), "f.toml", e.line, e.column, true);
        return;
    }
    FUZZ_CHECK(in(s.curvature, -1, 1), std::to_string(s.curvature));
    FUZZ_CHECK(in(s.limit_radius, 1e-3, world::Ranges::kLimitRadius), std::to_string(s.limit_radius));
    FUZZ_CHECK(!s.presets.empty(), "no presets");
    for (double p : s.presets) FUZZ_CHECK(in(p, -1, 1), std::to_string(p));
    for (const world::SceneBody& b : s.bodies) {
        FUZZ_CHECK(!b.vertices.empty(), b.name);
        FUZZ_CHECK(b.tessellation >= 1 && b.tessellation <= 256, b.name);
        FUZZ_CHECK(in(b.r, 0, s.limit_radius) && in(b.speed, 0, world::Ranges::kSpeed) && in(b.accel, 0, 1e3), b.name);
        for (const auto& v : b.vertices) FUZZ_CHECK(in(v.rho, 0, world::Ranges::kReach) && in(v.phi_deg, -1e6, 1e6), b.name);
        std::string why;
        FUZZ_CHECK(world::body_within_ranges(b, s.limit_radius, why), why);
    }
}

void board(std::string_view input) {
    const std::string text(input);
    files::Board b;
    files::BoardError e;
    if (!files::parse_board(text, "b.toml", b, e)) {
        check_sentence(e.to_string(), "b.toml", e.line, e.column, true);
        return;
    }
    world::EngineKind engine{};  // none (the scene's kind's first), or one a board may name
    FUZZ_CHECK(b.engine.empty() || (world::parse_engine(b.engine, engine) && world::engine_on_board(engine)), b.engine);
    FUZZ_CHECK(in(b.fps, 1, 1000) && b.threads >= 1 && b.threads <= 16, b.file);
    for (const std::string& s : {b.name, b.device, b.scene, b.evdev_device}) FUZZ_CHECK(world::is_plain(s), s);
    for (const std::string& s : b.chips) FUZZ_CHECK(world::is_plain(s), s);
    for (const files::BoardButton& bb : b.buttons) {
        FUZZ_CHECK(bb.gpio >= 0 || bb.key >= 0, "a button with neither");
        FUZZ_CHECK(bb.gpio <= 1023 && bb.key <= 767 && bb.pin >= 0 && bb.pin <= 40, "a button out of range");
    }
}

namespace {

// Whether an actions file the parser accepted has a control byte (NUL included) anywhere but in
// a comment, a tab, or the ends of a line (CR, LF): it must have none (app/script.hpp).
bool control_outside_comments(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    while (!text.empty()) {
        const std::size_t end = std::min(text.find('\n'), text.size());
        std::string_view line = text.substr(0, end);
        text.remove_prefix(std::min(end + 1, text.size()));
        line = line.substr(0, line.find('#'));
        while (!line.empty() && (line.front() == ' ' || line.front() == '\t' || line.front() == '\r')) line.remove_prefix(1);
        while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r')) line.remove_suffix(1);
        for (const char c : line)
            if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7F) return true;
    }
    return false;
}

}  // namespace

void actions(std::string_view input) {
    const std::string text(input);  // every byte, NUL included
    app::Script s;
    app::ScriptError e;
    if (!app::parse_script(text, "a.txt", s, e)) {
        check_sentence(e.to_string(), "a.txt", e.line, 1, false);
        FUZZ_CHECK(e.line >= 1, e.to_string());
        return;
    }
    for (std::size_t i = 0; i < s.events.size(); ++i) {
        FUZZ_CHECK(std::isfinite(s.events[i].time) && s.events[i].time >= 0, std::to_string(s.events[i].time));
        FUZZ_CHECK(i == 0 || s.events[i - 1].time <= s.events[i].time, "events out of order");
        FUZZ_CHECK(s.events[i].control != world::Action::quit, "quit replayed");
    }
    for (const app::Setting& st : s.settings) FUZZ_CHECK(world::is_plain(st.value) && !st.value.empty(), st.value);
    FUZZ_CHECK(!control_outside_comments(input), "a control byte accepted: " + text);
}

void world(std::string_view input) {
    const std::size_t split = input.find("\n%%\n");
    const std::string_view scene_text = input.substr(0, split);
    const std::string_view actions_text = split == std::string_view::npos ? std::string_view() : input.substr(split + 4);
    if (grid_vertices(scene_text) > kMaxVertices) return;
    world::Scene s;
    files::SceneError se;
    if (!files::parse_scene(std::string(scene_text), "w.toml", s, se)) return;  // the scene harness checks these
    app::Script script;
    app::ScriptError ae;
    if (!app::parse_script(std::string(actions_text), "w.txt", script, ae)) return;
    double points = 0;
    for (const world::SceneBody& b : s.bodies) points += static_cast<double>(b.vertices.size()) * (b.tessellation + 1);
    if (points > kMaxEdgePoints) return;

    constexpr int kFrames = 40;
    const geo::Projection projection = geo::kProjections[input.size() % std::size(geo::kProjections)];
    world::World<fx::fixed> wf(s);
    world::World<double> wd(s);
    world::World<float> wfl(s);
    world::World<double, geo::Paper> wp(s);
    run_world(wf, script, kFrames, projection);
    run_world(wd, script, kFrames, projection);
    run_world(wfl, script, kFrames, projection);
    run_world(wp, script, kFrames, projection);  // the paper's formulas: NaN is theirs to give
    FUZZ_CHECK(wf.frame == kFrames && wd.frame == kFrames, "frames");
    // The accepted ranges are the engines' (world/ranges.hpp): whatever parses stays finite.
    if (!finite_world(wf) || !finite_world(wd) || !finite_world(wfl))
        broken("a value that is not finite in the fixed, double or float engine", std::string(input));
}

}  // namespace noneuclid::fuzz

namespace noneuclid::fuzz {

namespace {

// The last error: one plain line, of a bounded length.
void check_error() {
    const std::string e = nw_last_error();
    FUZZ_CHECK(!e.empty() && e.size() <= 600 && world::is_plain(e) && e.find('\n') == std::string::npos, e);
}

// nw_draw with its arguments from three bytes, against the status they call for.
void capi_draw(nw_world* w, uint8_t a, uint8_t b, uint8_t c) {
    static const char* const formats[] = {"xrgb8888", "rgb565", "rgb888", "bgr565", "xbgr8888",
                                          "bgr888",   "rgba8888", "rgb555", nullptr};
    const int width = a % 70, height = b % 50;  // 0: refused
    const char* format = formats[c % 9];
    int bpp = 0;
    const bool named = format && nw_format_bytes(format, &bpp) == NW_OK;
    const long row = static_cast<long>(width) * bpp;
    const int stride_kind = (c / 9) % 3, capacity_kind = (b >> 6) & 3;
    const long stride = stride_kind == 0 ? 0 : stride_kind == 1 ? row + a % 5 : row - 1;
    const long step = stride == 0 ? row : stride;
    const long needed = height > 0 ? step * (height - 1) + row : 0;
    const long capacity = capacity_kind == 0 ? needed : capacity_kind == 1 ? needed - 1 : needed + 3;
    std::vector<uint8_t> buffer(static_cast<std::size_t>(std::max(capacity, 1L)));
    void* pixels = capacity_kind == 3 ? nullptr : buffer.data();
    const nw_status got = nw_draw(w, pixels, static_cast<std::size_t>(std::max(capacity, 0L)), width, height,
                                  static_cast<ptrdiff_t>(stride), format);
    nw_status want = NW_OK;
    if (!pixels || !format) want = NW_ERR_NULL;
    else if (!named) want = NW_ERR_NAME;
    else if (width < 1 || height < 1 || (stride != 0 && stride < row) || capacity < needed) want = NW_ERR_SIZE;
    FUZZ_CHECK(got == want, "nw_draw " + std::to_string(width) + "x" + std::to_string(height) + " stride " +
                                std::to_string(stride) + " capacity " + std::to_string(capacity) + ": " +
                                std::to_string(got) + " for " + std::to_string(want) + " " + nw_last_error());
    if (got != NW_OK) check_error();
}

// One operation (4 bytes) on the world.
void capi_op(nw_world* w, const uint8_t* op, long& steps) {
    static const char* const controls[] = {"thrust", "left", "right", "curvature_up", "curvature_down",
                                           "preset", "reset", "hyperbolic", "flat", "spherical",
                                           "fire", "instrument", "jump", nullptr};
    static const char* const projections[] = {"equidistant", "stereographic", "gnomonic", "orthographic",
                                              "lambert", "mercator", nullptr};
    const uint8_t a = op[1], b = op[2], c = op[3];
    nw_status s = NW_OK, want = NW_OK;
    int n = 0;
    switch (op[0] % 8) {
        case 0: {
            const long k = std::min<long>(a % 8, 200 - steps);
            steps += k;
            s = nw_step(w, k);
            break;
        }
        case 1: {
            const double K = (a - 128) / 100.0;
            s = nw_set_curvature(w, K);
            want = K >= -1 && K <= 1 ? NW_OK : NW_ERR_RANGE;
            double got = 9;
            if (s == NW_OK) FUZZ_CHECK(nw_curvature(w, &got) == NW_OK && std::abs(got - K) <= 1.0 / 65536, std::to_string(got));
            break;
        }
        case 2: {
            const char* name = controls[a % 14];
            s = nw_control(w, name, b & 1);
            want = !name ? NW_ERR_NULL : a % 14 == 12 ? NW_ERR_NAME : NW_OK;
            break;
        }
        case 3: capi_draw(w, a, b, c); return;
        case 4: {
            FUZZ_CHECK(nw_body_count(w, &n) == NW_OK, "nw_body_count");
            nw_body body;
            const int i = a - 8;
            s = nw_body_at(w, i, &body);
            want = i >= 0 && i < n ? NW_OK : NW_ERR_RANGE;
            if (s == NW_OK) {
                FUZZ_CHECK(std::memchr(body.name, 0, sizeof body.name) && std::memchr(body.kind, 0, sizeof body.kind), "names");
                FUZZ_CHECK(body.theta > -180 - 1e-9 && body.theta <= 180 + 1e-9 && body.vertices >= 1, body.name);
            }
            break;
        }
        case 5: {
            FUZZ_CHECK(nw_event_count(w, &n) == NW_OK, "nw_event_count");
            nw_event e;
            s = nw_event_at(w, a % 4, &e);
            want = a % 4 < n ? NW_OK : NW_ERR_RANGE;
            if (s == NW_OK) FUZZ_CHECK(e.kind >= NW_EVENT_START && e.kind <= NW_EVENT_OVER, std::to_string(e.kind));
            break;
        }
        case 6: {
            const char* name = projections[a % 7];
            s = nw_set_view(w, name, b & 1);
            want = !name ? NW_ERR_NULL : a % 7 == 5 ? NW_ERR_NAME : NW_OK;
            break;
        }
        default: {
            nw_game g;
            double t = -1;
            long frames = -1;
            FUZZ_CHECK(nw_game_state(w, &g) == NW_OK && g.phase >= 0 && g.phase <= 2, "nw_game_state");
            FUZZ_CHECK(nw_clock(w, &t, &frames) == NW_OK && frames <= steps && t >= 0, "nw_clock");
            break;
        }
    }
    FUZZ_CHECK(s == want, "operation " + std::to_string(op[0] % 8) + ": " + std::to_string(s) + " for " +
                              std::to_string(want) + " " + nw_last_error());
    if (s != NW_OK) check_error();
}

}  // namespace

void capi(std::string_view input) {
    const std::size_t split = input.find("\n%%\n");
    const std::string_view scene_text = input.substr(0, split);
    const std::string_view ops = split == std::string_view::npos ? std::string_view() : input.substr(split + 4);
    if (grid_vertices(scene_text) > kMaxVertices) return;
    world::Scene s;
    files::SceneError se;
    const bool parses = files::parse_scene(std::string(scene_text), "c.toml", s, se);
    double points = 0;
    for (const world::SceneBody& b : s.bodies) points += static_cast<double>(b.vertices.size()) * (b.tessellation + 1);
    if (parses && points > kMaxEdgePoints) return;

    static const char* const engines[] = {"fixed", "double", nullptr, "paper", "abacus"};
    const std::size_t e = input.size() % std::size(engines);
    nw_world* w = nullptr;
    const nw_status made = nw_world_from_text(scene_text.data(), scene_text.size(), engines[e], &w);
    if (e >= 3) {  // (the C interface runs fixed and double only)
        FUZZ_CHECK(made == NW_ERR_NAME && !w, std::to_string(made));
        check_error();
        return;
    }
    if (!parses) {
        FUZZ_CHECK(made == NW_ERR_SCENE && !w, "a scene the parser refuses was made: " + std::to_string(made));
        FUZZ_CHECK(std::string(nw_last_error()).rfind("scene text:", 0) == 0, nw_last_error());
        check_error();
        return;
    }
    if (made != NW_OK) {  // the world's budget and ranges (as the program checks a scene it loads)
        FUZZ_CHECK(made == NW_ERR_SCENE && !w, std::to_string(made) + " " + nw_last_error());
        check_error();
        return;
    }
    long steps = 0;
    for (std::size_t i = 0; i + 4 <= ops.size() && i < 4 * 64; i += 4)
        capi_op(w, reinterpret_cast<const uint8_t*>(ops.data() + i), steps);
    nw_world_free(w);
}

}  // namespace noneuclid::fuzz
