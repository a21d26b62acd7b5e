// What the web page calls (platform/web/page/page.js): `noneuclid run` in a browser. The page
// hands over the same option words as the command line (from its URL and its controls), with
// scene and actions files written into the module's memory file system; the one option reader
// (app/options.cpp) reads them, and the one frame loop (app/frame_loop.cpp) runs on the page's
// display, one tick per animation frame. Every run is recorded, as `run --record` would, so that
// the page can offer the recording and `noneuclid render --actions` can replay it.
#include <emscripten.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "app/lesson.hpp"
#include "app/setup.hpp"
#include "lang/lang.hpp"
#include "app/run.hpp"
#include "web_display.hpp"

namespace noneuclid::web {
namespace {

// The page's sound (docs/sound.md): each frame's samples from the synthesiser, which page.js
// (page/sound.js) plays with Web Audio. Made when the page turns sound on, at its AudioContext's
// rate; counts the cues it was given, for the page's tests.
class WebSound final : public app::SoundOut {
public:
    explicit WebSound(int rate) : synth_(rate), samples_(static_cast<std::size_t>(synth_.rate() / 4)) {}
    void frame(const app::SoundFrame& f, double seconds) override {
        synth_.apply(f);
        for (int i = 0; i < app::kCueCount; ++i) cues_ += f.has(static_cast<app::Cue>(i)) && !f.muted;
        world_ += seconds;
        const long long due = std::llround(world_ * synth_.rate());
        count_ = static_cast<int>(std::min<long long>(due - due_, static_cast<long long>(samples_.size())));
        due_ = due;
        synth_.render(samples_.data(), count_);
    }
    const int16_t* samples() const { return samples_.data(); }
    int count() const { return count_; }
    long cues() const { return cues_; }

private:
    app::Synth synth_;
    std::vector<int16_t> samples_;  // a quarter second at most a frame, made once
    double world_ = 0;
    long long due_ = 0;
    int count_ = 0;
    long cues_ = 0;
};

// One run: the page's display and recording, and the run composed on them (app/run.hpp), as
// long as the run.
struct Run {
    app::Script script;
    app::Options options;
    std::unique_ptr<WebDisplay> display;
    char* recording = nullptr;  // the recording so far (open_memstream)
    std::size_t recording_size = 0;
    std::FILE* recording_file = nullptr;
    app::LiveRun live;
    files::Lesson lesson_data;                  // ?lesson=: the lesson played instead of live
    std::unique_ptr<app::LessonPlayer> lesson;
    std::unique_ptr<WebSound> sound;            // while the page has sound on (not in a lesson)
    bool done = false;

    app::Session& session() { return lesson ? lesson->session() : *live.session; }
    const world::Scene& scene() const { return lesson ? lesson->scene() : live.scene; }

    ~Run() {
        lesson.reset();
        live.loop.reset(), live.session.reset(), live.recorder.reset();
        if (recording_file) std::fclose(recording_file);
        std::free(recording);
    }
};

std::unique_ptr<Run> g_run;
std::string g_message;

// Options of `run` that a page has no use for: one sentence each.
void refuse_options(const app::Options& o) {
    const app::Options d = app::defaults(app::Command::run);
    if (!o.display.empty()) app::usage_error("--display is not for a web page: the page is the display.");
    if (!o.board.empty() || o.input != d.input)
        app::usage_error("--board and --input are the kiosk's buttons: a web page has its keys and touch buttons.");
    if (!o.record.empty())
        app::usage_error("--record is not for a web page: it records every run; take the recording from its link.");
    if (!o.screenshot.empty())
        app::usage_error("--screenshot is not for a web page: save the picture from the page (right-click it).");
    if (!o.scores.empty() && o.scores != "none")
        app::usage_error("--scores is not for a web page: it keeps no files (--best sets the high score it shows).");
    if (o.threads != d.threads) app::usage_error("--threads is not for a web page: it draws on one thread.");
    if (o.fps != d.fps) app::usage_error("--fps is not for a web page: it draws at the screen's refresh rate.");
}

void start(const std::vector<std::string>& words, Run& run) {
    std::vector<char*> argv{const_cast<char*>("noneuclid")};
    for (const std::string& w : words) argv.push_back(const_cast<char*>(w.c_str()));
    app::Options& o = run.options;
    o = app::layered_options(static_cast<int>(argv.size()), argv.data(), 1, app::Command::run, run.script);
    refuse_options(o);
    if (!o.lesson.empty()) {  // a lesson: its steps on the page's display, not recorded
        run.lesson_data = app::load_lesson(o.lesson, app::resolve_language(o));
        run.display = std::make_unique<WebDisplay>(o.width, o.height, o.format);
        run.lesson = std::make_unique<app::LessonPlayer>(run.lesson_data, o, *run.display, "web");
        return;
    }
    app::prepare_run(run.live, o);
    run.display = std::make_unique<WebDisplay>(o.width, o.height, o.format);
    run.recording_file = open_memstream(&run.recording, &run.recording_size);
    app::compose_run(run.live, o, run.script, *run.display, "web", run.recording_file, nullptr);
}

// The action table's key word (world/action.hpp) as the page's KeyboardEvent.key: a printable
// character is itself; of the X11 names, those a page's keyboard has.
std::string page_key(std::string word) {
    if (word.size() == 1) return word;
    if (word == "Up" || word == "Left" || word == "Right") return "Arrow" + word;
    if (word == "space") return " ";
    if (word == "Escape") return word;
    if (word == "Control_L" || word == "Control_R") return "Control";
    return "";  // the keypad's: the page sees the character it types
}

bool running() { return g_run && !g_run->done; }

}  // namespace
}  // namespace noneuclid::web

