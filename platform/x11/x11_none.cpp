// open_window (app/platform.hpp) in a build without Xlib: it says so.
#include "app/platform.hpp"

namespace noneuclid::platform {

std::unique_ptr<app::Display> open_window(const WindowSpec&, std::string& error) {
    error = "this build has no X11 window (Xlib was not found when it was built): install libx11-dev and "
            "libxext-dev and rebuild, or use --display png.";
    return nullptr;
}

}  // namespace noneuclid::platform
