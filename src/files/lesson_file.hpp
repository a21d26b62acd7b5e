// Lessons (docs/lessons.md): a file of steps a teacher writes, in TOML, played on any display
// (app/lesson.hpp) and printed as a worksheet. A step shows a scene at a curvature and in a
// projection with a caption, may ask a question, and ends when what counts as done happens, when
// its seconds (a timed round, for a talk) run out, or on fire.
//
//     title = "What curvature is"
//     about = "K from -1 to +1: the same lines on a sphere, a plane and a saddle"
//     [[step]]
//     caption = "This is flat space, K = 0. Hold K+ and watch the grid."
//     scene = "kiosk"            # a built-in scene or a scene file (default: the last step's)
//     curvature = 0              # K at the start (default: the scene's)
//     projection = "equidistant" # (default: the last step's, else equidistant)
//     question = "What happens to the squares as K grows?"
//     question_curvature = 1     # the K the question asks about (default: the step's)
//     done = "curvature above 0.9"   # or "curvature below -0.9", "score 100", "seconds" (below)
//     seconds = 30               # at most this long (0: until done, or fire)
#pragma once

#include "lang/lang.hpp"

#include <string>
#include <vector>

#include "files/scene_file.hpp"  // SceneError

namespace noneuclid::files {

// What ends a step, besides its seconds and fire.
struct LessonDone {
    enum Kind { fire, curvature_above, curvature_below, score } kind = fire;
    double value = 0;
};

struct LessonStep {
    std::string caption, question;
    std::string scene;           // "" the last step's (the first step's default: kiosk)
    bool has_curvature = false;
    double curvature = 0;
    std::string projection;      // "" the last step's
    // The K the question asks about, where it is not the K the step starts at (a step that
    // starts at 0 and asks "what is the sum at K = +1?"): the worksheet's picture is there.
    bool has_question_curvature = false;
    double question_curvature = 0;
    LessonDone done;
    double seconds = 0;          // 0: no time limit
};

struct Lesson {
    std::string name;   // the built-in's name, or the file's path
    std::string title, about;
    std::vector<LessonStep> steps;
};

// "curvature above 0.9" and the like into `out`; false if it is not one (docs/lessons.md).
bool parse_lesson_done(const std::string& text, LessonDone& out);
// The condition in words, as the worksheet prints it ("K above 0.9"), in `language`.
std::string lesson_done_words(const LessonDone& d, lang::Language language = lang::Language::en);

bool parse_lesson(const std::string& text, const std::string& name, Lesson& out, SceneError& error);
bool load_lesson_file(const std::string& path, Lesson& out, SceneError& error);

// The built-in lessons (files/lessons.cpp): their names in order, and one by name (false if none).
std::vector<std::string> builtin_lesson_names();
// In `language` (lang/lessons_<code>.cpp; English for one a language lacks).
bool builtin_lesson(const std::string& name, Lesson& out, lang::Language language = lang::Language::en);
// A built-in lesson's file text (null if there is none by that name).
const char* builtin_lesson_text(const std::string& name, lang::Language language = lang::Language::en);

}  // namespace noneuclid::files
