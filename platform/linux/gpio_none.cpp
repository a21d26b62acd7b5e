// The GPIO backend of a build without libgpiod (a cross build without the target's
// libgpiod-dev): open_gpio says so in one sentence; evdev input still works.
#include "linux/input.hpp"

namespace noneuclid::platform {

std::unique_ptr<InputSource> open_gpio(const GpioConfig&, std::string& error) {
    error = "this build has no GPIO support: install libgpiod-dev and rebuild";
    return nullptr;
}

const char* gpiod_version() { return "none"; }

}  // namespace noneuclid::platform
