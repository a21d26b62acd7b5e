// Scripted actions: the same presses and releases the kiosk buttons send, from a text file.
//
//     # seconds  event    action
//     0.0        press    thrust
//     1.5        release  thrust
//     2.0        tap      preset        # press and release at once
//     3.0        press    curvature_down
//
// Events: press, release, tap. Actions: thrust, left, right, curvature_up, curvature_down,
// preset (next preset), reset. Times are seconds from the start, in any order (sorted, ties
// kept in file order). An event at time t applies before the first step that starts at or
// after t; '#' starts a comment.
#pragma once

#include <string>
#include <vector>

#include "world/world.hpp"

namespace noneuclid::world {

struct ActionEvent {
    double time = 0;
    enum Kind { press, release, tap } kind = press;
    Action action = Action::thrust;
};

struct ActionError {
    std::string file;
    long line = 0;
    std::string message;
    std::string to_string() const;
};

bool parse_actions(const std::string& text, const std::string& name, std::vector<ActionEvent>& out, ActionError& error);
bool load_actions_file(const std::string& path, std::vector<ActionEvent>& out, ActionError& error);

// Applies, in order, the events due by `time` (from index `next` on); returns the new index.
template <class W>
std::size_t apply_actions(W& world, const std::vector<ActionEvent>& events, std::size_t next, double time) {
    while (next < events.size() && events[next].time <= time + 1e-9) {
        const ActionEvent& e = events[next++];
        if (e.kind != ActionEvent::release) world.press(e.action);
        if (e.kind != ActionEvent::press) world.release(e.action);
    }
    return next;
}

}  // namespace noneuclid::world
