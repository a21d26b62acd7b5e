// open_gif and read_gif (app/platform.hpp) in a build without giflib: they say so.
#include "app/platform.hpp"

namespace noneuclid::platform {

namespace {
const char* const kNoGif =
    "this build has no GIF support (giflib was not found when it was built): install libgif-dev and rebuild";
}

std::unique_ptr<GifWriter> open_gif(const std::string& path, int, int, std::string& error) {
    error = std::string("cannot write ") + path + ": " + kNoGif + ".";
    return nullptr;
}

bool read_gif(const std::string& path, int&, int&, std::vector<GifFrame>&, std::string& error) {
    error = std::string("cannot read ") + path + ": " + kNoGif + ".";
    return false;
}

}  // namespace noneuclid::platform
