// The kiosk's functions (app/platform.hpp) in a build for a system without the Linux
// framebuffer, GPIO and evdev: they say so.
#include <cstdio>

#include "app/platform.hpp"

namespace noneuclid::platform {

namespace {
const char* const kNoKiosk = "this build has no kiosk (it was not built for Linux): use --display x11 or png";
}

std::unique_ptr<app::Display> open_kiosk(const KioskSpec&, std::string& error) {
    error = std::string(kNoKiosk) + ".";
    return nullptr;
}

bool find_board(const std::string&, files::Board&, std::string&, std::string& error) {
    error = kNoKiosk;
    return false;
}

int print_buttons(const files::Board&, const std::string&, long, double) {
    std::fprintf(stderr, "noneuclid: %s.\n", kNoKiosk);
    return 2;
}

}  // namespace noneuclid::platform
