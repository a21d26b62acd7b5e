// hud_font (app/platform.hpp) in a build without zlib, which reads console fonts: the built-in
// font, and one sentence for a font file asked for.
#include "app/platform.hpp"

namespace noneuclid::platform {

bool hud_font(const std::string& choice, LoadedFont& out, std::string& error) {
    if (!choice.empty() && choice != "builtin") {
        error = "cannot read the font " + choice +
                ": this build reads no console fonts (zlib was not found when it was built): use --font builtin, or "
                "install zlib1g-dev and rebuild.";
        return false;
    }
    out = LoadedFont{};
    out.font = render::builtin_font();
    out.source = "built-in 6x8";
    return true;
}

}  // namespace noneuclid::platform
