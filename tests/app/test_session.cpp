// The session behind every display (app/session.hpp) and the frame loop (app/frame_loop.hpp):
// the attract-mode autopilot, and a run's recording, which `noneuclid render --actions` must
// replay pixel for pixel (the system test relies on it to compare a real framebuffer with a
// render). The run here is the real frame loop on a display that delivers scripted keys.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/frame_loop.hpp"
#include "app/picture.hpp"
#include "app/recorder.hpp"
#include "test_common.hpp"
#include "app/setup.hpp"

namespace {

using namespace noneuclid;
using world::Action;

world::Scene kiosk_scene() {
    world::Scene s;
    EXPECT_TRUE(world::builtin_scene("kiosk", world::SceneParams{}, s));
    return s;
}

// ---- attract mode --------------------------------------------------------------------------

// Drives a world with only the autopilot, returns (time, K) samples.
template <class W>
std::vector<std::pair<double, double>> fly(W& w, app::Autopilot& ap, double seconds, double* top_speed) {
    std::vector<std::pair<double, double>> k;
    world::InputEvent ev[8];
    for (long f = 0; f < static_cast<long>(seconds * 60); ++f) {
        double speed = 0;
        for (const auto& b : w.bodies)
            if (b.desc->controlled) speed = static_cast<double>(b.speed);
        *top_speed = std::fmax(*top_speed, speed);
        app::PilotView v;
        v.K = static_cast<double>(w.K), v.ship_speed = speed;
        const int n = ap.frame(w.time, v, ev);
        for (int i = 0; i < n; ++i) {
            const world::Action a = ev[i].control;
            EXPECT_TRUE(world::is_world_action(a)) << "the autopilot only uses world actions";
            if (ev[i].pressed) w.press(a);
            else w.release(a);
        }
        w.step(1.0 / 60);
        k.push_back({w.time, static_cast<double>(w.K)});
    }
    return k;
}

TEST(Attract, StartsAfterTheIdleTimeAndSweepsKAtTheAskedPace) {
    const world::Scene scene = kiosk_scene();
    world::World<double> w(scene);
    app::AttractOptions o;
    o.idle_seconds = 10, o.sweep_seconds = 20, o.cruise_speed = 0.25;
    app::Autopilot ap(o, scene.curvature_rate);
    double top = 0;
    const auto k = fly(w, ap, 130, &top);
    // Nothing happens for 10 s.
    for (const auto& [t, K] : k)
        if (t < 10 - 1e-9) {
            EXPECT_DOUBLE_EQ(K, scene.curvature) << t;
        }
    ASSERT_TRUE(ap.active());
    // K reaches both ends, and a full -1 -> +1 run takes sweep_seconds (the duty cycle).
    double first_low = -1, next_high = -1;
    for (const auto& [t, K] : k) {
        if (first_low < 0 && K <= -1 + 1e-9) first_low = t;
        if (first_low >= 0 && next_high < 0 && K >= 1 - 1e-9) next_high = t;
    }
    ASSERT_GT(first_low, 0) << "K never reached -1";
    ASSERT_GT(next_high, 0) << "K never came back to +1";
    EXPECT_NEAR(next_high - first_low, 20.0, 0.5);
    for (const auto& [t, K] : k) EXPECT_TRUE(K >= -1 && K <= 1);
    // The ship flies but does not run away: thrust only below the cruise speed.
    EXPECT_GT(top, 0.2);
    EXPECT_LT(top, 0.25 + scene.thrust / 60 + 1e-9);
}

TEST(Attract, APressEndsItReleasesWhatItHeldAndResets) {
    const world::Scene scene = kiosk_scene();
    world::World<double> w(scene);
    app::Autopilot ap({5, 20, 0.25}, scene.curvature_rate);
    double top = 0;
    fly(w, ap, 8, &top);
    ASSERT_TRUE(ap.active());
    world::InputEvent out[8];
    const int n = ap.interrupt(w.time, out);
    EXPECT_FALSE(ap.active());
    ASSERT_GE(n, 2);
    EXPECT_EQ(out[n - 2].control, Action::reset);
    EXPECT_TRUE(out[n - 2].pressed);
    EXPECT_FALSE(out[n - 1].pressed);
    for (int i = 0; i < n - 2; ++i) EXPECT_FALSE(out[i].pressed) << "only releases before the reset";
    // Idle again: it comes back after the idle time, not before.
    world::InputEvent ev[8];
    const app::PilotView still{0, 0};
    EXPECT_EQ(ap.frame(w.time + 4.9, still, ev), 0);
    EXPECT_FALSE(ap.active());
    EXPECT_GT(ap.frame(w.time + 5.0, still, ev), 0);
    EXPECT_TRUE(ap.active());
    // Off means off.
    app::Autopilot off({0, 20, 0.25}, 0.5);
    EXPECT_EQ(off.frame(1e6, still, ev), 0);
    EXPECT_FALSE(off.active());
}

// ---- a run through the frame loop, and its replay ----------------------------------------

// A file of this test's own (ctest runs the tests in parallel processes).
std::string temp_file(const char* what) {
    const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
    return ::testing::TempDir() + t->test_suite_name() + "." + t->name() + "." + what;
}

struct Key {
    long frame;  // delivered while waiting for this frame
    Action control;
    bool pressed;
};

// A display that nobody watches, whose "keys" come at given frames, and whose canvas is resized
// at `resize_at` (a window the user drags), as a real one's would be.
class ScriptedDisplay final : public app::Display {
public:
    ScriptedDisplay(int w, int h, render::PixelFormat f, std::vector<Key> keys, long resize_at = -1)
        : format_(f), keys_(std::move(keys)), resize_at_(resize_at) {
        allocate(w, h);
    }
    render::Canvas canvas() override { return canvas_; }
    void present() override {
        if (++presented_ == resize_at_) allocate(canvas_.width() + 40, canvas_.height() - 30);
    }
    bool wait(int64_t, app::InputSink& sink) override {
        for (const Key& k : keys_)
            if (k.frame == presented_) sink.input({k.control, k.pressed});
        return true;
    }
    bool closing() const override { return false; }
    bool realtime() const override { return false; }
    bool read_back(app::Picture& out, std::string&) override {
        out.pixels = pixels_;
        out.canvas = render::Canvas(out.pixels.data(), canvas_.width(), canvas_.height(), canvas_.stride(), format_);
        return true;
    }
    const char* legend() const override { return "keys"; }

private:
    void allocate(int w, int h) {
        pixels_.assign(static_cast<std::size_t>(w * h * format_.bytes_per_pixel()), 0);
        canvas_ = render::Canvas(pixels_.data(), w, h, w * format_.bytes_per_pixel(), format_);
    }
    render::PixelFormat format_;
    std::vector<Key> keys_;
    long resize_at_, presented_ = 0;
    std::vector<uint8_t> pixels_;
    render::Canvas canvas_;
};

struct LiveRun {
    std::string recording;
    app::Picture last;  // what the display showed at the end
};

// `noneuclid run` on the scripted display for `frames` frames, recording as --record does.
LiveRun run_live(app::Options o, const std::vector<Key>& keys, render::PixelFormat format, long resize_at = -1) {
    const world::Scene scene = app::load_scene(o);
    const std::string path = temp_file("recording.txt");
    std::FILE* f = std::fopen(path.c_str(), "w");
    EXPECT_NE(f, nullptr);
    app::Recorder rec(f);
    platform::LoadedFont font;
    std::string error;
    EXPECT_TRUE(platform::hud_font("builtin", font, error));
    ScriptedDisplay display(320, 200, format, keys, resize_at);
    o.legend = display.legend();
    app::record_settings(rec, o, "scripted", font, format);
    const auto session = app::make_session(app::world_kind(o, scene), scene, app::session_options(o, scene, o.legend, app::world_kind(o, scene)), font.font, &rec);
    app::LoopOptions lo;
    lo.frames = o.frames;
    app::FrameLoop loop(display, *session, nullptr, &rec, lo);
    EXPECT_EQ(loop.run(), 0);
    EXPECT_EQ(loop.frames(), o.frames);
    std::fclose(f);
    LiveRun r;
    std::string err;
    EXPECT_TRUE(display.read_back(r.last, err));
    std::FILE* in = std::fopen(path.c_str(), "r");
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, in)) > 0;) r.recording.append(buf, n);
    std::fclose(in);
    return r;
}

