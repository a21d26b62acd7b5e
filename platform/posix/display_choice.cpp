// Which display `noneuclid run` uses when not told (app/platform.hpp).
#include <unistd.h>

#include <cstdlib>

#include "app/platform.hpp"

namespace noneuclid::platform {

DisplayChoice choose_display() {
    const char* display = std::getenv("DISPLAY");
    if (display && *display) return {DisplayKind::x11, std::string("DISPLAY is set (") + display + ")"};
    if (access("/dev/fb0", F_OK) == 0 && isatty(STDIN_FILENO))
        return {DisplayKind::fbdev, "DISPLAY is not set, /dev/fb0 exists and stdin is a terminal"};
    return {DisplayKind::png, "DISPLAY is not set and this is not a framebuffer console"};
}

}  // namespace noneuclid::platform
