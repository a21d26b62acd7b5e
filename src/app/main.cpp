// noneuclid: command-line front end. Commands: run (the kiosk on the framebuffer, a window, or
// the demo to PNG files headless), buttons (print what the kiosk's buttons send), demo, render (PNG), dump (JSON Lines), accuracy (the fixed-point core and the
// geometry against their references). `noneuclid --help` lists them with their options.
#if NONEUCLID_HAVE_DESKTOP
#include "desktop/console_font.hpp"
#endif
#if NONEUCLID_HAVE_PNG
#include "desktop/png_file.hpp"
#endif
#if NONEUCLID_HAVE_X11
#include "desktop/x11_window.hpp"
#endif
#include "desktop/display_choice.hpp"
#if NONEUCLID_HAVE_FBDEV
#include "linux/boards.hpp"
#include "linux/kiosk.hpp"
#endif
#if NONEUCLID_HAVE_INPUT
#include "linux/input.hpp"
#endif
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <system_error>
#include <string>
#include <vector>

#include "fixed/accuracy.hpp"
#include "fixed/tables.hpp"
#include "geometry/accuracy.hpp"
#include "render/hud.hpp"
#include "render/render_scene.hpp"
#include "world/actions.hpp"
#include "world/dump.hpp"
#include "world/scene_file.hpp"
#include "world/world.hpp"

namespace {

constexpr const char* kVersion = "0.1.0";

void print_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: noneuclid [COMMAND] [OPTIONS]\n"
                 "\n"
                 "A 2D engine for spaces of constant curvature K in [-1, 1], after Osudin,\n"
                 "Child & He (2019). It runs worlds without a screen (dump), draws them to PNG\n"
                 "pictures (render, demo) and reports on its own accuracy (accuracy).\n"
                 "\n"
                 "commands:\n"
                 "  demo              render the kiosk scene and the paper's time-lapse figures to\n"
                 "                    PNG files in ./out (--out-dir DIR), and say where; what the\n"
                 "                    program does when given no command\n"
                 "  accuracy          measure every fixed-point function against std:: double and\n"
                 "                    the geometry engines at the screen, and print the tables;\n"
                 "                    exit status 1 if any row misses its asserted bound\n"
                 "  dump              run a scene and write its state as JSON Lines, one line per\n"
                 "                    frame, frame 0 being the initial state\n"
                 "  render            run a scene and write its last frame as a PNG picture\n"
                 "  run               run a scene live: an X11 window when DISPLAY is set, the\n"
                 "                    framebuffer and the board's buttons on a console (the\n"
                 "                    kiosk), else the demo's PNG files (README: 'Desktop', 'Kiosk')\n"
                 "  buttons           print each press and release of the board's buttons or keys\n"
                 "                    (for checking the wiring); --events N, --timeout SECONDS,\n"
                 "                    --board, --input as for run\n"
                 "\n"
                 "options for accuracy:\n"
                 "  --samples N       evenly spaced samples per row (default 262144)\n"
                 "  --random N        seeded random samples per row (default 65536)\n"
                 "  --seed S          seed for the random samples (default 20190101)\n"
                 "\n"
                 "options for dump:\n"
                 "  --scene NAME|FILE a built-in scene (kiosk, fig1, fig14, fig15, fig16, fig17,\n"
                 "                    stress) or a TOML scene file (default kiosk)\n"
                 "  --curvature K     start at this K instead of the scene's, -1 <= K <= 1\n"
                 "  --frames N        steps to run after frame 0 (default 60)\n"
                 "  --dt S            seconds per step (default 1/60)\n"
                 "  --engine E        fixed (default: the device's), double, float, or paper\n"
                 "                    (the paper's formulas, literally)\n"
                 "  --actions FILE    timed presses and releases (see README, 'Actions')\n"
                 "  --size WxH        canvas for the \"screen\" points (default 800x480)\n"
                 "  --projection P    equidistant (default), stereographic, gnomonic,\n"
                 "                    orthographic, lambert\n"
                 "  --bodies N, --vertices N, --tessellation N   the stress scene's size\n"
                 "                    (default 200, 8, 8)\n"
                 "\n"
                 "options for render (and the dump options above):\n"
                 "  --out FILE.png    where to write the picture (required)\n"
                 "  --format F        the canvas's pixel format: xrgb8888 (default), rgb565, rgb888\n"
                 "  --aa              anti-aliased lines\n"
                 "  --width PX        line width in pixels (default 1)\n"
                 "  --timelapse EVERY lay every EVERY-th frame's bodies over the earlier ones, as in\n"
                 "                    the paper's figures 14-17\n"
                 "  --hud             draw K, the scene and the controls over the picture, in a\n"
                 "                    console font (/usr/share/consolefonts, $NONEUCLID_FONT) or\n"
                 "                    the built-in one\n"
                 "\n"
                 "options for run:\n"
                 "  --display D       x11, fbdev[:/dev/fbN] (default /dev/fb0, or the board's) or\n"
                 "                    png (the demo); default x11 if DISPLAY is set, else fbdev on\n"
                 "                    a framebuffer console, else png\n"
                 "  --board NAME|FILE the kiosk's board file: rpi-zero2w, rpi3, rpi4, rpi5, generic\n"
                 "                    or a path (default: detected from the device-tree model)\n"
                 "  --input I         fbdev only: gpio (libgpiod), evdev (key devices), none, or\n"
                 "                    auto (default: the board's GPIO buttons and, if found, keys)\n"
                 "  --attract SECONDS fbdev only: attract mode after this long without a button\n"
                 "                    (default: the board's, 120); 0 turns it off\n"
                 "  --threads N       fbdev only: draw on N threads (default: the board's, 1)\n"
                 "  --record FILE     fbdev only: write every action as it took effect, as an\n"
                 "                    actions file that render --actions replays exactly\n"
                 "  --scene, --curvature, --engine, --projection, --aa   as above (fbdev: the\n"
                 "                    board's [display] gives the defaults)\n"
                 "  --size WxH        the window's size (default 800x480; fbdev uses the mode's)\n"
                 "  --frames N        quit after N frames (default: when the window is closed)\n"
                 "  --fps CAP         frame rate cap (default 60); world time is 1/60 s a frame\n"
                 "  --screenshot F    at exit, read the window back from the X server into F.png\n"
                 "  --no-hud          start with the HUD off (H toggles it)\n"
                 "  --stats           at exit, print frames, wall time and CPU seconds\n"
                 "\n"
                 "  -h, --help        show this help\n"
                 "  --version         show the version\n");
}