using noneuclid::web::g_message;
using noneuclid::web::g_run;

extern "C" {

// Starts a run from option words separated by newlines ("--scene\nkiosk\n--curvature\n-1").
// 0 on success; 2 with one sentence in nw_message() for a bad word or file.
EMSCRIPTEN_KEEPALIVE int nw_start(const char* words) {
    g_run.reset();
    std::vector<std::string> list;
    for (const char *p = words, *q = words;; ++q) {
        if (*q == '\n' || *q == '\0') {
            if (q > p) list.emplace_back(p, q);
            if (*q == '\0') break;
            p = q + 1;
        }
    }
    auto run = std::make_unique<noneuclid::web::Run>();
    try {
        noneuclid::web::start(list, *run);
    } catch (const noneuclid::app::UsageError& e) {
        g_message = e.message;
        return 2;
    }
    g_run = std::move(run);
    g_message.clear();
    return 0;
}

// One frame. 1 while the run goes on; 0 once it has ended (frames reached, Esc, nw_stop).
EMSCRIPTEN_KEEPALIVE int nw_tick() {
    if (!noneuclid::web::running()) return 0;
    if (g_run->lesson) {
        if (g_run->lesson->tick()) return 1;
        g_run->done = true;
        g_message = g_run->lesson->finish() == 0 ? "" : "the lesson failed (see the console).";
        return 0;
    }
    if (g_run->live.loop->tick()) return 1;
    const int status = g_run->live.loop->finish();
    std::fflush(g_run->recording_file);
    g_run->done = true;
    g_message = status == 0 ? "" : "the run failed (see the console).";
    return 0;
}

// The run ends after the frame being drawn.
EMSCRIPTEN_KEEPALIVE void nw_stop() {
    if (noneuclid::web::running()) g_run->display->close();
}

// A control's number (world::Action) by name, or -1 if this build has none by that name.
EMSCRIPTEN_KEEPALIVE int nw_control(const char* name) {
    noneuclid::world::Action c{};
    return noneuclid::world::parse_action(name, c) ? static_cast<int>(c) : -1;
}

// A control pressed (1) or released (0): a touch button, the K slider.
EMSCRIPTEN_KEEPALIVE void nw_input(int control, int pressed) {
    if (!noneuclid::web::running() || control < 0 || control >= noneuclid::world::kActionCount) return;
    g_run->display->queue({static_cast<noneuclid::world::Action>(control), pressed != 0});
}

// A tap on the canvas at pixel (x, y): a mark of the live instrument there (turned on if it
// was off; world/instruments.hpp). 0 where the canvas shows no point of the world.
EMSCRIPTEN_KEEPALIVE int nw_mark(double x, double y) {
    if (!noneuclid::web::running()) return 0;
    const noneuclid::render::Canvas c = g_run->display->canvas();
    return g_run->session().mark_at(x, y, c.width(), c.height()) ? 1 : 0;
}

// The control a key (KeyboardEvent.key) stands for, or -1.
EMSCRIPTEN_KEEPALIVE int nw_key(const char* key) {
    for (int i = 0; i < noneuclid::world::kActionCount; ++i)
        if (noneuclid::world::any_key(i, [&](std::string_view w) { return noneuclid::web::page_key(std::string(w)) == key; }))
            return i;
    return -1;
}

// How many taps of the projection control turn the view to `name`; -1 for no such projection.
EMSCRIPTEN_KEEPALIVE int nw_projection_taps(const char* name) {
    namespace geo = noneuclid::geo;
    const int count = static_cast<int>(std::size(geo::kProjections));
    int now = 0, want = -1;
    for (int i = 0; i < count; ++i) {
        if (g_run && geo::kProjections[i] == g_run->session().options().draw.projection) now = i;
        if (std::string(name) == geo::projection_name(geo::kProjections[i])) want = i;
    }
    return want < 0 ? -1 : (want - now + count) % count;
}

// The built-in scenes' names, one a line.
EMSCRIPTEN_KEEPALIVE const char* nw_scenes() {
    static std::string names;
    if (names.empty())
        for (const std::string& n : noneuclid::world::builtin_scene_names()) names += n + "\n";
    return names.c_str();
}

// A menu's choices, one a line, "value<TAB>label", from the program's tables: "projection",
// "engine" or "language" (their menus on the page are these, so a new row is a new choice).
EMSCRIPTEN_KEEPALIVE const char* nw_choices(const char* menu) {
    static std::string lines;
    lines.clear();
    const std::string_view m = menu ? menu : "";
    if (m == "projection")
        for (const std::string& n : noneuclid::geo::projection_names()) lines += n + "\t" + n + "\n";
    if (m == "engine")
        for (const std::string& n : noneuclid::world::engine_names()) lines += n + "\t" + n + "\n";
    if (m == "language")
        for (int l = 0; l < noneuclid::lang::kLanguages; ++l) {
            const auto language = static_cast<noneuclid::lang::Language>(l);
            lines += std::string(noneuclid::lang::language_code(language)) + "\t" + noneuclid::lang::language_name(language) + "\n";
        }
    return lines.c_str();
}

// The run's state, for the page's status line.
EMSCRIPTEN_KEEPALIVE double nw_curvature() { return g_run ? g_run->session().curvature() : 0; }
EMSCRIPTEN_KEEPALIVE double nw_frame() { return g_run ? static_cast<double>(g_run->session().frame()) : 0; }
EMSCRIPTEN_KEEPALIVE const char* nw_projection() {
    return g_run ? noneuclid::geo::projection_name(g_run->session().options().draw.projection) : "";
}
// The lesson's step playing, from 1 (0: no lesson).
EMSCRIPTEN_KEEPALIVE int nw_lesson_step() { return g_run && g_run->lesson ? g_run->lesson->step() + 1 : 0; }
EMSCRIPTEN_KEEPALIVE const char* nw_engine() {
    // (compose_run set it to the engine the kind of world runs on)
    return g_run && g_run->options.engine ? noneuclid::world::engine_name(*g_run->options.engine) : "";
}
// 1 when the run's scene has the game (fire starts it and fires): the page shows the fire
// button and mentions Space only then.
EMSCRIPTEN_KEEPALIVE int nw_has_game() { return g_run && g_run->scene().game.on ? 1 : 0; }
// 1 if the scene has bumps (an uneven world: the < and > keys turn them).
EMSCRIPTEN_KEEPALIVE int nw_has_bumps() { return g_run && !g_run->scene().bumps.empty() ? 1 : 0; }
// The page's space changed (a turned phone, full screen): the canvas is width x height pixels
// from the next frame on, and the recording says so, as a resized window's does.
EMSCRIPTEN_KEEPALIVE void nw_resize(int width, int height) {
    if (noneuclid::web::running() && width >= 16 && height >= 16 && width <= 8192 && height <= 8192)
        g_run->display->resize(width, height);
}
EMSCRIPTEN_KEEPALIVE int nw_width() { return g_run ? g_run->display->canvas().width() : 0; }
EMSCRIPTEN_KEEPALIVE int nw_height() { return g_run ? g_run->display->canvas().height() : 0; }

// Sound on at `rate` samples a second (the page's AudioContext's), or off (0): from the next
// frame each frame's samples are at nw_sound_samples(), nw_sound_count() of them. 1 if on.
EMSCRIPTEN_KEEPALIVE int nw_sound(int rate) {
    if (!noneuclid::web::running() || g_run->lesson) return 0;
    g_run->live.loop->set_sound(nullptr);
    g_run->sound.reset();
    if (rate < 8000 || rate > 192000) return 0;
    g_run->sound = std::make_unique<noneuclid::web::WebSound>(rate);
    g_run->live.loop->set_sound(g_run->sound.get());
    return 1;
}
EMSCRIPTEN_KEEPALIVE const int16_t* nw_sound_samples() { return g_run && g_run->sound ? g_run->sound->samples() : nullptr; }
EMSCRIPTEN_KEEPALIVE int nw_sound_count() { return g_run && g_run->sound ? g_run->sound->count() : 0; }
// The cues the sound was given this run (muted ones not counted); 1 if muted now.
EMSCRIPTEN_KEEPALIVE double nw_sound_cues() { return g_run && g_run->sound ? static_cast<double>(g_run->sound->cues()) : 0; }
EMSCRIPTEN_KEEPALIVE int nw_sound_muted() { return g_run && g_run->session().sound().muted ? 1 : 0; }

// The recording so far: the settings and every control as it took effect (app/script.hpp).
EMSCRIPTEN_KEEPALIVE const char* nw_recording() {
    if (!g_run || !g_run->recording_file) return "";
    std::fflush(g_run->recording_file);
    return g_run->recording ? g_run->recording : "";
}

// The last error, one sentence ("" when the last call went well).
EMSCRIPTEN_KEEPALIVE const char* nw_message() { return g_message.c_str(); }

// The catalogue (lang/texts.hpp) in the language `code` names (the address's ?lang=, or the
// browser's "de-DE"; English for one without a catalogue): "lang\tde" first, then a
// "name\ttext" line for every text. The page labels itself from it and passes the code as --lang.
EMSCRIPTEN_KEEPALIVE const char* nw_texts(const char* code) {
    using namespace noneuclid::lang;
    static std::string out;
    Language language = Language::en;
    parse_language(code ? code : "", language);
    out = std::string("lang\t") + language_code(language) + "\n";
    for (int i = 0; i < kTexts; ++i)
        out += std::string(text_name(static_cast<Text>(i))) + "\t" + text(static_cast<Text>(i), language) + "\n";
    return out.c_str();
}

}  // extern "C"
