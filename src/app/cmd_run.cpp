// `noneuclid run`: a scene live on a display (the X11 window, the kiosk's framebuffer, or the
// headless PNG display), through the one frame loop.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>

#include "app/commands.hpp"
#include "app/frame_loop.hpp"
#include "app/high_scores.hpp"
#include "app/memory_display.hpp"
#include "app/setup.hpp"

namespace noneuclid::app {

namespace {

const char* display_name(platform::DisplayKind k) {
    static const char* const names[] = {"x11", "fbdev", "png"};
    return names[static_cast<int>(k)];
}

// The display asked for, or the one that fits this machine; said in one line.
platform::DisplayKind display_kind(const Options& given) {
    platform::DisplayChoice c;
    if (given.display.empty()) {
        c = platform::choose_display();
    } else {
        c.display = given.display == "x11" ? platform::DisplayKind::x11
                    : given.display == "fbdev" ? platform::DisplayKind::fbdev
                                               : platform::DisplayKind::png;
        c.reason = "--display " + given.display + " asked for it";
    }
    std::fprintf(stderr, "noneuclid: display %s, because %s.\n", display_name(c.display), c.reason.c_str());
    return c.display;
}

}  // namespace

int run_command(int argc, char** argv, int first) {
    Options given = defaults(Command::run);
    {
        Args args(argc, argv, first);
        parse_options(args, given, Command::run);
    }
    const platform::DisplayKind kind = display_kind(given);
    files::Board board;
    const bool kiosk = kind == platform::DisplayKind::fbdev;
    if (kiosk) {
        std::string note, error;
        if (!platform::find_board(given.board, board, note, error)) usage_error(error + ".");
        std::fprintf(stderr, "noneuclid: %s.\n", note.c_str());
    } else if (!given.board.empty() || given.input != "auto") {
        usage_error("--board and --input are the kiosk's buttons: add --display fbdev.");
    }
    Script script;
    Options o = layered_options(argc, argv, first, Command::run, script, kiosk ? &board : nullptr);
    if (kind == platform::DisplayKind::png) {
        if (o.frames == 0) o.frames = 600;  // ten seconds of world time: nobody is there to close it
        if (!o.attract_given) o.attract = 1;  // nor at the keys: the autopilot flies
        if (o.screenshot.empty()) o.screenshot = "out/run.png";
        std::error_code ec;
        const std::filesystem::path dir = std::filesystem::path(o.screenshot).parent_path();
        if (!dir.empty()) std::filesystem::create_directories(dir, ec);
    }
    const world::Scene scene = load_scene(o);
    const platform::LoadedFont font = load_font(o);

    std::unique_ptr<Display> display;
    std::string error;
    if (kind == platform::DisplayKind::x11) {
        display = platform::open_window({o.width, o.height}, error);
    } else if (kind == platform::DisplayKind::fbdev) {
        platform::KioskSpec spec;
        spec.device = o.device, spec.fps = o.fps, spec.board = board, spec.input = o.input;
        display = platform::open_kiosk(spec, error);
    } else {
        display = std::make_unique<MemoryDisplay>(o.width, o.height, o.format);
    }
    if (!display) {
        std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
        return 2;
    }
    if (o.legend.empty()) o.legend = display->legend();
    if (kiosk && given.size_given)
        std::fprintf(stderr, "noneuclid: --size is left unused: the kiosk draws at the framebuffer's size, %dx%d.\n",
                     display->canvas().width(), display->canvas().height());

    // The recording goes to a temporary file beside it, renamed over it at the end: a run cut
    // short by an error leaves no half recording in its place (a stop signal ends the run
    // normally, and its recording is kept).
    platform::AtomicFile recording;
    std::FILE* file = nullptr;
    if (!o.record.empty()) {
        std::string why;
        if (!recording.open(o.record, why)) {
            std::fprintf(stderr, "noneuclid: the recording: %s\n", why.c_str());
            return 2;
        }
        file = recording.file();
    }
    const std::unique_ptr<HighScoreTable> scores = scene.game.on ? open_scores(o.scores) : nullptr;
    if (scores && !o.best_given) o.best = scores->best();
    Recorder recorder(file);
    if (file) record_settings(recorder, o, display_name(kind), font, display->canvas().format());
    const std::unique_ptr<Session> session = make_session(o.engine, scene, session_options(o, scene, o.legend), font.font,
                                                          file ? &recorder : nullptr, scores.get());
    LoopOptions lo;
    lo.frames = o.frames, lo.fps = o.fps, lo.stats = o.stats, lo.screenshot = o.screenshot;
    FrameLoop loop(*display, *session, o.actions.empty() ? nullptr : &script, file ? &recorder : nullptr, lo);
    int status = loop.run();
    display.reset();  // the console back before the last lines
    std::string why;
    if (file && !recording.commit(why)) {
        std::fprintf(stderr, "noneuclid: the recording: %s\n", why.c_str());
        status = status ? status : 1;
    }
    return status;
}

}  // namespace noneuclid::app
