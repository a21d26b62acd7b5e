// write_pdf (app/platform.hpp) in a build without zlib (the web page, the static kiosk binary, a
// cross build without the target's zlib): it says so.
#include "app/platform.hpp"

namespace noneuclid::platform {

bool write_pdf(const std::string& path, const std::vector<render::Canvas>&, double, double, std::string& error) {
    error = "cannot write " + path +
            ": this build has no PDF support (zlib was not found when it was built): install zlib1g-dev and "
            "rebuild, or write the worksheet as a .png.";
    return false;
}

}  // namespace noneuclid::platform
