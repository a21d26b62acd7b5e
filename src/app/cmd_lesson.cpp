// `noneuclid lesson`: the built-in lessons listed; `noneuclid lesson NAME|FILE` plays one on
// run's display (app/lesson.hpp) with run's options; `--worksheet FILE` and `--answers FILE`
// write its worksheet and the teacher's key instead (app/worksheet.hpp: PNG, or PDF when named
// .pdf, on --paper a4 or letter), and `--print` the lesson's own file text (a built-in's, to copy
// and change).
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/displays.hpp"
#include "app/lesson.hpp"
#include "app/worksheet.hpp"
#include "app/setup.hpp"
#include "world/quote.hpp"

namespace noneuclid::app {

files::Lesson load_lesson(const std::string& name, lang::Language language) {
    files::Lesson lesson;
    if (files::builtin_lesson(name, lesson, language)) return lesson;
    const bool file = name.find('/') != std::string::npos || name.ends_with(".toml");
    if (!file)
        usage_error("there is no built-in lesson '" + world::printable(name) + "': the lessons are " +
                    world::or_list(files::builtin_lesson_names()) + ", or name a lesson file (.toml).");
    files::SceneError e;
    if (!files::load_lesson_file(name, lesson, e)) usage_error(e.to_string() + ".");
    return lesson;
}

int lesson_command(int argc, char** argv, int first) {
    if (first >= argc || argv[first][0] == '-') {
        // The list, in the language --lang (alone) or the locale names.
        Options o = defaults(Command::run);
        if (first < argc && std::strcmp(argv[first], "--lang") != 0)
            usage_error("lesson takes a lesson's name first (or nothing, or --lang L, for the list), not '" +
                        world::printable(argv[first]) + "'.");
        Args args(argc, argv, first);
        parse_options(args, o, Command::run);
        const lang::Language language = resolve_language(o);
        for (const std::string& name : files::builtin_lesson_names()) {
            files::Lesson l;
            files::builtin_lesson(name, l, language);
            std::printf("%-10s  %s: %s (%zu steps)\n", name.c_str(), l.title.c_str(), l.about.c_str(), l.steps.size());
        }
        return 0;
    }
    // --worksheet, --answers, --paper and --print are the lesson's own; the rest are run's.
    std::string worksheet, answers, paper_name = "a4";
    bool print = false;
    std::vector<char*> rest = {argv[0]};
    struct Own {
        const char* name;
        std::string* value;
        const char* example;
    };
    const Own own[] = {{"--worksheet", &worksheet, "--worksheet lesson.pdf"},
                       {"--answers", &answers, "--answers key.pdf"},
                       {"--paper", &paper_name, "--paper letter"}};
    for (int i = first + 1; i < argc; ++i) {
        bool taken = false;
        for (const Own& k : own) {
            const std::size_t n = std::strlen(k.name);
            if (std::strncmp(argv[i], k.name, n) == 0 && argv[i][n] == '=') {  // (--option=value, as app/args.hpp reads it)
                *k.value = argv[i] + n + 1, taken = true;
            } else if (std::strcmp(argv[i], k.name) == 0) {
                if (i + 1 >= argc) usage_error(std::string(k.name) + " needs a value: " + k.example + " (see noneuclid lesson --help).");
                *k.value = argv[++i], taken = true;
            }
        }
        if (taken) continue;
        if (std::strcmp(argv[i], "--print") == 0) print = true;
        else rest.push_back(argv[i]);
    }
    Paper paper = Paper::a4;
    if (!parse_paper(paper_name, paper))
        usage_error("--paper takes a4 or letter, not '" + world::printable(paper_name) + "'.");
    if (print) {
        Options o = defaults(Command::run);
        Args args(static_cast<int>(rest.size()), rest.data(), 1);
        parse_options(args, o, Command::run);
        const char* text = files::builtin_lesson_text(argv[first], resolve_language(o));
        if (!text && !files::builtin_lesson_text(argv[first])) load_lesson(argv[first], lang::Language::en);  // says why
        if (!text) usage_error("--print writes a built-in lesson's file: '" + world::printable(argv[first]) + "' is a file already.");
        std::fputs(text, stdout);
        return 0;
    }
    Options base = defaults(Command::run);
    {
        Args args(static_cast<int>(rest.size()), rest.data(), 1);
        parse_options(args, base, Command::run);
    }
    const files::Lesson lesson = load_lesson(argv[first], resolve_language(base));
    if (!base.record.empty()) usage_error("--record keeps one scene's run: a lesson's steps are not recorded (record a step with run --scene).");
    if (!worksheet.empty() || !answers.empty()) {
        // A .pdf is a PDF; any other name must end .png.
        for (const Own& k : {own[0], own[1]})
            if (!k.value->empty())
                check_output(k.name, *k.value, names_pdf(*k.value) ? ".pdf" : ".png", "a PNG, or a PDF when named .pdf");
        for (const Own& k : {own[0], own[1]}) {
            if (k.value->empty()) continue;
            std::string error;
            const bool key = k.value == &answers;
            if (!write_worksheet(lesson, base, *k.value, key, paper, error)) {
                std::fprintf(stderr, "noneuclid: %s\n", error.c_str());
                return 1;
            }
            std::fprintf(stderr, "noneuclid: wrote %s (the %s of '%s', %zu steps).\n", k.value->c_str(),
                         key ? "key" : "worksheet", lesson.title.c_str(), lesson.steps.size());
        }
        return 0;
    }
    // Played on run's display: the same choice and the same options as `noneuclid run`.
    return play_lesson(lesson, static_cast<int>(rest.size()), rest.data(), 1);
}

}  // namespace noneuclid::app
