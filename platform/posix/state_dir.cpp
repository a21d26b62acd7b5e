// Where the program keeps files between runs (app/platform.hpp): the service's state directory,
// else the XDG one.
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "app/platform.hpp"

namespace noneuclid::platform {

std::string state_file(const std::string& name, std::string& error) {
    namespace fs = std::filesystem;
    fs::path dir;
    if (const char* s = std::getenv("STATE_DIRECTORY"); s && *s) {
        const std::string all = s;  // systemd gives a colon-separated list: the first is ours
        dir = all.substr(0, all.find(':'));
    } else if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x == '/') {
        dir = fs::path(x) / "noneuclid";
    } else if (const char* h = std::getenv("HOME"); h && *h == '/') {
        dir = fs::path(h) / ".local" / "state" / "noneuclid";
    } else {
        error = "no state directory: neither STATE_DIRECTORY, XDG_STATE_HOME nor HOME is set (give --scores FILE)";
        return {};
    }
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        error = "cannot make the state directory " + dir.string() + " (" + ec.message() + "; give --scores FILE)";
        return {};
    }
    return (dir / name).string();
}

}  // namespace noneuclid::platform