// `noneuclid render --actions RECORDING` (without writing the PNG): the recording's settings
// under nothing else.
app::Picture replay(const std::string& recording, const std::string& drop = "") {
    std::string text = recording;
    if (!drop.empty()) text.erase(text.find(drop), drop.size());
    const std::string path = temp_file("replay.txt");
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(text.c_str(), f);
    std::fclose(f);
    std::string a0 = "noneuclid", a1 = "--actions", a2 = path;
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    app::Script script;
    const app::Options o = app::layered_options(3, argv, 1, app::Command::render, script);
    platform::LoadedFont font;
    std::string error;
    EXPECT_TRUE(platform::hud_font(o.font, font, error)) << error;
    app::Picture p;
    app::render_picture(o, app::load_scene(o), &script, font.font, p);
    return p;
}

long differing_bytes(const app::Picture& a, const app::Picture& b) {
    if (a.canvas.width() != b.canvas.width() || a.canvas.height() != b.canvas.height()) return -1;
    long n = 0;
    for (int y = 0; y < a.canvas.height(); ++y)
        for (int x = 0; x < a.canvas.width(); ++x) n += a.canvas.get_word(x, y) != b.canvas.get_word(x, y);
    return n;
}

// Keys of every kind: held world actions, a preset, K set by 1/2/3, the projection and the HUD.
const std::vector<Key> kKeys = {
    {12, Action::thrust, true},      {40, Action::curvature_down, true}, {95, Action::curvature_down, false},
    {130, Action::thrust, false},    {131, Action::left, true},          {150, Action::left, false},
    {160, Action::projection, true}, {161, Action::projection, false},   {170, Action::preset, true},
    {171, Action::preset, false},    {200, Action::hud, true},           {201, Action::hud, false},
    {230, Action::spherical, true},  {231, Action::spherical, false},    {260, Action::hud, true},
    {262, Action::hud, false},       {300, Action::hyperbolic, true},    {300, Action::hyperbolic, false},
};