// Parses a non-negative integer option value; on failure prints one sentence and exits 2.
unsigned long long parse_count(const char* option, const char* text, unsigned long long lo,
                               unsigned long long hi) {
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(text ? text : "", &end, 10);
    if (!text || *text == '\0' || *text == '-' || *end != '\0' || errno != 0 || v < lo ||
        v > hi) {
        std::fprintf(stderr,
                     "noneuclid: %s needs a whole number from %llu to %llu, not '%s'.\n",
                     option, lo, hi, text ? text : "");
        std::exit(2);
    }
    return v;
}

const char* format_arg(char* buf, std::size_t n, const noneuclid::fx::AccuracyRow& r,
                       const double* arg) {
    if (r.two_args)
        std::snprintf(buf, n, "(%.6g, %.6g)", arg[0], arg[1]);
    else
        std::snprintf(buf, n, "%.9g", arg[0]);
    return buf;
}

// The geometry engines at the screen: a 1080-px disk, limit radius pi = 540 px.
bool print_geometry_report() {
    using namespace noneuclid::geo;
    const GeometryReportOptions o;
    std::vector<ScreenErrorRow> rows(static_cast<std::size_t>(screen_error_row_count()));
    const int n = measure_screen_error(o, rows.data(), static_cast<int>(rows.size()));
    std::printf("\ngeometry at the screen: 1080-px disk (limit radius pi = 540 px), azimuthal "
                "equidistant;\n%d random bodies per K (centres inside the limit circle, edges at "
                "tessellation level 8),\nK swept over [-1, 1] in %d steps unless said; error in px "
                "against the engine named\n\n",
                o.bodies, o.k_steps);
    std::printf("%-7s %-9s %-12s %-20s %8s %5s  %-9s %-9s %-9s %-9s %-15s %-9s %s\n", "engine", "against",
                "points", "where", "samples", "NaN", "max px", "median", "p99", "p99.9", "max at K, r",
                "bound", "ok");
    bool all = true;
    for (int i = 0; i < n; ++i) {
        const ScreenErrorRow& r = rows[static_cast<std::size_t>(i)];
        char at[40], bound[16];
        std::snprintf(at, sizeof at, "%.4g, %.3g", r.at_K, r.at_r);
        if (r.bound_px > 0)
            std::snprintf(bound, sizeof bound, "%.2g", r.bound_px);
        else
            std::snprintf(bound, sizeof bound, "-");
        std::printf("%-7s %-9s %-12s %-20s %8ld %5ld  %-9.3g %-9.3g %-9.3g %-9.3g %-15s %-9s %s\n", r.engine,
                    r.against, r.what, r.where, r.samples, r.nonfinite, r.max_px, r.p50_px, r.p99_px,
                    r.p999_px, at, bound, r.bound_px > 0 ? (r.pass ? "yes" : "NO") : "-");
        all = all && r.pass;
    }
    std::vector<ContinuityRow> cont(static_cast<std::size_t>(continuity_row_count()));
    const int m = measure_continuity(o, cont.data(), static_cast<int>(cont.size()));
    std::printf("\ncontinuity through K = 0: the largest screen movement of any point of the scene\n\n");
    std::printf("%-22s %-46s %-10s %-9s %s\n", "engine", "between", "max px", "bound", "ok");
    for (int i = 0; i < m; ++i) {
        const ContinuityRow& r = cont[static_cast<std::size_t>(i)];
        char bound[16];
        if (r.bound_px > 0)
            std::snprintf(bound, sizeof bound, "%.2g", r.bound_px);
        else
            std::snprintf(bound, sizeof bound, "-");
        std::printf("%-22s %-46s %-10.3g %-9s %s\n", r.engine, r.what, r.max_px, bound,
                    r.bound_px > 0 ? (r.pass ? "yes" : "NO") : "-");
        all = all && r.pass;
    }
    std::vector<ShortDistanceRow> sd(static_cast<std::size_t>(short_distance_row_count()));
    const int k = measure_short_distance(o, sd.data(), static_cast<int>(sd.size()));
    std::printf("\nshort distances: relative error of the distance between two points this far apart,\n"
                "K in {-1, -0.5, -0.02, 0.02, 0.5, 1} (paper: acos/acosh of the law of cosines, no flat "
                "branch;\nfixed: error over the length, against the reference on the same rounded points; Q16.16 has\n"
                "no digits to spare below 1e-3, where one step is 1.5e-5)\n\n");
    std::printf("%-8s %-8s %-12s %s\n", "engine", "length", "max rel err", "NaN");
    for (int i = 0; i < k; ++i) {
        const ShortDistanceRow& r = sd[static_cast<std::size_t>(i)];
        std::printf("%-8s %-8.0e %-12.3g %ld\n", r.engine, r.length, r.max_rel, r.nonfinite);
    }
    return all;
}

