// Lesson files (files/lesson_file.hpp): read with the scene files' TOML reader, every mistake
// one sentence at its line and column.
#include "files/lesson_file.hpp"

#include <cstdio>
#include <cstdlib>

#include "files/text_file.hpp"
#include "files/toml_reader.hpp"
#include "geometry/projection.hpp"
#include "world/quote.hpp"

namespace noneuclid::files {

using tomlr::Bad;
using tomlr::Reader;

namespace {

constexpr int kMaxSteps = 64;
constexpr std::size_t kMaxText = 400;  // a caption's or question's characters (a HUD's few lines)

std::string text_of(const Reader& r, const toml::table& t, const char* key, const std::string& context) {
    const std::string v = r.plain_string(key, "");
    if (v.size() > kMaxText)
        throw Bad{t.get(key)->source(), context + world::quote(key) + " is " + std::to_string(v.size()) +
                                            " characters long: at most " + std::to_string(kMaxText) + " fit the screen"};
    return v;
}

void read_lesson(const toml::table& root, Lesson& out) {
    const Reader r(root, "");
    r.only({"title", "about", "step"});
    out.title = text_of(r, root, "title", "");
    out.about = text_of(r, root, "about", "");
    if (out.title.empty()) throw Bad{root.source(), "expected title = \"...\": the lesson's name for people"};
    const toml::array* steps = tomlr::tables(root, "step");
    if (!steps || steps->empty()) throw Bad{root.source(), "expected at least one [[step]]"};
    if (steps->size() > kMaxSteps)
        throw Bad{root.source(), "a lesson has at most " + std::to_string(kMaxSteps) + " steps, this one " + std::to_string(steps->size())};
    for (const toml::node& n : *steps) {
        const toml::table& t = *n.as_table();
        const std::string context = "step " + std::to_string(out.steps.size() + 1) + ": ";
        const Reader s(t, context);
        s.only({"caption", "question", "question_curvature", "scene", "curvature", "projection", "done", "seconds"});
        LessonStep step;
        step.caption = text_of(s, t, "caption", context);
        if (step.caption.empty()) throw Bad{t.source(), context + "expected caption = \"...\": what the step shows"};
        step.question = text_of(s, t, "question", context);
        step.scene = s.plain_string("scene", "");
        if (t.get("curvature")) step.has_curvature = true, step.curvature = s.number("curvature", 0, -1, 1, "K");
        if (t.get("question_curvature")) {
            if (step.question.empty())
                throw Bad{t.get("question_curvature")->source(),
                          context + "question_curvature is the K the question asks about: give the step a question too"};
            step.has_question_curvature = true;
            step.question_curvature = s.number("question_curvature", 0, -1, 1, "K");
        }
        step.projection = s.string("projection", "");
        geo::Projection p{};
        if (!step.projection.empty() && !geo::parse_projection_name(step.projection, p))
            throw Bad{t.get("projection")->source(), context + "expected projection = " + world::or_list(geo::projection_names(), true) +
                                                         ", found " + world::quote(step.projection)};
        const std::string done = s.string("done", "fire");
        if (!parse_lesson_done(done, step.done))
            throw Bad{t.get("done")->source(), context + "expected done = \"fire\", \"curvature above K\", \"curvature below K\" "
                                                   "or \"score N\", found " + world::quote(done)};
        step.seconds = s.number("seconds", 0, 0, 3600, "seconds, 0 for no limit");
        out.steps.push_back(std::move(step));
    }
}

}  // namespace

bool parse_lesson_done(const std::string& text, LessonDone& out) {
    char word[16] = {};
    double v = 0;
    int used = 0;
    if (text == "fire") return out = {LessonDone::fire, 0}, true;
    if (std::sscanf(text.c_str(), "curvature %15s %lf%n", word, &v, &used) == 2 && used == static_cast<int>(text.size()) &&
        v >= -1 && v <= 1) {
        const std::string w = word;
        if (w == "above") return out = {LessonDone::curvature_above, v}, true;
        if (w == "below") return out = {LessonDone::curvature_below, v}, true;
        return false;
    }
    if (std::sscanf(text.c_str(), "score %lf%n", &v, &used) == 1 && used == static_cast<int>(text.size()) && v >= 0 &&
        v <= 1e9)
        return out = {LessonDone::score, v}, true;
    return false;
}

std::string lesson_done_words(const LessonDone& d, lang::Language language) {
    using lang::Text;
    const auto t = [language](Text name) { return lang::text(name, language); };
    char buf[96];
    switch (d.kind) {
        case LessonDone::fire: return t(Text::done_fire);
        case LessonDone::curvature_above: std::snprintf(buf, sizeof buf, t(Text::done_above), d.value); return buf;
        case LessonDone::curvature_below: std::snprintf(buf, sizeof buf, t(Text::done_below), d.value); return buf;
        case LessonDone::score: std::snprintf(buf, sizeof buf, t(Text::done_score), d.value); return buf;
    }
    return "";
}

bool parse_lesson(const std::string& text, const std::string& name, Lesson& out, SceneError& error) {
    out = Lesson{};
    out.name = name;
    return tomlr::parse_toml(text, name, error, [&](const toml::table& root) { read_lesson(root, out); });
}

bool load_lesson_file(const std::string& path, Lesson& out, SceneError& error) {
    std::string text, why;
    if (!read_text_file(path, kSceneFileLimit, "a lesson file", text, why)) {
        error = {path, 0, 0, "the lesson: " + why + ": check the path, or name a built-in lesson ('noneuclid lesson' lists them)"};
        return false;
    }
    return parse_lesson(text, path, out, error);
}

}  // namespace noneuclid::files
