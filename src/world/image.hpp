// An image a body is textured with (SceneBody::texture): 8-bit RGB texels, read from a PNG file
// by the platform when a scene file is loaded (app/setup.cpp), or generated here for the
// built-in names ("builtin:checker", "builtin:rock"), which need no file and no PNG library.
// Images are immutable once made and shared between the scene's bodies (std::shared_ptr).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace noneuclid::world {

struct Image {
    int width = 0, height = 0;
    std::vector<uint32_t> texels;  // 0x00RRGGBB, row 0 at the top, rows packed
    std::string source;            // the file it was read from, or the built-in name
    uint32_t at(int x, int y) const {
        return texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
    }
};

// The largest image a texture may be, in texels each way: the PNG header is checked before the
// image is decoded, and a larger one is refused (docs/file-formats.md). 1024 x 1024 texels take
// 4 MiB; a body 60 px across shows about 60 of them.
inline constexpr int kImageMaxSide = 1024;
// The largest PNG file read for a texture.
inline constexpr std::size_t kImageFileLimit = std::size_t{4} << 20;

// The prefix of a built-in image's name.
inline constexpr const char* kBuiltinImagePrefix = "builtin:";
// The built-in images' names (with the prefix), null-terminated.
const char* const* builtin_image_names();
// The built-in image `name` ("builtin:checker": 64 x 64 squares in a colour gradient with an
// arrow along +x, the body's facing; "builtin:rock": 64 x 64 grey-brown noise with craters,
// seamless when repeated). False if there is none by that name.
bool builtin_image(const std::string& name, Image& out);

}  // namespace noneuclid::world
