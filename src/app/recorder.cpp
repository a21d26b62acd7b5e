#include "app/recorder.hpp"

namespace noneuclid::app {

void Recorder::comment(const std::string& text) {
    if (f_) std::fprintf(f_, "# %s\n", text.c_str());
}

void Recorder::setting(const char* key, const std::string& value) {
    if (f_) std::fprintf(f_, "%s %s\n", key, value.c_str());
}

void Recorder::event(double time, ScriptEvent::Kind kind, world::Action control) {
    if (!f_) return;
    switch (kind) {
        case ScriptEvent::attract_on: std::fprintf(f_, "%.9f attract on\n", time); return;
        case ScriptEvent::attract_off: std::fprintf(f_, "%.9f attract off\n", time); return;
        case ScriptEvent::press: std::fprintf(f_, "%.9f press %s\n", time, world::action_name(control)); return;
        case ScriptEvent::release: std::fprintf(f_, "%.9f release %s\n", time, world::action_name(control)); return;
        case ScriptEvent::tap: std::fprintf(f_, "%.9f tap %s\n", time, world::action_name(control)); return;
        case ScriptEvent::mark: return;  // (mark() writes those)
    }
}

void Recorder::mark(double time, double r, double theta_deg) {
    if (f_) std::fprintf(f_, "%.9f mark %.17g %.17g\n", time, r, theta_deg);
}

}  // namespace noneuclid::app
