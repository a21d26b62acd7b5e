// The kiosk's portable half: board files, the attract-mode autopilot, and render::Session's
// recording, which `noneuclid render --actions` must replay pixel for pixel (the system test
// relies on it to compare a real framebuffer with a render).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "render/render_scene.hpp"
#include "render/session.hpp"
#include "world/actions.hpp"
#include "world/attract.hpp"
#include "world/board.hpp"
#include "world/scene.hpp"

namespace {

using namespace noneuclid;
using world::Board;
using world::BoardError;
using world::Control;

// ---- board files ---------------------------------------------------------------------------

// The Raspberry Pi 40-pin header: physical pin -> BCM GPIO number (-1: power or ground), from
// the Raspberry Pi pinout documentation, written out independently of the board files.
const std::map<int, int> kHeader = {
    {1, -1}, {2, -1}, {3, 2}, {4, -1}, {5, 3}, {6, -1}, {7, 4}, {8, 14}, {9, -1}, {10, 15},
    {11, 17}, {12, 18}, {13, 27}, {14, -1}, {15, 22}, {16, 23}, {17, -1}, {18, 24}, {19, 10}, {20, -1},
    {21, 9}, {22, 25}, {23, 11}, {24, 8}, {25, -1}, {26, 7}, {27, 0}, {28, 1}, {29, 5}, {30, -1},
    {31, 6}, {32, 12}, {33, 13}, {34, -1}, {35, 19}, {36, 16}, {37, 26}, {38, 20}, {39, -1}, {40, 21}};

world::Scene kiosk_scene() {
    world::Scene s;
    EXPECT_TRUE(world::builtin_scene("kiosk", world::SceneParams{}, s));
    return s;
}

Board load(const std::string& name) {
    Board b;
    BoardError e;
    EXPECT_TRUE(world::load_board_file(std::string(NONEUCLID_SOURCE_DIR) + "/boards/" + name + ".toml", b, e)) << e.to_string();
    return b;
}

TEST(Boards, EveryPiBoardWiresTheSevenButtonsToMatchingHeaderPins) {
    const std::map<std::string, std::string> chip = {{"rpi-zero2w", "pinctrl-bcm2835"}, {"rpi3", "pinctrl-bcm2835"},
                                                     {"rpi4", "pinctrl-bcm2711"}, {"rpi5", "pinctrl-rp1"}};
    for (const auto& [name, label] : chip) {
        SCOPED_TRACE(name);
        const Board b = load(name);
        ASSERT_EQ(b.chips, std::vector<std::string>{label});
        EXPECT_FALSE(b.models.empty());
        int gpio_buttons = 0;
        for (const auto& bb : b.buttons) {
            if (bb.gpio < 0) continue;
            ++gpio_buttons;
            ASSERT_TRUE(kHeader.count(bb.pin)) << "pin " << bb.pin;
            EXPECT_EQ(kHeader.at(bb.pin), bb.gpio) << world::control_name(bb.control) << ": header pin " << bb.pin;
            // Not a pin the usual display/audio HATs or the I2C/SPI/UART defaults take.
            EXPECT_TRUE(bb.gpio != 2 && bb.gpio != 3 && bb.gpio != 14 && bb.gpio != 15) << bb.gpio;
        }
        EXPECT_EQ(gpio_buttons, 7);
        for (Control c : {Control::thrust, Control::left, Control::right, Control::curvature_up, Control::curvature_down,
                          Control::preset, Control::reset}) {
            bool found = false;
            for (const auto& bb : b.buttons) found = found || (bb.control == c && bb.gpio >= 0 && bb.key > 0);
            EXPECT_TRUE(found) << world::control_name(c);
        }
    }
}

TEST(Boards, GenericIsKeysOnlyAndMatchesNoModel) {
    const Board b = load("generic");
    EXPECT_FALSE(b.has_gpio());
    EXPECT_TRUE(b.has_keys());
    EXPECT_TRUE(b.models.empty());
}

TEST(Boards, ModelsOfDifferentBoardsDoNotOverlap) {
    // /proc/device-tree/model strings of real boards, and the board each must select.
    const std::map<std::string, std::string> real = {
        {"Raspberry Pi Zero 2 W Rev 1.0", "rpi-zero2w"}, {"Raspberry Pi 3 Model B Plus Rev 1.3", "rpi3"},
        {"Raspberry Pi 4 Model B Rev 1.4", "rpi4"},       {"Raspberry Pi 400 Rev 1.0", "rpi4"},
        {"Raspberry Pi 5 Model B Rev 1.0", "rpi5"},       {"Raspberry Pi Compute Module 4 Rev 1.0", "rpi4"}};
    for (const auto& [model, want] : real) {
        std::vector<std::string> matches;
        for (const char* name : {"rpi-zero2w", "rpi3", "rpi4", "rpi5", "generic"})
            for (const std::string& m : load(name).models)
                if (model.compare(0, m.size(), m) == 0) matches.push_back(name);
        ASSERT_FALSE(matches.empty()) << model;
        // "Raspberry Pi 4" is a prefix of "Raspberry Pi 400": both are rpi4, so only distinct
        // boards count.
        for (const std::string& m : matches) EXPECT_EQ(m, want) << model;
    }
}

struct BadBoard {
    const char* text;
    const char* where;
    const char* message;
};

TEST(Boards, ErrorsNameTheFileThePlaceAndTheFix) {
    const BadBoard cases[] = {
        {"name = \"x\"\ncolour = 3\n", "t.toml:2:1", "unknown key 'colour'"},
        {"[[button]]\naction = \"fly\"\ngpio = 4\n", "t.toml:2:10", "unknown action \"fly\""},
        {"[[button]]\ngpio = 4\n", "t.toml:1:1", "expected action ="},
        {"[[button]]\naction = \"thrust\"\n", "t.toml:1:1", "expected a gpio line or a key code"},
        {"[[button]]\naction = \"thrust\"\ngpio = 4\n[[button]]\naction = \"left\"\ngpio = 4\n", "t.toml:6:8",
         "gpio 4 is already the 'thrust' button"},
        {"[[button]]\naction = \"thrust\"\ngpio = 4000\n", "t.toml:3:8", "'gpio' must be from 0 to 1023"},
        {"[[button]]\naction = \"thrust\"\nkey = 57\npin = 41\n", "t.toml:4:7", "'pin' must be from 1 to 40"},
        {"[display]\nengine = \"quantum\"\n", "t.toml:2:10", "expected engine = \"fixed\""},
        {"[display]\nprojection = \"mercator\"\n", "t.toml:2:14", "expected projection = \"equidistant\""},
        {"[display]\nfps = 0\n", "t.toml:2:7", "'fps' must be from 1 to 1000"},
        {"[gpio]\nchip = 7\n", "t.toml:2:8", "expected a string or a list of strings for 'chip'"},
        {"[attract]\nidle_seconds = -1\n", "t.toml:2:16", "'idle_seconds' must be from 0"},
        {"display = 3\n", "t.toml:1:11", "expected a [display] table"},
        {"name = \n", "t.toml:1:8", "not valid TOML"},
    };
    for (const BadBoard& c : cases) {
        Board b;
        BoardError e;
        ASSERT_FALSE(world::parse_board(c.text, "t.toml", b, e)) << c.text;
        const std::string s = e.to_string();
        EXPECT_NE(s.find(c.where), std::string::npos) << s;
        EXPECT_NE(s.find(c.message), std::string::npos) << s;
    }
    Board b;
    BoardError e;
    EXPECT_FALSE(world::load_board_file("/nonexistent/board.toml", b, e));
    EXPECT_NE(e.to_string().find("cannot read the board file"), std::string::npos);
}

// ---- attract mode --------------------------------------------------------------------------

// Drives a world with only the autopilot, returns (time, K) samples.
template <class W>
std::vector<std::pair<double, double>> fly(W& w, world::Autopilot& ap, double seconds, double* top_speed) {
    std::vector<std::pair<double, double>> k;
    world::InputEvent ev[8];
    for (long f = 0; f < static_cast<long>(seconds * 60); ++f) {
        double speed = 0;
        for (const auto& b : w.bodies)
            if (b.desc->controlled) speed = static_cast<double>(b.speed);
        *top_speed = std::fmax(*top_speed, speed);
        const int n = ap.frame(w.time, static_cast<double>(w.K), speed, ev);
        for (int i = 0; i < n; ++i) {
            world::Action a{};
            EXPECT_TRUE(world::control_action(ev[i].control, a)) << "the autopilot only uses world actions";
            if (ev[i].pressed) w.press(a);
            else w.release(a);
        }
        w.step(typename W::scalar(1.0 / 60));
        k.push_back({w.time, static_cast<double>(w.K)});
    }
    return k;
}

TEST(Attract, StartsAfterTheIdleTimeAndSweepsKAtTheAskedPace) {
    const world::Scene scene = kiosk_scene();
    world::World<double> w(scene);
    world::AttractOptions o;
    o.idle_seconds = 10, o.sweep_seconds = 20, o.cruise_speed = 0.25;
    world::Autopilot ap(o, scene.curvature_rate);
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
    world::Autopilot ap({5, 20, 0.25}, scene.curvature_rate);
    double top = 0;
    fly(w, ap, 8, &top);
    ASSERT_TRUE(ap.active());
    world::InputEvent out[8];
    const int n = ap.interrupt(w.time, out);
    EXPECT_FALSE(ap.active());
    ASSERT_GE(n, 2);
    EXPECT_EQ(out[n - 2].control, Control::reset);
    EXPECT_TRUE(out[n - 2].pressed);
    EXPECT_FALSE(out[n - 1].pressed);
    for (int i = 0; i < n - 2; ++i) EXPECT_FALSE(out[i].pressed) << "only releases before the reset";
    // Idle again: it comes back after the idle time, not before.
    world::InputEvent ev[8];
    EXPECT_EQ(ap.frame(w.time + 4.9, 0, 0, ev), 0);
    EXPECT_FALSE(ap.active());
    EXPECT_GT(ap.frame(w.time + 5.0, 0, 0, ev), 0);
    EXPECT_TRUE(ap.active());
    // Off means off.
    world::Autopilot off({0, 20, 0.25}, 0.5);
    EXPECT_EQ(off.frame(1e6, 0, 0, ev), 0);
    EXPECT_FALSE(off.active());
}

// ---- recording and replay ------------------------------------------------------------------

struct Scripted {
    long frame;
    Control control;
    bool pressed;
};

// Runs a Session for `frames` frames with the scripted controls, recording to a temporary
// file; returns the recording's text and leaves the last frame in `pixels`.
template <class W>
std::string run_session(const world::Scene& scene, const std::vector<Scripted>& script, long frames, double idle,
                        render::PixelFormat format, std::vector<uint8_t>& pixels, int threads = 1) {
    const int w = 320, h = 200;
    pixels.assign(static_cast<std::size_t>(w * h * format.bytes_per_pixel()), 0);
    const render::Canvas canvas(pixels.data(), w, h, w * format.bytes_per_pixel(), format);
    std::FILE* f = std::tmpfile();
    render::FileRecorder rec(f);
    render::SessionOptions o;
    o.hud = false;
    o.attract = {idle, 6, 0.25};
    render::WorkerPool pool(threads);
    render::Session<W> s(scene, o, render::builtin_font(), &rec, &pool);
    for (long fr = 0; fr < frames; ++fr) {
        for (const Scripted& e : script)
            if (e.frame == fr) s.control({e.control, e.pressed});
        s.frame(canvas);
    }
    std::fflush(f);
    std::rewind(f);
    std::string text;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
    std::fclose(f);
    return text;
}

template <class W>
void replay_matches(double idle, int threads = 1) {
    const world::Scene scene = kiosk_scene();
    const std::vector<Scripted> script = {
        {12, Control::thrust, true},          {40, Control::curvature_down, true}, {95, Control::curvature_down, false},
        {130, Control::thrust, false},        {131, Control::left, true},          {150, Control::left, false},
        {160, Control::projection, true},     {161, Control::projection, false},  // not a world action: a comment
        {170, Control::preset, true},         {171, Control::preset, false},
    };
    const long frames = 420;
    for (render::PixelFormat format : {render::PixelFormat::rgb565(), render::PixelFormat::xrgb8888()}) {
        std::vector<uint8_t> live;
        const std::string text = run_session<W>(scene, script, frames, idle, format, live, threads);
        std::vector<world::ActionEvent> events;
        world::ActionError err;
        ASSERT_TRUE(world::parse_actions(text, "recording", events, err)) << err.to_string() << "\n" << text;
        // The replay, as `noneuclid render --actions` does it (projection from the recording's
        // comment is the one thing not replayed: the script switches it once, so replay with
        // the switched one).
        W world(scene);
        std::vector<uint8_t> replay(live.size());
        const render::Canvas canvas(replay.data(), 320, 200, 320 * format.bytes_per_pixel(), format);
        render::RenderJob job;
        job.frames = frames;
        job.draw.projection = geo::kProjections[1];
        render::render_scene(world, canvas, job, events);
        long differ = 0;
        for (std::size_t i = 0; i < live.size(); ++i) differ += live[i] != replay[i];
        EXPECT_EQ(differ, 0) << format.name;
        // The recording holds what was pressed, with the autopilot's actions when it flew.
        EXPECT_NE(text.find("press thrust"), std::string::npos);
        EXPECT_NE(text.find("release curvature_down"), std::string::npos);
        EXPECT_NE(text.find("# "), std::string::npos);
        if (idle > 0) {
            EXPECT_NE(text.find("attract on"), std::string::npos) << text;
        }
        // A control: dropping one event changes the picture, so the comparison can fail.
        events.erase(events.begin() + 1);
        W other(scene);
        std::vector<uint8_t> wrong(live.size());
        const render::Canvas c2(wrong.data(), 320, 200, 320 * format.bytes_per_pixel(), format);
        render::render_scene(other, c2, job, events);
        long d2 = 0;
        for (std::size_t i = 0; i < live.size(); ++i) d2 += live[i] != wrong[i];
        EXPECT_GT(d2, 100) << format.name;
    }
}

TEST(Session, RecordingReplaysPixelExactFixed) { replay_matches<world::World<fx::fixed>>(0); }
TEST(Session, RecordingReplaysPixelExactDouble) { replay_matches<world::World<double>>(0); }
TEST(Session, RecordingReplaysPixelExactFloat) { replay_matches<world::World<float>>(0); }
// With attract mode kicking in (after 3 s idle) the autopilot's presses are recorded too.
TEST(Session, RecordingWithAttractModeReplaysPixelExact) { replay_matches<world::World<fx::fixed>>(3); }
// The kiosk's --threads: drawn over a pool of 2 or 3, the same pixels as render's one thread.
TEST(Session, DrawnOnThreadsReplaysPixelExact) {
    replay_matches<world::World<fx::fixed>>(3, 2);
    replay_matches<world::World<double>>(0, 3);
}

}  // namespace
