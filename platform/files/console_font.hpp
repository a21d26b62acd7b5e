// Console fonts from files: PSF1/PSF2, plain or gzip-compressed (.psf, .psf.gz, .psfu.gz), as
// Debian ships them in /usr/share/consolefonts (package console-setup-linux), and the choice of
// the HUD's font (platform::hud_font, declared in app/platform.hpp, is defined here).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/platform.hpp"
#include "render/font.hpp"

namespace noneuclid::platform {

// Reads a PSF font, gzip-compressed or not, from `path`. On failure returns false, leaves `out`
// unchanged and sets `error` to one sentence naming the path.
bool load_console_font(const std::string& path, LoadedFont& out, std::string& error);

// The HUD's font, the first that loads of: $NONEUCLID_FONT if set; in `console_fonts_dir`,
// Lat15-Terminus16, Uni2-Terminus16, Lat15-Fixed16, Uni2-Fixed16 (.psf.gz); any other *.psf.gz
// or *.psfu.gz there (in name order); else the built-in 6x8 font. Never fails. If `note` is
// given it receives one sentence saying which font was chosen and why.
LoadedFont default_hud_font(std::string* note,
                            const std::string& console_fonts_dir = "/usr/share/consolefonts");

}  // namespace noneuclid::platform