int run_accuracy(const noneuclid::fx::AccuracyOptions& options) {
    using noneuclid::fx::AccuracyRow;
    std::vector<AccuracyRow> rows(static_cast<std::size_t>(noneuclid::fx::accuracy_row_count()));
    const int n = noneuclid::fx::measure_accuracy(options, rows.data(), static_cast<int>(rows.size()));

    std::printf("noneuclid %s: fixed-point (Q16.16, binary angle) functions against std:: double\n",
                kVersion);
    std::printf("samples per row: %ld evenly spaced (+%ld log-spaced where marked ~) + %ld random "
                "(seed %llu)\n",
                options.dense, options.dense, options.random,
                static_cast<unsigned long long>(options.seed));
    std::printf("rows with a floor: relative error where |reference| >= floor, absolute below it;\n"
                "other rows: absolute error everywhere. Errors in radians for angles.\n"
                "asserted bound: what tests/accuracy holds; required: the ceiling asked for.\n\n");
    std::printf("%-15s %-19s %8s  %-10s %-18s  %-10s %-18s %-5s  %-21s %-9s %s\n", "function",
                "domain", "samples", "max abs", "at", "max rel", "at", "floor", "asserted bound",
                "required", "ok");
    bool all = true;
    for (int i = 0; i < n; ++i) {
        const AccuracyRow& r = rows[static_cast<std::size_t>(i)];
        char a1[48], a2[48], rel[16], bound[40], req[16], floor_[24];
        const bool has_rel = r.rel_floor > 0 || r.rel_bound > 0;
        if (has_rel) {
            std::snprintf(rel, sizeof rel, "%.2e", r.max_rel);
            format_arg(a2, sizeof a2, r, r.arg_rel);
            std::snprintf(floor_, sizeof floor_, "%g", r.rel_floor);
        } else {
            std::snprintf(rel, sizeof rel, "-");
            std::snprintf(a2, sizeof a2, "-");
            std::snprintf(floor_, sizeof floor_, "-");
        }
        if (r.abs_bound > 0 && r.rel_bound > 0)
            std::snprintf(bound, sizeof bound, "abs %.1e, rel %.1e", r.abs_bound, r.rel_bound);
        else if (r.abs_bound > 0)
            std::snprintf(bound, sizeof bound, "abs %.1e", r.abs_bound);
        else
            std::snprintf(bound, sizeof bound, "rel %.1e", r.rel_bound);
        if (r.required > 0)
            std::snprintf(req, sizeof req, "%s %.0e", r.required_is_rel ? "rel" : "abs", r.required);
        else
            std::snprintf(req, sizeof req, "-");
        char abs_[16];
        if (r.abs_samples > 0) {
            std::snprintf(abs_, sizeof abs_, "%.2e", r.max_abs);
            format_arg(a1, sizeof a1, r, r.arg_abs);
        } else {
            std::snprintf(abs_, sizeof abs_, "-");
            std::snprintf(a1, sizeof a1, "-");
        }
        std::printf("%-15s %-19s %8ld  %-10s %-18s  %-10s %-18s %-5s  %-21s %-9s %s\n",
                    r.function, r.domain, r.samples, abs_, a1, rel, a2, floor_, bound, req,
                    r.pass ? "yes" : "NO");
        all = all && r.pass;
    }
    std::printf("\nlookup tables: %zu bytes (%.1f KiB) of read-only data, built at compile time\n",
                noneuclid::fx::tables::table_bytes,
                static_cast<double>(noneuclid::fx::tables::table_bytes) / 1024.0);
    all = print_geometry_report() && all;
    std::printf("\n%s\n", all ? "all rows within their asserted bounds"
                              : "SOME ROWS MISS THEIR BOUNDS (marked NO)");
    return all ? 0 : 1;
}


// ---- dump ------------------------------------------------------------------------------------

struct DumpArgs {
    std::string scene = "kiosk";
    bool has_curvature = false;
    double curvature = 0;
    long frames = 60;
    double dt = 1.0 / 60;
    std::string engine = "fixed";
    std::string actions;
    noneuclid::world::DumpOptions dump;
    noneuclid::world::SceneParams params;
    // render
    std::string out;
    noneuclid::render::PixelFormat format = noneuclid::render::PixelFormat::xrgb8888();
    bool aa = false;
    double line_width = 1;
    long timelapse = 0;
    bool hud = false;
};

