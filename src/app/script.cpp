#include "app/script.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "world/quote.hpp"
#include "files/text_file.hpp"

namespace noneuclid::app {

namespace {
// The longest setting value: a path's (PATH_MAX).
constexpr std::size_t kSettingLimit = 4096;

const char* const kSettingKeys[] = {"scene", "curvature", "engine", "projection", "size",   "format", "aa",
                                    "hud",   "font",      "legend", "frames",     "best",   "centre", "view",
                                    "tissot", "palette", "large-hud", "hud-scale", "lang", nullptr};

bool is_setting(const std::string& word) {
    for (const char* const* k = kSettingKeys; *k; ++k)
        if (word == *k) return true;
    return false;
}

std::string trim(const std::string& s) {
    const std::size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return {};
    return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

// The first byte of `s` that is a control character other than a tab, or npos.
std::size_t first_control(const std::string& s) {
    for (std::size_t i = 0; i < s.size(); ++i)
        if ((static_cast<unsigned char>(s[i]) < 0x20 && s[i] != '\t') || s[i] == 0x7F) return i;
    return std::string::npos;
}

// An event's time: the whole word a decimal number >= 0 (digits, a point, an exponent), finite.
// The whole word: strtod stops at a NUL, which must not end the word early ("1.5\0junk").
bool read_time(const std::string& word, double& time) {
    if (word.empty() || word.find_first_not_of("0123456789.eE+-") != std::string::npos) return false;
    char* end = nullptr;
    time = std::strtod(word.c_str(), &end);
    return end == word.c_str() + word.size() && std::isfinite(time) && time >= 0;
}

// Words are parted by spaces and tabs only: a control byte between them (a vertical tab, a form
// feed, a carriage return inside the line), which a reader splitting on any white space would
// take for a space, is refused. (One inside a word makes that word wrong, and is said so.)
std::string control_between(const std::string& content, std::size_t at) {
    return "a control character (" + world::quote(content.substr(at, 1)) + ") where only spaces and tabs may part words: " +
           world::quote(content);
}

std::string control_list() {
    std::string names;
    for (int i = 0; i < world::kActionCount; ++i) {
        const auto c = static_cast<world::Action>(i);
        if (c == world::Action::quit) continue;
        names += std::string(names.empty() ? "" : ", ") + world::action_name(c);
    }
    return names;
}
}  // namespace

const char* const* setting_keys() { return kSettingKeys; }

std::string ScriptError::to_string() const {
    std::string s = world::printable(file, world::kPathLimit);
    if (line > 0) s.append(1, ':').append(std::to_string(line));
    return s.append(": ").append(message);
}

bool parse_script(const std::string& text, const std::string& file, Script& out, ScriptError& error) {
    out = Script{};
    out.file = file;
    using world::quote;
    // A UTF-8 byte-order mark (an editor's) before the first line is not part of it.
    std::istringstream in(text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? text.substr(3) : text);
    std::string raw;
    long line = 0;
    auto fail = [&](const std::string& m) {
        error = {file, line, m};
        return false;
    };
    while (std::getline(in, raw)) {
        ++line;
        const std::string content = trim(raw.substr(0, raw.find('#')));
        std::istringstream words(content);
        std::string first;
        if (!(words >> first)) {  // blank or comment
            if (const std::size_t at = first_control(content); at != std::string::npos) return fail(control_between(content, at));
            continue;
        }
        if (is_setting(first)) {
            const std::string value = trim(content.substr(content.find(first) + first.size()));
            if (value.empty()) return fail("the setting '" + first + "' needs a value");
            // The value becomes an option's (and may be shown in its message, or written back
            // into a recording's line): text a terminal shows as it is, of a path's length.
            if (value.size() > kSettingLimit)
                return fail("the setting '" + first + "' is " + std::to_string(value.size()) + " bytes long, over the " +
                            std::to_string(kSettingLimit) + " a value may have: " + quote(value));
            if (!world::is_plain(value))
                return fail("the setting '" + first + "' has a control character or a byte that is not UTF-8: " +
                            quote(value));
            if (const std::size_t at = first_control(content); at != std::string::npos) return fail(control_between(content, at));
            out.settings.push_back({first, value, line});
            continue;
        }
        double time = 0;
        if (!read_time(first, time)) {
            std::string keys;
            for (const char* const* k = kSettingKeys; *k; ++k) keys += std::string(keys.empty() ? "" : ", ") + *k;
            return fail("expected a time in seconds (a number >= 0) or a setting (" + keys + ") first, found " +
                        quote(first));
        }
        std::string kind, what, extra;
        words >> kind >> what;
        ScriptEvent e;
        e.time = time;
        if (kind == "mark") {  // "T mark R THETA": a mark of the live instrument at (R, THETA degrees)
            e.kind = ScriptEvent::mark;
            std::string theta;
            words >> theta;
            char* stop = nullptr;
            e.r = std::strtod(what.c_str(), &stop);
            const bool r_ok = !what.empty() && *stop == '\0' && e.r >= 0 && e.r <= 1e4;
            e.theta_deg = std::strtod(theta.c_str(), &stop);
            if (!r_ok || theta.empty() || *stop != '\0' || !std::isfinite(e.theta_deg) || std::fabs(e.theta_deg) > 1e6)
                return fail("expected 'mark R THETA' (a distance from O, 0 to 10000, and an angle in degrees), found " +
                            quote(content));
            what = theta;
        } else if (kind == "attract") {
            if (what == "on") e.kind = ScriptEvent::attract_on;
            else if (what == "off") e.kind = ScriptEvent::attract_off;
            else return fail("expected on or off after 'attract', found " + quote(what));
        } else {
            if (kind == "press") e.kind = ScriptEvent::press;
            else if (kind == "release") e.kind = ScriptEvent::release;
            else if (kind == "tap") e.kind = ScriptEvent::tap;
            else return fail("expected press, release, tap, mark or attract after the time, found " + quote(kind));
            if (!world::parse_action(what, e.control) || e.control == world::Action::quit)
                return fail("expected a control (" + control_list() + "), found " + quote(what));
        }
        if (words >> extra) return fail("unexpected " + quote(extra) + " after " + quote(what));
        if (const std::size_t at = first_control(content); at != std::string::npos) return fail(control_between(content, at));
        out.events.push_back(e);
    }
    std::stable_sort(out.events.begin(), out.events.end(),
                     [](const ScriptEvent& a, const ScriptEvent& b) { return a.time < b.time; });
    return true;
}

bool load_script(const std::string& path, Script& out, ScriptError& error) {
    std::string text, why;
    if (!files::read_text_file(path, files::kActionsFileLimit, "an actions file", text, why)) {
        error = {path, 0, "the actions file: " + why + ": check the path"};
        return false;
    }
    return parse_script(text, path, out, error);
}

}  // namespace noneuclid::app
