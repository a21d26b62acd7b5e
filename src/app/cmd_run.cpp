// `noneuclid run`: a scene live on a display (app/displays.hpp: the X11 window, the kiosk's
// framebuffer, or the headless PNG display), through the one frame loop.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <system_error>

#include "app/commands.hpp"
#include "app/displays.hpp"
#include "app/run.hpp"
#include "app/lesson.hpp"
#include "app/setup.hpp"

namespace noneuclid::app {

namespace {

// The display asked for, or the one that fits this machine; said in one line.
const DisplayRow& display_for(const Options& given) {
    platform::DisplayChoice c;
    const DisplayRow* row = nullptr;
    if (given.display.empty()) {
        c = platform::choose_display();
        row = display_row(c.display);
    } else {
        row = display_named(given.display);
        c.reason = "--display " + given.display + " asked for it";
    }
    if (!row) usage_error("this build has no display for " + c.reason + ": give --display.");
    std::fprintf(stderr, "noneuclid: display %s, because %s.\n", row->name, c.reason.c_str());
    return *row;
}

// What `run` and a lesson share: the options layered (the board's on the kiosk), the display
// chosen and, for the headless one, its defaults. The display is opened by the caller, once the
// scene is known to load.
struct RunSetup {
    const DisplayRow* shown = nullptr;
    files::Board board;
    Script script;
    Options o;
    bool size_given = false;  // --size on the command line
};
void set_up_run(int argc, char** argv, int first, RunSetup& r) {
    Options given = defaults(Command::run);
    {
        Args args(argc, argv, first);
        parse_options(args, given, Command::run);
    }
    check_outputs(given);  // --record and --screenshot come from the command line only
    r.shown = &display_for(given);
    if (r.shown->kiosk) {
        std::string note, error;
        if (!platform::find_board(given.board, r.board, note, error)) usage_error(error + ".");
        std::fprintf(stderr, "noneuclid: %s.\n", note.c_str());
    } else if (!given.board.empty() || given.input != "auto") {
        usage_error("--board and --input are the kiosk's buttons: add --display fbdev.");
    }
    r.o = layered_options(argc, argv, first, Command::run, r.script, r.shown->kiosk ? &r.board : nullptr);
    Options& o = r.o;
    if (r.shown->kind == platform::DisplayKind::png) {
        if (o.frames == 0) o.frames = 600;  // ten seconds of world time: nobody is there to close it
        if (!o.attract_given) o.attract = 1;  // nor at the keys: the autopilot flies
        if (o.screenshot.empty()) {
            o.screenshot = "out/run.png";
            check_output("--screenshot", o.screenshot, ".png", "a PNG");
        }
    }
    r.size_given = given.size_given;
}

// The run's sound if it asks for it (--sound, the board's sound), said in one line; a device that
// cannot be opened, or a build without sound, is said too, and the run goes on silent.
std::unique_ptr<SoundOut> open_run_sound(const Options& o) {
    if (!o.sound) return nullptr;
    platform::SoundSpec spec;
    spec.device = o.sound_device;
    std::string error;
    std::unique_ptr<SoundOut> sound = platform::open_sound(spec, error);
    if (sound) std::fprintf(stderr, "noneuclid: sound on '%s' (N mutes it).\n", spec.device.c_str());
    else std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
    return sound;
}

// The lesson on the display r chose.
int play_lesson_on(const files::Lesson& lesson, RunSetup& r) {
    {
        LiveRun check;  // every step's scene loads before the display opens: a bad one is said first
        for (std::size_t i = 0; i < lesson.steps.size(); ++i)
            if (!lesson.steps[i].scene.empty()) {
                Options s = r.o;
                s.scene = lesson.steps[i].scene;
                prepare_run(check, s);
            }
    }
    std::string error;
    std::unique_ptr<Display> display = r.shown->open(r.o, r.board, error);
    if (!display) {
        std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
        return 2;
    }
    LessonPlayer player(lesson, r.o, *display, r.shown->name);
    while (player.tick()) {
    }
    const int status = player.finish();
    display.reset();
    return status;
}

}  // namespace

int play_lesson(const files::Lesson& lesson, int argc, char** argv, int first) {
    RunSetup r;
    set_up_run(argc, argv, first, r);
    return play_lesson_on(lesson, r);
}

int run_command(int argc, char** argv, int first) {
    RunSetup r;
    set_up_run(argc, argv, first, r);
    if (!r.o.lesson.empty()) return play_lesson_on(load_lesson(r.o.lesson, resolve_language(r.o)), r);
    const DisplayRow& shown = *r.shown;
    files::Board& board = r.board;
    Script& script = r.script;
    Options& o = r.o;
    const bool size_given = r.size_given;
    LiveRun run;
    prepare_run(run, o);
    std::unique_ptr<files::Lesson> attract_lesson;
    if (!o.attract_lesson.empty()) {
        if (!o.record.empty() || !o.actions.empty())
            usage_error("--attract-lesson starts a new run for each visitor: it cannot be recorded or replayed (drop --record or --actions).");
        attract_lesson = std::make_unique<files::Lesson>(load_lesson(o.attract_lesson, resolve_language(o)));
    }

    std::string error;
    std::unique_ptr<Display> display = shown.open(o, board, error);
    if (!display) {
        std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
        return 2;
    }
    if (shown.kiosk && size_given)
        std::fprintf(stderr, "noneuclid: --size is left unused: the kiosk draws at the framebuffer's size, %dx%d.\n",
                     display->canvas().width(), display->canvas().height());

    // The recording goes to a temporary file beside it, renamed over it at the end: a run cut
    // short by an error leaves no half recording in its place (a stop signal ends the run
    // normally, and its recording is kept).
    platform::AtomicFile recording;
    if (!o.record.empty()) {
        std::string why;
        if (!recording.open(o.record, why)) {
            std::fprintf(stderr, "noneuclid: the recording: %s\n", why.c_str());
            return 2;
        }
    }
    const std::unique_ptr<HighScoreTable> scores = run.scene.game.on ? open_scores(o.scores, true) : nullptr;
    if (scores && !o.best_given) o.best = scores->best();
    int status = 0;
    if (attract_lesson) {  // attract mode plays a lesson (app/lesson.hpp)
        AttractLessonRun a(*attract_lesson, o, *display, shown.name, scores.get());
        const std::unique_ptr<SoundOut> sound = open_run_sound(o);
        a.set_sound(sound.get());
        while (a.tick()) {
        }
        status = a.finish();
    } else {
        compose_run(run, o, script, *display, shown.name, recording.file(), scores.get());
        const std::unique_ptr<SoundOut> sound = open_run_sound(o);
        run.loop->set_sound(sound.get());
        status = run.loop->run();
    }
    display.reset();  // the console back before the last lines
    std::string why;
    if (recording.file() && !recording.commit(why)) {
        std::fprintf(stderr, "noneuclid: the recording: %s\n", why.c_str());
        status = status ? status : 1;
    }
    return status;
}

}  // namespace noneuclid::app