[[noreturn]] void usage_error(const std::string& message) {
    std::fprintf(stderr, "noneuclid: %s\n", message.c_str());
    std::exit(2);
}

double parse_number(const char* option, const char* text, double lo, double hi) {
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (*text == '\0' || *end != '\0' || !(v >= lo && v <= hi))
        usage_error(std::string(option) + " needs a number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                    ", not '" + text + "'.");
    return v;
}

// A built-in scene or a TOML scene file; on failure prints one sentence and returns false.
bool load_scene(const std::string& name, const noneuclid::world::SceneParams& params, noneuclid::world::Scene& scene) {
    using namespace noneuclid::world;
    if (builtin_scene(name, params, scene)) return true;
    SceneError err;
    if (load_scene_file(name, scene, err)) return true;
    if (err.line == 0 && name.find('/') == std::string::npos && name.find(".toml") == std::string::npos) {
        std::string names;
        for (const char* const* n = builtin_scene_names(); *n; ++n) names += std::string(names.empty() ? "" : ", ") + *n;
        usage_error("no built-in scene '" + name + "' and no scene file by that name: the built-in scenes are " + names + ".");
    }
    std::fprintf(stderr, "%s\n", err.to_string().c_str());
    return false;
}

template <class W>
int run_dump(const noneuclid::world::Scene& scene, const DumpArgs& a,
             const std::vector<noneuclid::world::ActionEvent>& events) {
    using T = typename W::scalar;
    W world(scene);
    std::string line;
    std::size_t next = noneuclid::world::apply_actions(world, events, 0, 0.0);
    noneuclid::world::dump_frame(world, a.dump, line);
    std::fwrite(line.data(), 1, line.size(), stdout);
    const T dt(a.dt);
    for (long f = 0; f < a.frames; ++f) {
        world.step(dt);
        next = noneuclid::world::apply_actions(world, events, next, world.time);
        line.clear();
        noneuclid::world::dump_frame(world, a.dump, line);
        if (std::fwrite(line.data(), 1, line.size(), stdout) != line.size()) return 1;
    }
    return std::fflush(stdout) == 0 ? 0 : 1;
}

// Runs the scene and draws its last frame (or, with --timelapse, every EVERY-th frame's bodies
// over the last frame's grid), then writes the PNG.
template <class W>
int run_render(const noneuclid::world::Scene& scene, const DumpArgs& a,
               const std::vector<noneuclid::world::ActionEvent>& events) {
    namespace r = noneuclid::render;
    W world(scene);
    const int w = a.dump.width, h = a.dump.height;
    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(w) * a.format.bytes_per_pixel();
    std::vector<uint8_t> pixels(static_cast<std::size_t>(stride) * static_cast<std::size_t>(h));
    const r::Canvas canvas(pixels.data(), w, h, stride, a.format);
    r::RenderJob job;
    job.frames = a.frames;
    job.dt = a.dt;
    job.timelapse = a.timelapse;
    job.draw.projection = a.dump.projection;
    job.draw.antialias = a.aa;
    job.draw.line_width = static_cast<int32_t>(a.line_width * r::kSub + 0.5);
    r::render_scene(world, canvas, job, events);
    if (a.hud) {
        r::HudInfo info;
        info.K = static_cast<double>(world.K);
        info.scene = scene.name.c_str();
        info.projection = noneuclid::geo::projection_name(a.dump.projection);
#if NONEUCLID_HAVE_DESKTOP
        std::string note;
        const noneuclid::platform::LoadedFont font = noneuclid::platform::default_hud_font(&note);
        r::draw_hud(canvas, font.font, info);
#else
        r::draw_hud(canvas, r::builtin_font(), info);
#endif
    }
#if NONEUCLID_HAVE_PNG
    std::string error;
    if (!noneuclid::platform::write_png(a.out, canvas, error)) {
        std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
        return 1;
    }
    std::fprintf(stderr, "noneuclid: wrote %s (%dx%d, %s, K = %.3f, frame %ld)\n", a.out.c_str(), w, h, a.format.name,
                 static_cast<double>(world.K), world.frame);
    return 0;
#else
    std::fprintf(stderr, "noneuclid: this build has no PNG support (libpng was not found when it was built): "
                         "install libpng-dev and rebuild.\n");
    return 1;
#endif
}

// Option values shared by dump, render and run: one sentence and exit 2 when they are wrong.
void parse_size(const char* v, int& width, int& height) {
    int w = 0, h = 0;
    char tail = 0;
    if (std::sscanf(v, "%dx%d%c", &w, &h, &tail) != 2 || w < 16 || h < 16 || w > 16384 || h > 16384)
        usage_error(std::string("--size needs WIDTHxHEIGHT in pixels, 16 to 16384 each (e.g. 800x480), not '") + v + "'.");
    width = w, height = h;
}
std::string parse_engine(const char* v) {
    const std::string e = v;
    if (e != "fixed" && e != "double" && e != "float" && e != "paper")
        usage_error("--engine must be fixed, double, float or paper, not '" + e + "'.");
    return e;
}
noneuclid::geo::Projection parse_projection(const char* v) {
    for (noneuclid::geo::Projection pr : noneuclid::geo::kProjections)
        if (std::string(v) == noneuclid::geo::projection_name(pr)) return pr;
    usage_error(std::string("--projection must be equidistant, stereographic, gnomonic, orthographic or lambert, not '") + v + "'.");
}

int world_command(int argc, char** argv, int i, bool render);

int dump_command(int argc, char** argv, int i) { return world_command(argc, argv, i, false); }

int world_command(int argc, char** argv, int i, bool render) {
    using namespace noneuclid::world;
    DumpArgs a;
    const char* command = render ? "render" : "dump";
    for (; i < argc; ++i) {
        const std::string opt = argv[i];
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) usage_error(opt + " needs a value; see 'noneuclid --help'.");
            return argv[++i];
        };
        if (opt == "-h" || opt == "--help") {
            print_help(stdout);
            return 0;
        } else if (opt == "--scene") {
            a.scene = value();
        } else if (opt == "--curvature") {
            a.has_curvature = true;
            a.curvature = parse_number("--curvature", value(), -1, 1);
        } else if (opt == "--frames") {
            a.frames = static_cast<long>(parse_count("--frames", value(), 0, 100000000));
        } else if (opt == "--dt") {
            a.dt = parse_number("--dt", value(), 1e-4, 1);
        } else if (opt == "--engine") {
            a.engine = parse_engine(value());
        } else if (opt == "--actions") {
            a.actions = value();
        } else if (opt == "--size") {
            parse_size(value(), a.dump.width, a.dump.height);
        } else if (opt == "--projection") {
            a.dump.projection = parse_projection(value());
        } else if (opt == "--bodies") {
            a.params.bodies = static_cast<int>(parse_count("--bodies", value(), 1, 100000));
        } else if (opt == "--vertices") {
            a.params.vertices = static_cast<int>(parse_count("--vertices", value(), 1, 10000));
        } else if (opt == "--tessellation") {
            a.params.tessellation = static_cast<int>(parse_count("--tessellation", value(), 1, 256));
        } else if (render && opt == "--out") {
            a.out = value();
        } else if (render && opt == "--format") {
            const std::string f = value();
            if (f == "xrgb8888") a.format = noneuclid::render::PixelFormat::xrgb8888();
            else if (f == "rgb565") a.format = noneuclid::render::PixelFormat::rgb565();
            else if (f == "rgb888") a.format = noneuclid::render::PixelFormat::rgb888();
            else usage_error("--format must be xrgb8888, rgb565 or rgb888, not '" + f + "'.");
        } else if (render && opt == "--aa") {
            a.aa = true;
        } else if (render && opt == "--width") {
            a.line_width = parse_number("--width", value(), 0.1, 64);
        } else if (render && opt == "--hud") {
            a.hud = true;
        } else if (render && opt == "--timelapse") {
            a.timelapse = static_cast<long>(parse_count("--timelapse", value(), 1, 100000000));
        } else {
            usage_error("unknown option '" + opt + "' for " + command + "; see 'noneuclid --help'.");
        }
    }
    if (render && a.out.empty()) usage_error("render needs --out FILE.png: where to write the picture.");
    Scene scene;
    if (!load_scene(a.scene, a.params, scene)) return 2;
    if (a.has_curvature) scene.curvature = a.curvature;
    std::vector<ActionEvent> events;
    if (!a.actions.empty()) {
        ActionError err;
        if (!load_actions_file(a.actions, events, err)) {
            std::fprintf(stderr, "%s\n", err.to_string().c_str());
            return 2;
        }
    }
    if (render) {
        if (a.engine == "double") return run_render<World<double>>(scene, a, events);
        if (a.engine == "float") return run_render<World<float>>(scene, a, events);
        if (a.engine == "paper") return run_render<World<double, true>>(scene, a, events);
        return run_render<World<noneuclid::fx::fixed>>(scene, a, events);
    }
    if (a.engine == "double") return run_dump<World<double>>(scene, a, events);
    if (a.engine == "float") return run_dump<World<float>>(scene, a, events);
    if (a.engine == "paper") return run_dump<World<double, true>>(scene, a, events);
    return run_dump<World<noneuclid::fx::fixed>>(scene, a, events);
}

}  // namespace