void replays_exactly(world::EngineKind engine, double idle, int threads = 1) {
    for (render::PixelFormat format : {render::PixelFormat::rgb565(), render::PixelFormat::xrgb8888()}) {
        SCOPED_TRACE(format.name);
        // With attract mode: idle from 5 s on, the autopilot flies from 8 s to the end (its
        // legend on the HUD), or (rgb565) until a key at 9.3 s ends it: its held controls are
        // released, the world reset.
        std::vector<Key> keys = kKeys;
        const bool interrupt = idle > 0 && format.bits_per_pixel == 16;
        if (interrupt) keys.push_back({560, Action::left, true}), keys.push_back({575, Action::left, false});
        app::Options o = app::defaults(app::Command::run);
        o.engine = engine, o.frames = idle > 0 ? 600 : 420, o.attract = idle, o.threads = threads, o.format = format;
        o.hud = true;
        const LiveRun live = run_live(o, keys, format);
        EXPECT_EQ(differing_bytes(replay(live.recording), live.last), 0) << live.recording;
        // What the recording holds: the keys as they took effect, the view's as taps, the end.
        for (const char* line : {"press thrust", "release curvature_down", "tap projection", "tap hud",
                                 "press spherical", "press hyperbolic", "\nsize 320x200\n"})
            EXPECT_NE(live.recording.find(line), std::string::npos) << line;
        EXPECT_NE(live.recording.find("\nframes " + std::to_string(o.frames) + "\n"), std::string::npos);
        if (idle > 0) {
            EXPECT_NE(live.recording.find("attract on"), std::string::npos) << live.recording;
            EXPECT_EQ(live.recording.find("attract off") != std::string::npos, interrupt) << live.recording;
        }
        // The comparison can fail: without one key the picture differs.
        const std::size_t at = live.recording.find("tap projection");
        const std::size_t start = live.recording.rfind('\n', at) + 1;
        const std::string line = live.recording.substr(start, live.recording.find('\n', at) + 1 - start);
        EXPECT_GT(differing_bytes(replay(live.recording, line), live.last), 100);
    }
}

TEST(Recording, ReplaysPixelExactFixed) { replays_exactly(world::engine_named("fixed"), 0); }
TEST(Recording, ReplaysPixelExactDouble) { replays_exactly(world::engine_named("double"), 0); }
TEST(Recording, ReplaysPixelExactFloat) { replays_exactly(world::engine_named("float"), 0); }
// With attract mode kicking in (after 3 s idle) the autopilot's presses and the HUD's attract
// legend are replayed too.
TEST(Recording, WithAttractModeReplaysPixelExact) { replays_exactly(world::engine_named("fixed"), 3); }
// --threads: drawn over a pool of 2 or 3, the same pixels as render's one thread.
TEST(Recording, DrawnOnThreadsReplaysPixelExact) {
    replays_exactly(world::engine_named("fixed"), 3, 2);
    replays_exactly(world::engine_named("double"), 0, 3);
}

