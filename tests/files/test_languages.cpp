// The languages (lang/lang.hpp, docs/languages.md): every catalogue has every text, keeps its
// printf conversions, and uses only letters the built-in font draws; the built-in lessons in
// German and French are the English ones step for step, their words translated; locales read.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "files/lesson_file.hpp"
#include "geometry/projection.hpp"
#include "lang/lang.hpp"
#include "render/font.hpp"

namespace {
namespace languages_test {  // (a unity batch shares this file's scope with others)

using namespace noneuclid;
using lang::Language;
using lang::Text;

// Every language but English, from the table (lang/languages.hpp): a new row is tested here too.
std::vector<Language> others() {
    std::vector<Language> out;
    for (int l = 1; l < lang::kLanguages; ++l) out.push_back(static_cast<Language>(l));
    return out;
}
const std::vector<Language> kOthers = others();

// The printf conversions of a format, in order ("%ld", "%.0f", ...; "%%" is none).
std::vector<std::string> conversions(const char* s) {
    std::vector<std::string> out;
    for (const char* p = s; *p; ++p) {
        if (*p != '%') continue;
        if (p[1] == '%') {
            ++p;
            continue;
        }
        const char* q = p + 1;
        while (*q && !std::isalpha(static_cast<unsigned char>(*q))) ++q;
        while (*q == 'l' || *q == 'h') ++q;
        out.emplace_back(p, *q ? q + 1 : q);
        p = *q ? q : q - 1;
    }
    return out;
}

// The code points of UTF-8 text (each malformed byte a U+FFFD).
std::vector<char32_t> code_points(const std::string& s) {
    std::vector<char32_t> out;
    for (std::size_t i = 0; i < s.size();) {
        const unsigned char b = static_cast<unsigned char>(s[i]);
        const int n = b < 0x80 ? 1 : (b >> 5) == 6 ? 2 : (b >> 4) == 14 ? 3 : (b >> 3) == 30 ? 4 : 0;
        if (n == 0 || i + n > s.size()) {
            out.push_back(0xFFFD), ++i;
            continue;
        }
        char32_t c = n == 1 ? b : b & (0x7F >> n);
        for (int k = 1; k < n; ++k) c = c << 6 | (static_cast<unsigned char>(s[i + k]) & 0x3F);
        out.push_back(c), i += n;
    }
    return out;
}

// What of `text` the built-in font cannot draw, as "U+00E5 U+2019", or "".
std::string undrawn(const std::string& text) {
    std::string out;
    for (char32_t c : code_points(text))
        if (c != '\n' && !render::builtin_font_draws(c)) {
            char buf[16];
            std::snprintf(buf, sizeof buf, " U+%04X", static_cast<unsigned>(c));
            out += buf;
        }
    return out;
}

TEST(Languages, EveryCatalogueHasEveryTextOnce) {
    for (Language l : kOthers) {
        const lang::Catalogue c = lang::catalogue(l);
        std::map<int, int> seen;
        for (int i = 0; i < c.count; ++i) {
            ASSERT_NE(c.entries[i].text, nullptr) << lang::language_code(l) << " entry " << i;
            EXPECT_NE(c.entries[i].text[0], '\0') << lang::language_code(l) << ": " << lang::text_name(c.entries[i].name) << " is empty";
            ++seen[static_cast<int>(c.entries[i].name)];
        }
        for (int i = 0; i < lang::kTexts; ++i) {
            const char* name = lang::text_name(static_cast<Text>(i));
            EXPECT_EQ(seen[i], 1) << lang::language_code(l) << " has " << seen[i] << " texts named " << name
                                  << " (each needs exactly one)";
        }
    }
}

// The HUD names a projection by the text named as it is (render/hud.cpp): every projection of
// the table has one, so a new projection's word is in every language's file.
TEST(Languages, EveryProjectionHasItsWord) {
    for (geo::Projection p : geo::kProjections) {
        lang::Text t;
        EXPECT_TRUE(lang::text_named(geo::projection_name(p), t)) << geo::projection_name(p) << ": add it to lang/texts.hpp";
    }
}

TEST(Languages, EachTextKeepsTheEnglishConversionsInOrder) {
    for (Language l : kOthers)
        for (int i = 0; i < lang::kTexts; ++i) {
            const Text t = static_cast<Text>(i);
            EXPECT_EQ(conversions(lang::text(t, l)), conversions(lang::text(t, Language::en)))
                << lang::language_code(l) << ": " << lang::text_name(t) << " = \"" << lang::text(t, l) << "\"";
        }
}

// The HUD's texts are drawn in the built-in font where no console font is found (the page, a
// desktop without kbd's fonts): each of their letters must be one it draws, not its '?'.
TEST(Languages, TheBuiltInFontDrawsEveryLetterOfTheHudsTexts) {
    for (int li = 0; li < lang::kLanguages; ++li)
        for (int i = 0; i < lang::kTexts; ++i) {
            const Language l = static_cast<Language>(li);
            const Text t = static_cast<Text>(i);
            if (std::string(lang::text_name(t)).rfind("page_", 0) == 0) continue;  // the page's: the browser's fonts
            EXPECT_EQ(undrawn(lang::text(t, l)), "") << lang::language_code(l) << ": " << lang::text_name(t);
        }
    // And the letters are their own: Ü is neither U nor '?', é neither e nor '?'.
    const render::Font& f = render::builtin_font();
    const auto same = [&f](char32_t a, char32_t b) {
        for (int y = 0; y < f.height; ++y)
            for (int x = 0; x < f.width; ++x)
                if (f.pixel(f.glyph_for(a), x, y) != f.pixel(f.glyph_for(b), x, y)) return false;
        return true;
    };
    for (auto [accented, plain] : {std::pair{U'Ü', U'U'}, {U'é', U'e'}, {U'è', U'e'}, {U'ß', U's'}, {U'ç', U'c'}, {U'À', U'A'}}) {
        EXPECT_FALSE(same(accented, plain)) << static_cast<unsigned>(accented);
        EXPECT_FALSE(same(accented, U'?')) << static_cast<unsigned>(accented);
    }
    EXPECT_FALSE(render::builtin_font_draws(U'å'));  // not drawn: '?'
    EXPECT_TRUE(same(U'å', U'?'));
}

TEST(Languages, TheBuiltInLessonsAreTheEnglishOnesStepForStepTranslated) {
    for (const std::string& name : files::builtin_lesson_names()) {
        files::Lesson en;
        ASSERT_TRUE(files::builtin_lesson(name, en, Language::en));
        for (Language l : kOthers) {
            const char* code = lang::language_code(l);
            files::Lesson t;
            ASSERT_TRUE(files::builtin_lesson(name, t, l)) << code << ": " << name;
            ASSERT_NE(files::builtin_lesson_text(name, l), files::builtin_lesson_text(name, Language::en))
                << code << " has no " << name << " of its own";
            EXPECT_NE(t.title, en.title) << code << ": " << name;
            EXPECT_EQ(undrawn(t.title + t.about), "") << code << ": " << name;
            ASSERT_EQ(t.steps.size(), en.steps.size()) << code << ": " << name;
            for (std::size_t i = 0; i < t.steps.size(); ++i) {
                const files::LessonStep &a = en.steps[i], &b = t.steps[i];
                const std::string at = std::string(code) + ": " + name + " step " + std::to_string(i + 1);
                EXPECT_EQ(b.scene, a.scene) << at;
                EXPECT_EQ(b.has_curvature, a.has_curvature) << at;
                EXPECT_EQ(b.curvature, a.curvature) << at;
                EXPECT_EQ(b.projection, a.projection) << at;
                EXPECT_EQ(b.done.kind, a.done.kind) << at;
                EXPECT_EQ(b.done.value, a.done.value) << at;
                EXPECT_EQ(b.seconds, a.seconds) << at;
                EXPECT_NE(b.caption, a.caption) << at << ": the caption is not translated";
                EXPECT_EQ(b.question.empty(), a.question.empty()) << at;
                if (!a.question.empty()) {
                    EXPECT_NE(b.question, a.question) << at;
                }
                EXPECT_EQ(undrawn(b.caption + b.question), "") << at;
            }
        }
    }
}

// The table's rows read back: codes, names, the refusal's list, and every language's lessons are
// the English ones by name, in order (a language lacking one would fall back to the English).
TEST(Languages, TheTablesRowsReadBack) {
    EXPECT_STREQ(lang::language_choices(), "en, de or fr");
    EXPECT_STREQ(lang::language_name(Language::fr), "Français");
    EXPECT_STREQ(lang::language_code(Language::de), "de");
    const lang::Lessons en = lang::lessons(Language::en);
    ASSERT_GE(en.count, 3);
    for (Language l : kOthers) {
        const lang::Lessons o = lang::lessons(l);
        ASSERT_EQ(o.count, en.count) << lang::language_code(l);
        for (int i = 0; i < en.count; ++i) EXPECT_STREQ(o.lessons[i].name, en.lessons[i].name) << lang::language_code(l);
    }
}

TEST(Languages, LocalesAndCodesRead) {
    const std::pair<const char*, Language> good[] = {{"en", Language::en},          {"de", Language::de},
                                                     {"fr", Language::fr},          {"de_DE.UTF-8", Language::de},
                                                     {"fr-CH", Language::fr},       {"de@euro", Language::de},
                                                     {"en_GB.UTF-8", Language::en}, {"fr_FR", Language::fr}};
    for (auto [code, want] : good) {
        Language got = Language::en;
        EXPECT_TRUE(lang::parse_language(code, got)) << code;
        EXPECT_EQ(got, want) << code;
    }
    for (const char* bad : {"", "C", "POSIX", "C.UTF-8", "es_ES.UTF-8", "deu", "french", "d", "EN"}) {
        Language got = Language::en;
        EXPECT_FALSE(lang::parse_language(bad, got)) << bad;
    }
    // Names and codes both ways.
    for (int i = 0; i < lang::kTexts; ++i) {
        Text back{};
        ASSERT_TRUE(lang::text_named(lang::text_name(static_cast<Text>(i)), back));
        EXPECT_EQ(static_cast<int>(back), i);
    }
    Text none{};
    EXPECT_FALSE(lang::text_named("no_such_text", none));
    // What ends a step, in words.
    files::LessonDone d{files::LessonDone::curvature_above, 0.9};
    EXPECT_EQ(files::lesson_done_words(d, Language::de), "K über 0.9");
    EXPECT_EQ(files::lesson_done_words(d, Language::fr), "K au-dessus de 0.9");
}

}  // namespace languages_test
}  // namespace