// `noneuclid demo` (also what the program does with no command): renders the kiosk scene and
// the paper's time-lapse figures into a directory as PNG files, and says where.
int demo_command(int argc, char** argv, int i) {
    std::string dir = "out";
    for (; i < argc; ++i) {
        const std::string opt = argv[i];
        if (opt == "--out-dir" && i + 1 < argc) dir = argv[++i];
        else if (opt == "-h" || opt == "--help") return print_help(stdout), 0;
        else usage_error("unknown option '" + opt + "' for demo; see 'noneuclid --help'.");
    }
#if !NONEUCLID_HAVE_PNG
    usage_error("this build has no PNG support (libpng was not found when it was built): install libpng-dev and rebuild.");
#endif
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) usage_error("cannot create the directory '" + dir + "': " + ec.message() + ".");
    struct Picture {
        const char* file;
        std::vector<std::string> args;
    };
    const Picture pictures[] = {
        {"kiosk.png", {"--scene", "kiosk", "--frames", "120", "--aa", "--hud", "--size", "800x480"}},
        {"fig14.png", {"--scene", "fig14", "--frames", "600", "--timelapse", "40", "--size", "600x600"}},
        {"fig15.png", {"--scene", "fig15", "--frames", "600", "--timelapse", "40", "--size", "600x600"}},
        {"fig16.png", {"--scene", "fig16", "--frames", "120", "--timelapse", "15", "--size", "600x600"}},
        {"fig17.png", {"--scene", "fig17", "--frames", "250", "--timelapse", "25", "--size", "600x600", "--hud"}},
    };
    for (const Picture& p : pictures) {
        std::vector<std::string> words = p.args;
        words.push_back("--out");
        words.push_back(dir + "/" + p.file);
        std::vector<char*> av{argv[0]};
        for (std::string& w : words) av.push_back(w.data());
        const int rc = world_command(static_cast<int>(av.size()), av.data(), 1, true);
        if (rc != 0) return rc;
    }
    std::printf("noneuclid: the demo is in %s/: kiosk.png (the kiosk's picture with its HUD) and fig14.png .. "
                "fig17.png (the paper's time-lapse figures). 'noneuclid --help' lists the commands.\n",
                dir.c_str());
    return 0;
}

