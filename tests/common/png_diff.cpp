// png_diff A.png B.png [--exact]: prints how many pixels differ by more than 8 levels in any
// channel (with --exact: by anything); exit 0 if that is at most 0.5% of the pixels (--exact:
// none) and the sizes match, 1 otherwise, 2 on a bad file. Used by x11_test.sh to compare the
// window (read back from the X server) with render. A file whose name ends in .ppm is read as a
// binary PPM (P6, maxval 255), what the library's examples write (tests/library).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "app/platform.hpp"

namespace {
// A binary PPM's pixels as RGB bytes (P6, maxval 255, no comments: as the examples write it).
bool read_ppm(const std::string& path, int& width, int& height, std::string& rgb, std::string& error) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int maxval = 0;
    if (!(in >> magic >> width >> height >> maxval) || magic != "P6" || maxval != 255 || width < 1 || height < 1 ||
        in.get() == EOF) {
        error = path + ": not a binary PPM of 8-bit channels (P6, maxval 255)";
        return false;
    }
    rgb.assign(std::istreambuf_iterator<char>(in), {});
    if (rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {
        error = path + ": its pixels are cut short or followed by more bytes";
        return false;
    }
    return true;
}
bool read_picture(const std::string& path, int& width, int& height, std::string& rgb, std::string& error) {
    if (path.size() > 4 && path.compare(path.size() - 4, 4, ".ppm") == 0) return read_ppm(path, width, height, rgb, error);
    return noneuclid::platform::read_png(path, width, height, rgb, error);
}
}  // namespace

int main(int argc, char** argv) {
    const bool exact = argc == 4 && std::strcmp(argv[3], "--exact") == 0;
    if (argc != 3 && !exact) {
        std::fprintf(stderr, "usage: png_diff A.png B.png [--exact]\n");
        return 2;
    }
    int wa = 0, ha = 0, wb = 0, hb = 0;
    std::string a, b, error;
    if (!read_picture(argv[1], wa, ha, a, error) || !read_picture(argv[2], wb, hb, b, error)) {
        std::fprintf(stderr, "png_diff: %s\n", error.c_str());
        return 2;
    }
    if (wa != wb || ha != hb) {
        std::printf("sizes differ: %dx%d against %dx%d\n", wa, ha, wb, hb);
        return 1;
    }
    const int tolerance = exact ? 0 : 8;
    long differ = 0;
    const long pixels = static_cast<long>(wa) * ha;
    for (long i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c)
            if (std::abs(static_cast<unsigned char>(a[static_cast<std::size_t>(i * 3 + c)]) -
                         static_cast<unsigned char>(b[static_cast<std::size_t>(i * 3 + c)])) > tolerance) {
                ++differ;
                break;
            }
    const bool ok = exact ? differ == 0 : differ * 200 <= pixels;  // at most 0.5%
    std::printf("%ld of %ld pixels differ by more than %d levels (%.3f%%, limit %s): %s\n", differ, pixels, tolerance,
                100.0 * static_cast<double>(differ) / static_cast<double>(pixels), exact ? "none" : "0.5%",
                ok ? "same" : "DIFFERENT");
    return ok ? 0 : 1;
}
