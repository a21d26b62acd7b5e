#include "world/actions.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace noneuclid::world {

std::string ActionError::to_string() const {
    std::string s = file;
    if (line > 0) s.append(1, ':').append(std::to_string(line));
    return s.append(": ").append(message);
}

bool parse_actions(const std::string& text, const std::string& name, std::vector<ActionEvent>& out, ActionError& error) {
    out.clear();
    std::istringstream in(text);
    std::string raw;
    long line = 0;
    while (std::getline(in, raw)) {
        ++line;
        const std::string content = raw.substr(0, raw.find('#'));
        std::istringstream words(content);
        std::string t, kind, action, extra;
        if (!(words >> t)) continue;  // blank or comment
        words >> kind >> action;
        auto fail = [&](const std::string& m) {
            error = {name, line, m};
            return false;
        };
        char* end = nullptr;
        const double time = std::strtod(t.c_str(), &end);
        if (*end != '\0' || !std::isfinite(time) || time < 0)
            return fail("expected a time in seconds (a number >= 0) first, found '" + t + "'");
        ActionEvent e;
        e.time = time;
        if (kind == "press") e.kind = ActionEvent::press;
        else if (kind == "release") e.kind = ActionEvent::release;
        else if (kind == "tap") e.kind = ActionEvent::tap;
        else return fail("expected press, release or tap after the time, found '" + kind + "'");
        if (!parse_action(action, e.action))
            return fail("expected an action (thrust, left, right, curvature_up, curvature_down, preset, reset), found '" +
                        action + "'");
        if (words >> extra) return fail("unexpected '" + extra + "' after the action");
        out.push_back(e);
    }
    std::stable_sort(out.begin(), out.end(), [](const ActionEvent& a, const ActionEvent& b) { return a.time < b.time; });
    return true;
}

bool load_actions_file(const std::string& path, std::vector<ActionEvent>& out, ActionError& error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = {path, 0, "cannot read the actions file: check the path"};
        return false;
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parse_actions(text.str(), path, out, error);
}

}  // namespace noneuclid::world