// `noneuclid run`: the scene live in a window (X11), or the demo's PNG files without one.
#if NONEUCLID_HAVE_FBDEV
// The board: --board, else the one matching this machine, else generic. Exits 2 with one
// sentence if it cannot be read.
noneuclid::world::Board board_for(const std::string& spec) {
    noneuclid::world::Board board;
    std::string error, why;
    if (!spec.empty()) {
        if (!noneuclid::platform::load_board(spec, board, error)) usage_error(error + ".");
        std::fprintf(stderr, "noneuclid: board %s (%s)\n", board.name.c_str(), board.file.c_str());
    } else {
        if (!noneuclid::platform::detect_board(board, why, error)) usage_error(error + ".");
        std::fprintf(stderr, "noneuclid: %s.\n", why.c_str());
    }
    return board;
}
#endif

#if NONEUCLID_HAVE_INPUT
// The board's buttons as input sources: `mode` gpio, evdev, none or auto (GPIO if the board
// wires any, plus key devices if it names keys and one is present). Returns false after one
// sentence on stderr.
bool open_inputs(const noneuclid::world::Board& b, const std::string& mode,
                 std::vector<std::unique_ptr<noneuclid::platform::InputSource>>& out) {
    namespace p = noneuclid::platform;
    if (mode == "none") return true;
    const bool want_gpio = mode == "gpio" || (mode == "auto" && b.has_gpio());
    const bool want_keys = mode == "evdev" || (mode == "auto" && b.has_keys());
    if (mode == "gpio" && !b.has_gpio()) {
        std::fprintf(stderr, "noneuclid: the board %s (%s) wires no GPIO buttons: add 'gpio = N' to its [[button]] tables, or use --input evdev.\n",
                     b.name.c_str(), b.file.c_str());
        return false;
    }
    if (mode == "evdev" && !b.has_keys()) {
        std::fprintf(stderr, "noneuclid: the board %s (%s) names no key codes: add 'key = N' to its [[button]] tables, or use --input gpio.\n",
                     b.name.c_str(), b.file.c_str());
        return false;
    }
    std::string error;
    if (want_gpio) {
        p::GpioConfig g;
        g.chips = b.chips;
        g.debounce_ms = static_cast<unsigned>(b.debounce_ms);
        for (const auto& bb : b.buttons)
            if (bb.gpio >= 0) g.buttons.push_back({bb.control, static_cast<unsigned>(bb.gpio), bb.pin});
        auto src = p::open_gpio(g, error);
        if (!src) {
            std::fprintf(stderr, "noneuclid: %s.\n", error.c_str());
            return false;
        }
        std::fprintf(stderr, "noneuclid: %s\n", src->describe().c_str());
        out.push_back(std::move(src));
    }
    if (want_keys) {
        p::EvdevConfig e;
        e.device = b.evdev_device;
        e.grab = b.grab;
        for (const auto& bb : b.buttons)
            if (bb.key >= 0) e.keys.push_back({bb.control, static_cast<unsigned>(bb.key)});
        auto src = p::open_evdev(e, error);
        if (!src) {
            if (mode == "evdev" || !want_gpio) {
                std::fprintf(stderr, "noneuclid: %s.\n", error.c_str());
                return false;
            }
            std::fprintf(stderr, "noneuclid: no keys (%s); the GPIO buttons are enough.\n", error.c_str());
        } else {
            std::fprintf(stderr, "noneuclid: %s\n", src->describe().c_str());
            out.push_back(std::move(src));
        }
    }
    return true;
}
#endif

std::string parse_input_mode(const std::string& v) {
    if (v == "auto" || v == "gpio" || v == "evdev" || v == "none") return v;
    usage_error("--input must be auto, gpio, evdev or none, not '" + v + "'.");
}

