// One-button mode (app/one_button.hpp): fire alone plays the game and moves K elsewhere; what it
// sends are the world's own actions, so its recording, played back without the mode, reaches the
// same world (the dumps of the last frame equal, character for character).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "app/recorder.hpp"
#include "app/script.hpp"
#include "app/setup.hpp"
#include "render/font.hpp"

namespace {
namespace one_button_test {  // (a unity batch shares this file's scope with others)

using namespace noneuclid;
using world::Action;

std::string temp_path(const char* what) {
    const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
    return ::testing::TempDir() + t->test_suite_name() + "." + t->name() + "." + what;
}

struct OneButtonRun {
    std::string recording, last_dump;
    std::vector<double> K;  // after each step
};

// `scene` in one-button mode for `frames` steps, fire pressed and released at the given frames
// (the display's queue, as a button would), recorded.
OneButtonRun one_button_run(const std::string& scene_name, long frames, const std::vector<std::pair<long, bool>>& fire) {
    app::Options o = app::defaults(app::Command::run);
    o.scene = scene_name, o.one_button = true, o.engine = world::engine_named("double");
    const world::Scene scene = app::load_scene(o);
    const std::string path = temp_path("recording.txt");
    std::FILE* f = std::fopen(path.c_str(), "w");
    EXPECT_NE(f, nullptr);
    OneButtonRun r;
    {
        app::Recorder rec(f);
        platform::LoadedFont font;
        std::string error;
        EXPECT_TRUE(platform::hud_font("builtin", font, error));
        app::record_settings(rec, o, "scripted", font, render::PixelFormat::xrgb8888());
        const auto s = app::make_session(app::world_kind(o, scene), scene, app::session_options(o, scene, "buttons", app::world_kind(o, scene)), font.font, &rec);
        std::size_t next = 0;
        for (long i = 0; i < frames; ++i) {
            while (next < fire.size() && fire[next].first == i) s->queue({Action::fire, fire[next++].second});
            s->step();
            r.K.push_back(s->curvature());
        }
        s->dump(320, 200, r.last_dump);
        rec.setting("frames", std::to_string(frames));
    }
    std::fclose(f);
    std::FILE* in = std::fopen(path.c_str(), "r");
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, in)) > 0;) r.recording.append(buf, n);
    std::fclose(in);
    return r;
}

// The recording played by `dump --actions`, without the mode: its last frame's dump.
std::string replayed_dump(const OneButtonRun& run, long frames) {
    const std::string path = temp_path("replay.txt");
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(run.recording.c_str(), f);
    std::fclose(f);
    std::string a0 = "noneuclid", a1 = "--actions", a2 = path;
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    app::Script script;
    const app::Options d = app::layered_options(3, argv, 1, app::Command::dump, script);
    EXPECT_FALSE(d.one_button);
    const world::Scene scene = app::load_scene(d);
    const auto s = app::make_session(app::world_kind(d, scene), scene, app::session_options(d, scene, "buttons", app::world_kind(d, scene)), render::builtin_font(), nullptr);
    app::ScriptPlayer player(script.events);
    s->play_due(player);
    for (long i = 0; i < frames; ++i) {
        s->step();
        s->play_due(player);
    }
    std::string line;
    s->dump(320, 200, line);
    return line;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(OneButton, FireAlonePlaysTheGame) {
    // A tap starts the game, a tap fires, a hold of a second thrusts, a last tap fires again.
    const long frames = 300;
    const OneButtonRun r = one_button_run("asteroids", frames, {{10, true}, {12, false}, {60, true}, {63, false},
                                                         {100, true}, {160, false}, {200, true}, {202, false}});
    EXPECT_EQ(count(r.recording, "press left"), 1u) << "the ship turns by itself";
    EXPECT_EQ(count(r.recording, "press thrust"), 1u) << r.recording;
    EXPECT_EQ(count(r.recording, "release thrust"), 1u);
    EXPECT_EQ(count(r.recording, "press fire"), 3u) << "three taps, three fires (the first starts the game)";
    EXPECT_EQ(r.recording.find("one-button"), std::string::npos) << "the mode is not a setting of the recording";
    // The thrust began kHoldSeconds (0.4 s, 24 steps) after the press at frame 100.
    const std::size_t at = r.recording.find("press thrust");
    ASSERT_NE(at, std::string::npos);
    const double t = std::stod(r.recording.substr(r.recording.rfind('\n', at) + 1));
    EXPECT_NEAR(t, (100 + 24) / 60.0, 1.5 / 60);
    EXPECT_NE(r.last_dump.find("\"phase\":\"playing\""), std::string::npos) << "the game runs";
    EXPECT_EQ(replayed_dump(r, frames), r.last_dump);
}

TEST(OneButton, WithoutTheGameATapMovesKToTheNextPreset) {
    // The kiosk starts flat; its presets are -1, 0, +1: a tap gives +1, the next -1.
    const OneButtonRun r = one_button_run("kiosk", 120, {{10, true}, {12, false}, {60, true}, {61, false}});
    EXPECT_EQ(r.K[9], 0);
    EXPECT_EQ(r.K[20], 1);
    EXPECT_EQ(r.K[70], -1);
    EXPECT_EQ(count(r.recording, "tap preset") + count(r.recording, "press preset"), 2u) << r.recording;
    EXPECT_EQ(replayed_dump(r, 120), r.last_dump);
}

}  // namespace one_button_test
}  // namespace
