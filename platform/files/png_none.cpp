// write_png, read_png and read_texture (app/platform.hpp) in a build without libpng: they say so.
// The web page is such a build (it shows its pictures on the page and reads no files but the
// scene and actions it is handed), and says what it can do instead.
#include "app/platform.hpp"

namespace noneuclid::platform {

namespace {
#ifdef __EMSCRIPTEN__
const char* const kNoPng = "the web page reads no image files (run noneuclid on a computer to use one)";
#else
const char* const kNoPng =
    "this build has no PNG support (libpng was not found when it was built): install libpng-dev and rebuild";
#endif
}  // namespace

bool write_png(const std::string& path, const render::Canvas&, std::string& error) {
    error = std::string("cannot write ") + path + ": " + kNoPng + ".";
    return false;
}

bool read_png(const std::string& path, int&, int&, std::string&, std::string& error) {
    error = std::string("cannot read ") + path + ": " + kNoPng + ".";
    return false;
}

std::string file_identity(const std::string&) {
    return "";  // no image file is read, so none is shared
}

bool read_texture(const std::string& path, world::Image&, std::string& why) {
    why = path + ": " + kNoPng + ", or name a built-in image (builtin:checker, builtin:rock)";
    return false;
}

}  // namespace noneuclid::platform
