// The recording's parser (recording.hpp): line by line, words parted by spaces and tabs, '#'
// starting a comment, as app/script.cpp reads the same files.
#include "recording.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace noneuclid::mcu {
namespace {

// The next word of `*at` (spaces and tabs part words), NUL-terminated in place; null at the end.
char* next_word(char** at) {
    char* p = *at;
    while (*p == ' ' || *p == '\t' || *p == '\r') ++p;
    if (*p == '\0') return nullptr;
    char* const word = p;
    while (*p != '\0' && *p != ' ' && *p != '\t' && *p != '\r') ++p;
    if (*p != '\0') *p++ = '\0';
    *at = p;
    return word;
}

bool on_off(const char* v, bool& out) {
    if (std::strcmp(v, "on") == 0) return out = true, true;
    if (std::strcmp(v, "off") == 0) return out = false, true;
    return false;
}

// One setting line (key, value).
bool setting(const char* key, const char* value, Recording& out, char* why, std::size_t size) {
    bool flag = false;
    auto must_be = [&](const char* want) {
        if (std::strcmp(value, want) == 0) return true;
        std::snprintf(why, size, "the setting '%.24s %.40s': the firmware draws only %.24s %s.", key, value, key, want);
        return false;
    };
    if (std::strcmp(key, "scene") == 0) {
        if (std::strlen(value) >= sizeof out.scene) return must_be("kiosk"), false;
        std::strcpy(out.scene, value);
        return true;
    }
    if (std::strcmp(key, "engine") == 0) return must_be("fixed");
    if (std::strcmp(key, "size") == 0) return must_be("240x240");
    if (std::strcmp(key, "format") == 0) return must_be("rgb565");
    if (std::strcmp(key, "palette") == 0) return must_be("scene");
    if (std::strcmp(key, "lang") == 0) return out.named_lang = must_be("en");
    if (std::strcmp(key, "font") == 0) return out.named_font = must_be("builtin");
    if (std::strcmp(key, "legend") == 0) return must_be("buttons");
    if (std::strcmp(key, "large-hud") == 0) return must_be("off");
    if (std::strcmp(key, "aa") == 0 && on_off(value, flag)) return out.aa = flag, true;
    if (std::strcmp(key, "hud") == 0 && on_off(value, flag)) return out.hud = flag, true;
    if (std::strcmp(key, "projection") == 0) {
        for (geo::Projection p : geo::kProjections)
            if (std::strcmp(value, geo::projection_name(p)) == 0) return out.projection = p, true;
    }
    if (std::strcmp(key, "frames") == 0 || std::strcmp(key, "best") == 0) {
        char* end = nullptr;
        const long n = std::strtol(value, &end, 10);
        if (*end == '\0' && n >= 0) return (key[0] == 'f' ? out.frames : out.best) = n, true;
    }
    std::snprintf(why, size, "the setting '%s %s' is not one the firmware plays.", key, value);
    return false;
}

}  // namespace

bool parse_recording(char* text, Recording& out, char* why, std::size_t why_size) {
    out = Recording{};
    long line = 0;
    for (char* p = text; p && *p;) {
        char* const start = p;
        p = std::strchr(p, '\n');
        if (p) *p++ = '\0';
        ++line;
        if (char* hash = std::strchr(start, '#')) *hash = '\0';
        char* at = start;
        const char* first = next_word(&at);
        if (!first) continue;
        char* end = nullptr;
        const double time = std::strtod(first, &end);
        if (*end != '\0' || end == first) {  // a setting: the rest of the line is its value
            while (*at == ' ' || *at == '\t') ++at;
            char* tail = at + std::strlen(at);
            while (tail > at && (tail[-1] == ' ' || tail[-1] == '\t' || tail[-1] == '\r')) *--tail = '\0';
            if (!setting(first, at, out, why, why_size)) return false;
            continue;
        }
        const char* kind = next_word(&at);
        const char* what = next_word(&at);
        RecordedEvent e;
        e.time = time;
        const bool known = kind && (std::strcmp(kind, "press") == 0 || std::strcmp(kind, "release") == 0 ||
                                    std::strcmp(kind, "tap") == 0);
        if (!known || !what || !world::parse_action(what, e.control) || e.control == world::Action::quit || next_word(&at)) {
            std::snprintf(why, why_size, "line %ld: expected 'TIME press|release|tap CONTROL' (not quit, mark or attract).",
                          line);
            return false;
        }
        e.pressed = std::strcmp(kind, "release") != 0;
        e.tap = std::strcmp(kind, "tap") == 0;
        if (out.count == Recording::kMaxEvents) {
            std::snprintf(why, why_size, "more than %d events.", Recording::kMaxEvents);
            return false;
        }
        // Sorted as it goes, ties in file order (an insertion after every earlier-or-equal time).
        int i = out.count++;
        for (; i > 0 && out.events[i - 1].time > e.time; --i) out.events[i] = out.events[i - 1];
        out.events[i] = e;
    }
    // Without them render takes the machine's console font and locale, which the firmware has not.
    bool hud_event = false;
    for (int i = 0; i < out.count; ++i) hud_event = hud_event || out.events[i].control == world::Action::hud;
    if ((out.hud || hud_event) && !(out.named_font && out.named_lang)) {
        std::snprintf(why, why_size, "with the HUD on, the recording must say 'font builtin' and 'lang en'.");
        return false;
    }
    return true;
}

}  // namespace noneuclid::mcu
