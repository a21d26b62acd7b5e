// Which display `noneuclid run` uses when not told: an X11 window when $DISPLAY is set, the
// framebuffer when /dev/fb0 exists and stdin is a terminal (a console), PNG files otherwise.
#pragma once

#include <string>

namespace noneuclid::platform {

enum class DisplayKind { x11, fbdev, png };

struct DisplayChoice {
    DisplayKind display = DisplayKind::png;
    std::string reason;  // "because ..." for the one line the program prints
};

DisplayChoice choose_display();

}  // namespace noneuclid::platform