// `noneuclid buttons`: what each button or key sends, one line per event.
int buttons_command(int argc, char** argv, int i) {
    std::string board_spec, mode = "auto";
    long events = 0;
    double timeout = 0;
    for (; i < argc; ++i) {
        const std::string opt = argv[i];
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) usage_error(opt + " needs a value; see 'noneuclid --help'.");
            return argv[++i];
        };
        if (opt == "-h" || opt == "--help") return print_help(stdout), 0;
        else if (opt == "--board") board_spec = value();
        else if (opt == "--input") mode = parse_input_mode(value());
        else if (opt == "--events") events = static_cast<long>(parse_count("--events", value(), 1, 1000000000));
        else if (opt == "--timeout") timeout = parse_number("--timeout", value(), 0.001, 1e7);
        else usage_error("unknown option '" + opt + "' for buttons; see 'noneuclid --help'.");
    }
#if NONEUCLID_HAVE_FBDEV && NONEUCLID_HAVE_INPUT
    const noneuclid::world::Board board = board_for(board_spec);
    if (mode == "none") usage_error("buttons needs an input: --input gpio, evdev or auto.");
    std::vector<std::unique_ptr<noneuclid::platform::InputSource>> inputs;
    if (!open_inputs(board, mode, inputs)) return 2;
    if (inputs.size() != 1) {
        if (inputs.empty()) usage_error("the board has no buttons to listen to: give it [[button]] tables.");
        std::fprintf(stderr, "noneuclid: listening to the first input only; choose with --input gpio or evdev.\n");
    }
    return noneuclid::platform::print_input_events(*inputs.front(), events, timeout, stdout);
#else
    (void)events, (void)timeout;
    (void)board_spec;
    usage_error("this build has no kiosk input (it was built without Linux GPIO and evdev support): build it on Linux with libgpiod-dev installed.");
#endif
}

int run_command(int argc, char** argv, int i) {
    using noneuclid::platform::DisplayKind;
    std::string display, fb_device, board_spec, input_mode = "auto", record;
    std::optional<std::string> scene_name, engine;
    std::optional<noneuclid::geo::Projection> projection;
    std::optional<double> fps, attract;
    std::optional<int> threads;
    std::optional<bool> aa, hud;
    bool has_curvature = false, stats = false;
    double curvature = 0;
    long frames = 0;
    int width = 800, height = 480;
    std::string screenshot;
    for (; i < argc; ++i) {
        const std::string opt = argv[i];
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) usage_error(opt + " needs a value; see 'noneuclid --help'.");
            return argv[++i];
        };
        if (opt == "-h" || opt == "--help") {
            print_help(stdout);
            return 0;
        } else if (opt == "--display") {
            display = value();
            if (display.rfind("fbdev:", 0) == 0) {
                fb_device = display.substr(6);
                display = "fbdev";
                if (fb_device.empty()) usage_error("--display fbdev: needs a device after the colon, e.g. fbdev:/dev/fb1.");
            }
            if (display != "x11" && display != "fbdev" && display != "png")
                usage_error("--display must be x11, fbdev, fbdev:/dev/fbN or png, not '" + display + "'.");
        } else if (opt == "--scene") {
            scene_name = value();
        } else if (opt == "--curvature") {
            has_curvature = true;
            curvature = parse_number("--curvature", value(), -1, 1);
        } else if (opt == "--frames") {
            frames = static_cast<long>(parse_count("--frames", value(), 1, 100000000));
        } else if (opt == "--fps") {
            fps = parse_number("--fps", value(), 1, 1000);
        } else if (opt == "--size") {
            parse_size(value(), width, height);
        } else if (opt == "--aa") {
            aa = true;
        } else if (opt == "--no-hud") {
            hud = false;
        } else if (opt == "--stats") {
            stats = true;
        } else if (opt == "--engine") {
            engine = parse_engine(value());
        } else if (opt == "--projection") {
            projection = parse_projection(value());
        } else if (opt == "--screenshot") {
            screenshot = value();
        } else if (opt == "--board") {
            board_spec = value();
        } else if (opt == "--input") {
            input_mode = parse_input_mode(value());
        } else if (opt == "--record") {
            record = value();
        } else if (opt == "--attract") {
            attract = parse_number("--attract", value(), 0, 1e7);
        } else if (opt == "--threads") {
            threads = static_cast<int>(parse_count("--threads", value(), 1, 16));
        } else {
            usage_error("unknown option '" + opt + "' for run; see 'noneuclid --help'.");
        }
    }
    DisplayKind kind = DisplayKind::png;
    std::string reason;
    if (!display.empty()) {
        kind = display == "x11" ? DisplayKind::x11 : (display == "fbdev" ? DisplayKind::fbdev : DisplayKind::png);
        reason = "--display " + display + " asked for it";
    } else {
        const noneuclid::platform::DisplayChoice c = noneuclid::platform::choose_display();
        kind = c.display, reason = c.reason;
    }
    const char* kind_name = kind == DisplayKind::x11 ? "x11" : (kind == DisplayKind::fbdev ? "fbdev" : "png");
    std::fprintf(stderr, "noneuclid: display %s, because %s.\n", kind_name, reason.c_str());
    if (kind != DisplayKind::fbdev && (!record.empty() || !board_spec.empty() || attract || threads || input_mode != "auto"))
        usage_error("--board, --input, --attract, --threads and --record are for the framebuffer kiosk: add --display fbdev.");
    if (kind == DisplayKind::png) return demo_command(argc, argv, argc);
    if (kind == DisplayKind::fbdev) {
#if NONEUCLID_HAVE_FBDEV
        const noneuclid::world::Board board = board_for(board_spec);
        noneuclid::world::Scene scene;
        if (!load_scene(scene_name.value_or(board.scene), noneuclid::world::SceneParams{}, scene)) return 2;
        if (has_curvature) scene.curvature = curvature;
        noneuclid::platform::KioskOptions o;
        o.device = fb_device.empty() ? board.device : fb_device;
        o.frames = frames;
        o.fps = fps.value_or(board.fps);
        o.antialias = aa.value_or(board.antialias);
        o.hud = hud.value_or(board.hud);
        o.engine = engine.value_or(board.engine);
        o.projection = projection ? *projection : parse_projection(board.projection.c_str());
        o.attract.idle_seconds = attract.value_or(board.idle_seconds);
        o.attract.sweep_seconds = board.sweep_seconds;
        o.threads = threads.value_or(board.threads);
        o.record = record;
        o.stats = stats;
        std::vector<std::unique_ptr<noneuclid::platform::InputSource>> inputs;
#if NONEUCLID_HAVE_INPUT
        if (!open_inputs(board, input_mode, inputs)) return 2;
#else
        if (input_mode == "gpio" || input_mode == "evdev")
            usage_error("this build has no kiosk input (libgpiod-dev was not found when it was built): install it and rebuild, or use --input none.");
#endif
        if (inputs.empty()) std::fprintf(stderr, "noneuclid: no buttons: the world runs on its own (attract mode after %.0f s).\n", o.attract.idle_seconds);
        return noneuclid::platform::run_fbdev(scene, o, inputs);
#else
        usage_error("this build has no framebuffer display (it was not built for Linux): use --display x11 or png.");
#endif
    }
    noneuclid::world::Scene scene;
    if (!load_scene(scene_name.value_or("kiosk"), noneuclid::world::SceneParams{}, scene)) return 2;
    if (has_curvature) scene.curvature = curvature;
