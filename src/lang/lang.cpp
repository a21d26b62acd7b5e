#include "lang/lang.hpp"

#include <array>

namespace noneuclid::lang {

extern const Entry kGerman[];
extern const int kGermanCount;
extern const Entry kFrench[];
extern const int kFrenchCount;

namespace {

constexpr Entry kEnglish[] = {
#define NONEUCLID_TEXT_ENTRY(name, english) {Text::name, english},
    NONEUCLID_TEXTS(NONEUCLID_TEXT_ENTRY)
#undef NONEUCLID_TEXT_ENTRY
};

constexpr const char* kNames[] = {
#define NONEUCLID_TEXT_STRING(name, english) #name,
    NONEUCLID_TEXTS(NONEUCLID_TEXT_STRING)
#undef NONEUCLID_TEXT_STRING
};

// A language's texts by index, gathered once from its entries (English where it has none).
using Table = std::array<const char*, kTexts>;
Table gather(Catalogue c) {
    Table t{};
    for (int i = 0; i < kTexts; ++i) t[i] = kEnglish[i].text;
    for (int i = 0; i < c.count; ++i) {
        const int at = static_cast<int>(c.entries[i].name);
        if (at >= 0 && at < kTexts && c.entries[i].text) t[at] = c.entries[i].text;
    }
    return t;
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

}  // namespace

Catalogue catalogue(Language language) {
    switch (language) {
        case Language::de: return {kGerman, kGermanCount};
        case Language::fr: return {kFrench, kFrenchCount};
        case Language::en: break;
    }
    return {kEnglish, kTexts};
}

const char* text(Text name, Language language) {
    static const Table tables[kLanguages] = {gather(catalogue(Language::en)), gather(catalogue(Language::de)),
                                             gather(catalogue(Language::fr))};
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

const char* language_code(Language language) {
    constexpr const char* codes[] = {"en", "de", "fr"};
    const int l = static_cast<int>(language);
    return l >= 0 && l < kLanguages ? codes[l] : "en";
}

const char* language_name(Language language) {
    constexpr const char* names[] = {"English", "Deutsch", "Français"};
    const int l = static_cast<int>(language);
    return l >= 0 && l < kLanguages ? names[l] : "English";
}

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

const char* language_choices() { return "en, de or fr"; }

}  // namespace noneuclid::lang
