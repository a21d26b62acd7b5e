// The built-in lessons (docs/lessons.md): their file texts are each language's
// (lang/lessons_<code>.cpp), parsed here like any lesson file.
#include "files/lesson_file.hpp"

namespace noneuclid::files {

std::vector<std::string> builtin_lesson_names() {
    std::vector<std::string> out;
    const lang::Lessons l = lang::lessons(lang::Language::en);
    for (int i = 0; i < l.count; ++i) out.push_back(l.lessons[i].name);
    return out;
}

const char* builtin_lesson_text(const std::string& name, lang::Language language) {
    const lang::Lessons l = lang::lessons(language);
    for (int i = 0; i < l.count; ++i)
        if (name == l.lessons[i].name) return l.lessons[i].text;
    return language == lang::Language::en ? nullptr : builtin_lesson_text(name, lang::Language::en);
}

bool builtin_lesson(const std::string& name, Lesson& out, lang::Language language) {
    const char* text = builtin_lesson_text(name, language);
    SceneError e;
    return text && parse_lesson(text, name, out, e);
}

}  // namespace noneuclid::files
