// Writes a recording (app/script.hpp's format) as a run goes: the settings to replay it with
// first, then every control as it takes effect, with the world time it took effect at. The
// session calls it; nothing here reads a clock. Write errors show when the file is finished
// (platform::AtomicFile::commit).
#pragma once

#include <cstdio>
#include <string>

#include "app/script.hpp"

namespace noneuclid::app {

class Recorder {
public:
    // Writes to `f` (not owned; null: records nothing).
    explicit Recorder(std::FILE* f) : f_(f) {}
    void comment(const std::string& text);
    void setting(const char* key, const std::string& value);
    void event(double time, ScriptEvent::Kind kind, world::Action control = world::Action::thrust);
    void mark(double time, double r, double theta_deg);

private:
    std::FILE* f_;
};

}  // namespace noneuclid::app