// A whole game, recorded and replayed: a visitor starts it with fire, turns, thrusts and fires
// until the ship is lost (one life, fast asteroids), the game-over screen gives way to attract
// mode, which plays the next game; the replay draws the last frame pixel for pixel, and its
// dump has the hits, the crash and the end.
TEST(Recording, AWholeGameReplaysPixelExact) {
    app::Options o = app::defaults(app::Command::run);
    o.scene = std::string(NONEUCLID_SOURCE_DIR) + "/tests/files/data/game.toml";
    o.frames = 1500, o.attract = 3, o.hud = true;
    o.scores = "none";
    const std::vector<Key> keys = {{10, Action::fire, true},   {12, Action::fire, false},  {40, Action::fire, true},
                                   {60, Action::left, true},   {95, Action::left, false},  {120, Action::thrust, true},
                                   {150, Action::thrust, false}, {170, Action::right, true}, {230, Action::right, false},
                                   {260, Action::fire, false}};
    const LiveRun live = run_live(o, keys, render::PixelFormat::rgb565());
    EXPECT_EQ(differing_bytes(replay(live.recording), live.last), 0);
    for (const char* line : {"press fire", "release fire", "attract on"})
        EXPECT_NE(live.recording.find(line), std::string::npos) << line;
    // The game as dump sees it, from the same recording.
    const std::string path = temp_file("game.txt");
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(live.recording.c_str(), f);
    std::fclose(f);
    std::string a0 = "noneuclid", a1 = "--actions", a2 = path;
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    app::Script script;
    const app::Options d = app::layered_options(3, argv, 1, app::Command::dump, script);
    const world::Scene scene = app::load_scene(d);
    const auto s = app::make_session(app::world_kind(d, scene), scene, app::session_options(d, scene, "keys", app::world_kind(d, scene)), render::builtin_font(), nullptr);
    app::ScriptPlayer player(script.events);
    std::string all, line;
    s->play_due(player);
    for (long i = 0; i < o.frames; ++i) {
        s->step();
        s->play_due(player);
        line.clear();
        s->dump(320, 200, line);
        all += line;
    }
    EXPECT_NE(all.find("{\"start\":true}"), std::string::npos);
    EXPECT_NE(all.find("{\"hit\":[\"bullet "), std::string::npos);
    EXPECT_NE(all.find("{\"crash\":\"asteroid "), std::string::npos);
    EXPECT_NE(all.find("{\"over\":"), std::string::npos);
    EXPECT_NE(all.find("\"phase\":\"playing\"", all.rfind("{\"over\":")), std::string::npos) << "attract mode played on";
}

// A window resized during the run: the recording's last size is the last frame's.
TEST(Recording, AResizedWindowReplaysAtItsLastSize) {
    app::Options o = app::defaults(app::Command::run);
    o.frames = 200;
    const LiveRun live = run_live(o, kKeys, render::PixelFormat::xrgb8888(), 120);
    EXPECT_EQ(live.last.canvas.width(), 360);
    EXPECT_NE(live.recording.find("\nsize 360x170\n"), std::string::npos) << live.recording;
    EXPECT_EQ(differing_bytes(replay(live.recording), live.last), 0);
}