#if NONEUCLID_HAVE_X11
    noneuclid::platform::RunOptions o;
    o.width = width, o.height = height, o.frames = frames, o.fps = fps.value_or(60), o.antialias = aa.value_or(false);
    o.hud = hud.value_or(true);
    o.engine = engine.value_or("fixed"), o.projection = projection.value_or(noneuclid::geo::Projection::azimuthal_equidistant);
    o.screenshot = screenshot, o.stats = stats;
    return noneuclid::platform::run_x11(scene, o);
#else
    (void)frames, (void)width, (void)height, (void)stats;
    usage_error("this build has no X11 window (Xlib was not found when it was built): install libx11-dev and libxext-dev and rebuild, or use --display png.");
#endif
}

int main(int argc, char** argv) {
    if (argc == 1) return demo_command(argc, argv, 1);
    if (std::strcmp(argv[1], "demo") == 0) return demo_command(argc, argv, 2);
    if (std::strcmp(argv[1], "run") == 0) return run_command(argc, argv, 2);
    if (std::strcmp(argv[1], "buttons") == 0) return buttons_command(argc, argv, 2);
    noneuclid::fx::AccuracyOptions options;
    int i = 1;
    if (i < argc && std::strcmp(argv[i], "dump") == 0) return dump_command(argc, argv, i + 1);
    if (i < argc && std::strcmp(argv[i], "render") == 0) return world_command(argc, argv, i + 1, true);
    if (i < argc && std::strcmp(argv[i], "accuracy") == 0) ++i;
    for (; i < argc; ++i) {
        const char* a = argv[i];
        auto value = [&](const char* name) -> const char* {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "noneuclid: %s needs a value; see 'noneuclid --help'.\n", name);
                std::exit(2);
            }
            return argv[++i];
        };
        if (std::strcmp(a, "-h") == 0 || std::strcmp(a, "--help") == 0) {
            print_help(stdout);
            return 0;
        } else if (std::strcmp(a, "--version") == 0) {
            std::printf("noneuclid %s\n", kVersion);
            return 0;
        } else if (std::strcmp(a, "--samples") == 0) {
            options.dense = static_cast<long>(parse_count(a, value(a), 2, 100000000));
        } else if (std::strcmp(a, "--random") == 0) {
            options.random = static_cast<long>(parse_count(a, value(a), 0, 100000000));
        } else if (std::strcmp(a, "--seed") == 0) {
            options.seed = parse_count(a, value(a), 0, ~0ull);
        } else if (a[0] == '-') {
            std::fprintf(stderr, "noneuclid: unknown option '%s'; see 'noneuclid --help'.\n", a);
            return 2;
        } else {
            std::fprintf(stderr, "noneuclid: unknown command '%s'; see 'noneuclid --help'.\n", a);
            return 2;
        }
    }
    return run_accuracy(options);
}
