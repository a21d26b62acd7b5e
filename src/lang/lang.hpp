// The languages the program speaks and its catalogue of texts (lang/texts.hpp names them):
// English, German and French. text() gives a text in a language, English where a catalogue
// lacks it (which a test forbids). No heap, no OS: the tables are constant data.
#pragma once

#include <cstdint>
#include <string_view>

#include "lang/texts.hpp"

namespace noneuclid::lang {

enum class Language : uint8_t { en, de, fr };
inline constexpr int kLanguages = 3;

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
// "en, de or fr": for the sentence that refuses another.
const char* language_choices();

}  // namespace noneuclid::lang
