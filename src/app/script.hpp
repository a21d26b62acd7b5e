// Actions files and recordings: what the buttons and keys did, when, and the settings to replay
// it with. One text format for both: `run --record FILE` writes it, and `render --actions FILE`
// (or `run --actions FILE`, `dump --actions FILE`) plays it back, the same frames bit for bit.
//
//     # comment                     '#' starts a comment anywhere
//     scene kiosk                   a setting: the command-line option of the same name
//     hud off                       (on/off for the flags); the command line wins over it
//     0.0     press    thrust       TIME EVENT CONTROL: seconds of world time from the start
//     1.5     release  thrust
//     2.0     tap      preset       press and release at once
//     3.25    tap      projection
//     12.5    attract  on           recordings: the attract mode began (or ended: off); the
//                                   HUD's legend says so
//
// Controls: the world's actions (thrust, left, right, curvature_up, curvature_down, preset,
// reset, hyperbolic, flat, spherical, fire) and the view's (projection: the next one; hud:
// on/off). Settings: scene, curvature, engine, projection, size, format, aa, hud, font, legend,
// frames, best (see `noneuclid --help`). Events may come in any order: they are sorted by
// time, ties kept in file order. An event at time t applies before the first step that starts
// at or after t.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "kinds/step.hpp"
#include "world/action.hpp"

namespace noneuclid::app {

struct ScriptEvent {
    enum Kind : uint8_t { press, release, tap, attract_on, attract_off, mark };
    double time = 0;
    Kind kind = press;
    world::Action control = world::Action::thrust;  // press, release, tap
    double r = 0, theta_deg = 0;                       // mark: where the live instrument's mark goes
};

struct Setting {
    std::string key, value;
    long line = 0;
};

struct Script {
    std::string file;
    std::vector<ScriptEvent> events;  // sorted by time, ties in file order
    std::vector<Setting> settings;    // in file order (a later one wins)
};

struct ScriptError {
    std::string file;
    long line = 0;  // 0: the file as a whole
    std::string message;
    std::string to_string() const;  // "file:line: message"
};

// The setting keys a script may hold, null-terminated.
const char* const* setting_keys();

bool parse_script(const std::string& text, const std::string& file, Script& out, ScriptError& error);
bool load_script(const std::string& path, Script& out, ScriptError& error);

// The events due by a time, in order, from a script's list (which must outlive it and not change):
// kinds/step.hpp's DueEvents, the firmware's player too.
class ScriptPlayer : public kinds::DueEvents<ScriptEvent> {
public:
    ScriptPlayer() = default;
    explicit ScriptPlayer(const std::vector<ScriptEvent>& events) : DueEvents(events.data(), events.size()) {}
};

}  // namespace noneuclid::app
