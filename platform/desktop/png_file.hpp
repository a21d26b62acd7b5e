// Writing a canvas to a PNG file with libpng (8-bit RGB, whatever the canvas's pixel format).
#pragma once

#include <string>

#include "render/canvas.hpp"

namespace noneuclid::platform {

// Writes `canvas` to `path`. On failure returns false and sets `error` to one sentence naming
// the file and what to do.
bool write_png(const std::string& path, const render::Canvas& canvas, std::string& error);

// Reads an 8-bit RGB or RGBA PNG into `rgb` (3 bytes a pixel, rows packed), for tests and the
// golden-image comparison. On failure returns false and sets `error`.
bool read_png(const std::string& path, int& width, int& height, std::string& rgb, std::string& error);

}  // namespace noneuclid::platform
