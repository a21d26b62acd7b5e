// Lesson files (files/lesson_file.hpp): the built-in lessons read and refer to built-in scenes;
// a bad file is one sentence at its line and column; what counts as done reads both ways.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "files/lesson_file.hpp"
#include "world/scene.hpp"

namespace {
namespace lesson_file_test {  // (a unity batch shares this file's scope with others)

using namespace noneuclid;

TEST(LessonFile, TheBuiltInLessonsReadAndUseBuiltInScenes) {
    const auto names = files::builtin_lesson_names();
    ASSERT_GE(names.size(), 4u);
    const auto scenes = world::builtin_scene_names();
    for (const std::string& name : names) {
        files::Lesson l;
        ASSERT_TRUE(files::builtin_lesson(name, l)) << name;
        // Their text is a lesson file: read as one, it gives the same lesson.
        files::Lesson again;
        files::SceneError e;
        ASSERT_TRUE(files::parse_lesson(files::builtin_lesson_text(name), name, again, e)) << e.to_string();
        EXPECT_EQ(again.steps.size(), l.steps.size());
        EXPECT_FALSE(l.title.empty());
        EXPECT_GE(l.steps.size(), 2u) << name;
        ASSERT_FALSE(l.steps[0].scene.empty()) << name << ": the first step names its scene";
        for (const files::LessonStep& s : l.steps) {
            EXPECT_FALSE(s.caption.empty());
            if (!s.scene.empty()) {
                EXPECT_NE(std::find(scenes.begin(), scenes.end(), s.scene), scenes.end()) << s.scene;
            }
            EXPECT_TRUE(s.seconds > 0 || s.done.kind != files::LessonDone::fire) << name << ": a step with no end but fire";
        }
    }
    files::Lesson none;
    EXPECT_FALSE(files::builtin_lesson("nope", none));
}

TEST(LessonFile, WhatCountsAsDoneReadsAndSays) {
    files::LessonDone d;
    ASSERT_TRUE(files::parse_lesson_done("curvature above 0.9", d));
    EXPECT_EQ(d.kind, files::LessonDone::curvature_above);
    EXPECT_EQ(d.value, 0.9);
    EXPECT_EQ(files::lesson_done_words(d), "K above 0.9");
    ASSERT_TRUE(files::parse_lesson_done("curvature below -0.5", d));
    EXPECT_EQ(files::lesson_done_words(d), "K below -0.5");
    ASSERT_TRUE(files::parse_lesson_done("score 100", d));
    EXPECT_EQ(files::lesson_done_words(d), "a score of 100");
    ASSERT_TRUE(files::parse_lesson_done("fire", d));
    for (const char* bad : {"", "curvature", "curvature above", "curvature above 2", "curvature near 0.5", "score -1",
                            "score 10 points", "curvature above 0.5x", "Fire"})
        EXPECT_FALSE(files::parse_lesson_done(bad, d)) << bad;
}

TEST(LessonFile, ABadFileIsOneSentenceAtItsPlace) {
    struct Bad {
        const char* text;
        const char* where;
        const char* message;
    };
    const std::string long_caption(401, 'x');
    const std::string too_long = "title = \"t\"\n[[step]]\ncaption = \"" + long_caption + "\"\n";
    const Bad cases[] = {
        {"[[step]]\ncaption = \"c\"\n", "t.toml:1:1", "expected title ="},
        {"title = \"t\"\n", "t.toml:1:1", "expected at least one [[step]]"},
        {"title = \"t\"\ncolour = 1\n[[step]]\ncaption = \"c\"\n", "t.toml:2:1", "unknown key 'colour'"},
        {"title = \"t\"\n[[step]]\nscene = \"kiosk\"\n", "t.toml:2:1", "step 1: expected caption ="},
        {"title = \"t\"\n[[step]]\ncaption = \"c\"\ncurvature = 2\n", "t.toml:4:13", "step 1: 'curvature' must be from -1 to 1"},
        {"title = \"t\"\n[[step]]\ncaption = \"c\"\nprojection = \"mercator\"\n", "t.toml:4:14", "step 1: expected projection ="},
        {"title = \"t\"\n[[step]]\ncaption = \"c\"\ndone = \"when ready\"\n", "t.toml:4:8", "step 1: expected done = \"fire\""},
        {"title = \"t\"\n[[step]]\ncaption = \"c\"\nseconds = -1\n", "t.toml:4:11", "step 1: 'seconds' must be from 0"},
        {too_long.c_str(), "t.toml:3:11", "step 1: 'caption' is 401 characters long: at most 400"},
        {"title = \n", "t.toml:1:9", "not valid TOML"},
    };
    for (const Bad& c : cases) {
        files::Lesson l;
        files::SceneError e;
        ASSERT_FALSE(files::parse_lesson(c.text, "t.toml", l, e)) << c.text;
        const std::string s = e.to_string();
        EXPECT_NE(s.find(c.where), std::string::npos) << s;
        EXPECT_NE(s.find(c.message), std::string::npos) << s;
    }
    files::Lesson l;
    files::SceneError e;
    EXPECT_FALSE(files::load_lesson_file("/nonexistent/lesson.toml", l, e));
    EXPECT_NE(e.to_string().find("the lesson: cannot read it"), std::string::npos) << e.to_string();
}

}  // namespace lesson_file_test
}  // namespace
