// The languages the program speaks (lang/languages.hpp, a row each), their catalogues of texts
// (lang/texts.hpp names them) and their built-in lessons' file texts. text() gives a text in a
// language, English where a catalogue lacks it (which a test forbids). No heap, no OS: the
// tables are constant data.
#pragma once

#include <cstdint>
#include <string_view>

#include "lang/languages.hpp"
#include "lang/texts.hpp"

namespace noneuclid::lang {

enum class Language : uint8_t {
#define NONEUCLID_LANGUAGE_CODE(code, name) code,
    NONEUCLID_LANGUAGES(NONEUCLID_LANGUAGE_CODE)
#undef NONEUCLID_LANGUAGE_CODE
};
inline constexpr int kLanguages = 0
#define NONEUCLID_LANGUAGE_COUNT(code, name) +1
    NONEUCLID_LANGUAGES(NONEUCLID_LANGUAGE_COUNT)
#undef NONEUCLID_LANGUAGE_COUNT
    ;

enum class Text : uint16_t {
#define NONEUCLID_TEXT_NAME(name, english) name,
    NONEUCLID_TEXTS(NONEUCLID_TEXT_NAME)
#undef NONEUCLID_TEXT_NAME
};
inline constexpr int kTexts = 0
#define NONEUCLID_TEXT_COUNT(name, english) +1
    NONEUCLID_TEXTS(NONEUCLID_TEXT_COUNT)
#undef NONEUCLID_TEXT_COUNT
    ;

// A language's entry: a text by name. Each language's file lists its entries.
struct Entry {
    Text name;
    const char* text;
};
struct Catalogue {
    const Entry* entries;
    int count;
};
// The entries of a language as its file lists them (English: the index's own).
Catalogue catalogue(Language language);

// A built-in lesson: its name and its lesson file's text (docs/lessons.md), in one language.
struct LessonText {
    const char* name;
    const char* text;
};
struct Lessons {
    const LessonText* lessons;
    int count;
};
// The built-in lessons of a language, as its lessons' file lists them.
Lessons lessons(Language language);

// Each language's tables (lang/<code>.cpp, lang/lessons_<code>.cpp), for lang.cpp.
#define NONEUCLID_LANGUAGE_TABLES(code, name)  \
    extern const Entry kTexts_##code[];         \
    extern const int kTextsCount_##code;        \
    extern const LessonText kLessons_##code[];  \
    extern const int kLessonsCount_##code;
NONEUCLID_LANGUAGES(NONEUCLID_LANGUAGE_TABLES)
#undef NONEUCLID_LANGUAGE_TABLES

// `name` in `language`: its catalogue's text, the English if the catalogue lacks it.
const char* text(Text name, Language language);
// The name of a text ("legend_keys"), for the page and for messages; null past the last.
const char* text_name(Text name);
// The text named `name`; false if none is.
bool text_named(std::string_view name, Text& out);

// "en", "de", "fr".
const char* language_code(Language language);
// "English", "Deutsch", "Français": each in its own language.
const char* language_name(Language language);
// A language from a code ("de") or a locale ("de_DE.UTF-8", "fr-CH", "de@euro"); false for
// anything else (C, POSIX, an empty string, a language without a catalogue).
bool parse_language(std::string_view code, Language& out);
// "en, de or fr" (every code of the table): for the sentence that refuses another.
const char* language_choices();

}  // namespace noneuclid::lang