// A tap on the canvas (the web page's) marks the live instrument at the world point that pixel
// shows, in every projection: the dump's triangle has the tapped points as its marks, and the
// recording's mark lines replay it to the same dump.
TEST(Session, ATapMarksTheLiveInstrumentWhereThePixelShows) {
    for (geo::Projection p : geo::kProjections) {
        app::Options o = app::defaults(app::Command::run);
        o.scene = "measure", o.has_curvature = true, o.curvature = -0.5, o.projection = p;
        o.engine = world::engine_named("double");
        const world::Scene scene = app::load_scene(o);
        const std::string path = temp_file("marks.txt");
        std::FILE* file = std::fopen(path.c_str(), "w");
        ASSERT_NE(file, nullptr);
        app::Recorder rec(file);
        const auto s = app::make_session(app::world_kind(o, scene), scene, app::session_options(o, scene, "keys", app::world_kind(o, scene)), render::builtin_font(), &rec);
        // Three points, and the pixels that show them (by the projection's own formula).
        const geo::Polar<double> want[3] = {{0.8, 0.3}, {1.1, 2.2}, {0.5, -2.0}};
        for (const geo::Polar<double>& w : want) {
            const geo::Projected<double> pr = geo::project(-0.5, w.r, p);
            const auto m = geo::ScreenMap<double>::of(400, 300, -0.5, scene.limit_radius, p, s->layout(400, 300).disc);
            ASSERT_TRUE(s->mark_at(m.cx + m.scale * pr.rho * std::cos(w.theta), m.cy - m.scale * pr.rho * std::sin(w.theta), 400, 300));
            s->step();
        }
        EXPECT_FALSE(s->mark_at(0, 0, 400, 300)) << "a corner shows no point of the world";
        std::string line;
        s->dump(400, 300, line);
        const std::size_t at = line.find("\"measure\":");
        ASSERT_NE(at, std::string::npos) << line;
        const std::string live = line.substr(line.rfind("{\"instrument\":\"triangle\""));
        double got[3][2] = {};
        ASSERT_EQ(std::sscanf(live.c_str(), "{\"instrument\":\"triangle\",\"K\":%*[^,],\"points\":[[%lf,%lf],[%lf,%lf],[%lf,%lf]]",
                              &got[0][0], &got[0][1], &got[1][0], &got[1][1], &got[2][0], &got[2][1]), 6) << live;
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(got[k][0], want[k].r, 1e-9) << geo::projection_name(p) << " " << live;
            EXPECT_NEAR(noneuclid::test::angle_diff(noneuclid::test::deg(got[k][1]), want[k].theta), 0, 1e-9) << geo::projection_name(p) << " " << live;
        }
        std::fclose(file);
        std::string text;
        {
            std::FILE* f = std::fopen(path.c_str(), "r");
            char buf[4096];
            for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
            std::fclose(f);
        }
        int marks = 0;
        for (std::size_t at = text.find(" mark "); at != std::string::npos; at = text.find(" mark ", at + 1)) ++marks;
        EXPECT_EQ(marks, 3) << text;
    }
}

// The keys 1, 2, 3 set K, through the session, as actions.
// The kiosk's legend names the fire button only where fire acts (the game, a scene's instruments),
// the zoom where the curvature buttons zoom, and speaks the run's language.
TEST(Session, TheButtonsLegendNamesFireOnlyWhereItActsInTheRunsLanguage) {
    struct Case {
        const char* scene;
        const char* lang;
        const char* has;
        const char* lacks;
    } cases[] = {{"kiosk", "en", "curvature +/-", "fire"},     {"asteroids", "en", "  fire  ", "zoom"},
                 {"measure", "en", "  fire  ", "zoom"},        {"earth", "en", "zoom +/-", "fire"},
                 {"asteroids", "de", "  Feuer  ", "fire"},     {"kiosk", "fr", "courbure +/-", "feu"}};
    for (const Case& c : cases) {
        app::Options o = app::defaults(app::Command::run);
        o.scene = c.scene, o.language = c.lang;
        world::Scene scene;
        ASSERT_TRUE(world::builtin_scene(c.scene, o.params, scene)) << c.scene;
        const app::SessionOptions so = app::session_options(o, scene, "buttons", app::world_kind(o, scene));
        EXPECT_NE(so.legend.find(c.has), std::string::npos) << c.scene << " " << c.lang << ": " << so.legend;
        EXPECT_EQ(so.legend.find(c.lacks), std::string::npos) << c.scene << " " << c.lang << ": " << so.legend;
    }
}

TEST(Session, KeysSetKAndQuitStops) {
    app::Options o = app::defaults(app::Command::run);
    const world::Scene scene = app::load_scene(o);
    const auto s = app::make_session(app::world_kind(o, scene), scene, app::session_options(o, scene, "keys", app::world_kind(o, scene)), render::builtin_font(),
                                     nullptr);
    ASSERT_NE(s->curvature(), 1.0);
    for (auto [c, K] : {std::pair{Action::spherical, 1.0}, {Action::hyperbolic, -1.0}, {Action::flat, 0.0}}) {
        const double before = s->curvature();
        s->queue({c, true});
        s->queue({c, false});
        EXPECT_EQ(s->curvature(), before) << "queued input waits for the step";
        s->step();
        EXPECT_EQ(s->curvature(), K) << world::action_name(c);
    }
    EXPECT_FALSE(s->quit());
    s->queue({Action::quit, true});
    EXPECT_TRUE(s->quit());
}

}  // namespace
