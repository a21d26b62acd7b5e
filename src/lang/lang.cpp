#include "lang/lang.hpp"

#include <array>

namespace noneuclid::lang {

namespace {

// The languages' rows and tables, in the order of lang::Language.
struct Row {
    const char* code;
    const char* name;
    Catalogue texts;
    Lessons lessons;
};
const Row kRows[] = {
#define NONEUCLID_LANGUAGE_ROW(code, name) \
    {#code, name, {kTexts_##code, kTextsCount_##code}, {kLessons_##code, kLessonsCount_##code}},
    NONEUCLID_LANGUAGES(NONEUCLID_LANGUAGE_ROW)
#undef NONEUCLID_LANGUAGE_ROW
};
static_assert(sizeof kRows / sizeof kRows[0] == kLanguages);

const Row& row(Language language) {
    const int l = static_cast<int>(language);
    return kRows[l >= 0 && l < kLanguages ? l : 0];
}

constexpr const char* kNames[] = {
#define NONEUCLID_TEXT_STRING(name, english) #name,
    NONEUCLID_TEXTS(NONEUCLID_TEXT_STRING)
#undef NONEUCLID_TEXT_STRING
};

// A language's texts by index, gathered once from its entries (English where it has none).
using Table = std::array<const char*, kTexts>;
Table gather(Catalogue c) {
    Table t{};
    for (int i = 0; i < kTexts; ++i) t[i] = kTexts_en[i].text;
    for (int i = 0; i < c.count; ++i) {
        const int at = static_cast<int>(c.entries[i].name);
        if (at >= 0 && at < kTexts && c.entries[i].text) t[at] = c.entries[i].text;
    }
    return t;
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

}  // namespace

Catalogue catalogue(Language language) { return row(language).texts; }

Lessons lessons(Language language) { return row(language).lessons; }

const char* text(Text name, Language language) {
    static const std::array<Table, kLanguages> tables = [] {
        std::array<Table, kLanguages> t{};
        for (int l = 0; l < kLanguages; ++l) t[l] = gather(kRows[l].texts);
        return t;
    }();
    const int at = static_cast<int>(name), l = static_cast<int>(language);
    if (at < 0 || at >= kTexts) return "";
    return tables[l >= 0 && l < kLanguages ? l : 0][at];
}

const char* text_name(Text name) {
    const int at = static_cast<int>(name);
    return at >= 0 && at < kTexts ? kNames[at] : nullptr;
}

bool text_named(std::string_view name, Text& out) {
    for (int i = 0; i < kTexts; ++i)
        if (name == kNames[i]) return out = static_cast<Text>(i), true;
    return false;
}

const char* language_code(Language language) { return row(language).code; }

const char* language_name(Language language) { return row(language).name; }

bool parse_language(std::string_view code, Language& out) {
    for (int l = 0; l < kLanguages; ++l) {
        const std::string_view c = language_code(static_cast<Language>(l));
        // The code alone, or followed by a locale's territory, codeset or modifier.
        if (code == c || (starts_with(code, c) && code.size() > 2
                          && (code[2] == '_' || code[2] == '-' || code[2] == '.' || code[2] == '@')))
            return out = static_cast<Language>(l), true;
    }
    return false;
}

const char* language_choices() {
    // "en, de or fr", made once from the rows.
    static const std::array<char, 8 * kLanguages> words = [] {
        std::array<char, 8 * kLanguages> w{};
        std::size_t at = 0;
        for (int l = 0; l < kLanguages; ++l) {
            const char* sep = l == 0 ? "" : l + 1 == kLanguages ? " or " : ", ";
            for (const char* p = sep; *p; ++p) w[at++] = *p;
            for (const char* p = kRows[l].code; *p; ++p) w[at++] = *p;
        }
        return w;
    }();
    return words.data();
}

}  // namespace noneuclid::lang
