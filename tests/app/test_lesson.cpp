// Lessons played (app/lesson.hpp) on a display that presses keys at given frames, and printed:
// a step ends when its seconds run out or when what counts as done happens (K past a value, a
// press of fire), the next begins at its own curvature (the worksheet: test_worksheet.cpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "app/platform.hpp"

namespace {
namespace lesson_test {  // (a unity batch shares this file's scope with others)

using namespace noneuclid;
using world::Action;

// Presses and releases at the frames given (counted across the whole lesson); never closes.
class KeyDisplay final : public app::Display {
public:
    struct Key {
        long frame;
        Action control;
        bool pressed;
    };
    explicit KeyDisplay(std::vector<Key> keys) : keys_(std::move(keys)) {
        pixels_.assign(320 * 200 * 4, 0);
        canvas_ = render::Canvas(pixels_.data(), 320, 200, 320 * 4, render::PixelFormat::xrgb8888());
    }
    render::Canvas canvas() override { return canvas_; }
    void present() override { ++presented_; }
    bool wait(int64_t, app::InputSink& sink) override {
        for (const Key& k : keys_)
            if (k.frame == presented_) sink.input({k.control, k.pressed});
        return true;
    }
    bool closing() const override { return false; }
    bool realtime() const override { return false; }
    bool read_back(app::Picture&, std::string&) override { return false; }
    const char* legend() const override { return "keys"; }
    long presented() const { return presented_; }

private:
    std::vector<Key> keys_;
    long presented_ = 0;
    std::vector<uint8_t> pixels_;
    render::Canvas canvas_;
};

// Plays `lesson`; for each step, the frame (presented so far) it began at and K at its start.
struct Played {
    std::vector<long> began;
    std::vector<double> K;
    int status = -1;
};
Played play(const files::Lesson& lesson, KeyDisplay& display) {
    app::Options o = app::defaults(app::Command::run);
    o.engine = world::engine_named("double");
    app::LessonPlayer player(lesson, o, display, "test");
    Played p;
    p.began.push_back(0), p.K.push_back(player.session().curvature());
    int step = 0;
    for (long guard = 0; guard < 20000 && player.tick(); ++guard)
        if (player.step() != step) {
            step = player.step();
            p.began.push_back(display.presented());
            p.K.push_back(player.session().curvature());
        }
    p.status = player.finish();
    return p;
}

TEST(Lesson, StepsEndByTheirSecondsOrWhenDoneAndBeginAtTheirK) {
    files::Lesson l;
    ASSERT_TRUE(files::builtin_lesson("curvature", l));
    // Step 1 lasts 20 s; step 2 ends when K > 0.9 (K+ held from frame 1300: 0.5 a second from
    // 0, so about 108 frames); step 3 when K < -0.9 (K- held from frame 1500, from K = +1).
    KeyDisplay d({{1300, Action::curvature_up, true}, {1450, Action::curvature_up, false},
                  {1500, Action::curvature_down, true}, {1900, Action::curvature_down, false}});
    const Played p = play(l, d);
    ASSERT_EQ(p.began.size(), 4u);
    EXPECT_NEAR(p.began[1], 20 * 60, 2);
    EXPECT_NEAR(p.began[2] - 1300, 0.9 / 0.5 * 60, 3);
    EXPECT_NEAR(p.began[3] - 1500, 1.9 / 0.5 * 60, 3);
    EXPECT_EQ(p.K[0], 0);
    EXPECT_EQ(p.K[2], 1);   // step 3 begins at K = +1
    EXPECT_EQ(p.K[3], -1);
    EXPECT_NEAR(d.presented() - p.began[3], 20 * 60, 2);  // the last step's 20 s
    EXPECT_EQ(p.status, 0);
}

TEST(Lesson, AStepWithoutSecondsEndsOnFire) {
    files::Lesson l;
    files::SceneError e;
    ASSERT_TRUE(files::parse_lesson("title = \"t\"\n[[step]]\ncaption = \"a\"\nscene = \"fig2\"\n"
                                    "[[step]]\ncaption = \"b\"\ncurvature = -0.5\nseconds = 1\n", "t.toml", l, e))
        << e.to_string();
    KeyDisplay d({{300, Action::fire, true}, {302, Action::fire, false}});
    const Played p = play(l, d);
    ASSERT_EQ(p.began.size(), 2u);
    EXPECT_NEAR(p.began[1], 300, 2);
    EXPECT_EQ(p.K[1], -0.5);
    EXPECT_NEAR(d.presented() - p.began[1], 60, 2);
}

}  // namespace lesson_test
}  // namespace

namespace {
namespace attract_lesson_test {  // (a unity batch shares this file's scope with others)

using namespace noneuclid;
using lesson_test::KeyDisplay;
using world::Action;

// The kiosk's attract mode playing a lesson: after a second without a button the lesson's first
// step (fig2 at K = 0) plays with attract mode flying in it; a press gives a new run of the
// scene; left alone again, the lesson comes back.
TEST(Lesson, AttractModePlaysALessonUntilAButtonIsPressed) {
    files::Lesson l;
    ASSERT_TRUE(files::builtin_lesson("lines", l));
    app::Options o = app::defaults(app::Command::run);
    o.scene = "kiosk", o.attract = 1, o.engine = world::engine_named("double");
    KeyDisplay d({{300, Action::thrust, true}, {305, Action::thrust, false}});
    app::AttractLessonRun run(l, o, d, "test", nullptr);
    long lesson_from = -1, back_at = -1, again_at = -1;
    for (long f = 0; f < 800 && run.tick(); ++f) {
        if (run.in_lesson() && lesson_from < 0) {
            lesson_from = d.presented();
            EXPECT_EQ(run.session().options().scene_name, "fig2");
            EXPECT_EQ(run.session().curvature(), 0);
        }
        if (lesson_from >= 0 && back_at < 0 && !run.in_lesson()) {
            back_at = d.presented();
            EXPECT_EQ(run.session().options().scene_name, "kiosk");
            EXPECT_EQ(run.session().frame(), 0) << "a new run of the scene";
        }
        if (back_at >= 0 && again_at < 0 && run.in_lesson()) again_at = d.presented();
    }
    EXPECT_NEAR(lesson_from, 60, 3) << "attract mode's second";
    EXPECT_NEAR(back_at, 300, 2) << "the press";
    EXPECT_NEAR(again_at - back_at, 60, 8) << "a second after the visitor left";
}

}  // namespace attract_lesson_test
}  // namespace
