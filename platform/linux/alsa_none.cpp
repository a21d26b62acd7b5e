// open_sound (app/platform.hpp) in a build without libasound (the static kiosk binary, a cross
// build, the web page, which has its own): it says so, and the run goes on silent.
#include "app/platform.hpp"

namespace noneuclid::platform {

std::unique_ptr<app::SoundOut> open_sound(const SoundSpec&, std::string& error) {
    error = "this build has no sound (libasound was not found when it was built): install libasound2-dev and "
            "rebuild; the run goes on silent.";
    return nullptr;
}

}  // namespace noneuclid::platform
