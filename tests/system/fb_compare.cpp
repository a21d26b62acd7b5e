// fb_compare: a framebuffer read back from the system test's VM against a PNG from
// `noneuclid render` (tests/system/run).
//
//   fb_compare DUMP.raw DUMP.info REFERENCE.png [--tolerance PIXELS] [--diff OUT.png] [--count RRGGBB]
//
// DUMP.raw holds the framebuffer's visible rows, line_length bytes apart (guest-lib.sh's
// fb_dump); DUMP.info is the guest's `probe fb` line: xres, yres, xoffset, bpp, line_length and
// the red/green/blue offset/length the kernel reports. Each pixel is unpacked with the device's
// own layout (render::PixelFormat: each channel's top bits replicated into the low ones, as
// write_png unpacks a canvas) and compared exactly with the reference's 8-bit RGB. So a picture
// drawn into a BGR565 framebuffer compares equal to the same picture rendered as RGB565.
//
// Prints how many pixels differ and the largest channel difference. Exit 0 when at most
// PIXELS pixels differ (default 0), 1 when more do, 2 on bad input. --diff writes the pixels
// that differ in white over a dimmed reference. --count prints how many of the framebuffer's
// pixels are exactly that colour (as the device's format stores it): the game's bullets, say.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/platform.hpp"  // read_png
#include "render/canvas.hpp"

namespace {

namespace r = noneuclid::render;

[[noreturn]] void fail(const std::string& sentence) {
    std::fprintf(stderr, "fb_compare: %s\n", sentence.c_str());
    std::exit(2);
}

// "key=value key=value ..." -> map.
std::map<std::string, std::string> parse_info(const std::string& path) {
    std::ifstream in(path);
    if (!in) fail("cannot read " + path + ".");
    std::map<std::string, std::string> m;
    std::string word;
    while (in >> word) {
        const auto eq = word.find('=');
        if (eq != std::string::npos) m[word.substr(0, eq)] = word.substr(eq + 1);
    }
    return m;
}

long number(const std::map<std::string, std::string>& m, const std::string& key) {
    const auto it = m.find(key);
    if (it == m.end()) fail("the framebuffer description has no " + key + ".");
    char* end = nullptr;
    const long v = std::strtol(it->second.c_str(), &end, 10);
    if (end == it->second.c_str() || *end != '\0' || v < 0) fail("bad " + key + " '" + it->second + "'.");
    return v;
}

r::Channel channel(const std::map<std::string, std::string>& m, const std::string& key) {
    const auto it = m.find(key);
    if (it == m.end()) fail("the framebuffer description has no " + key + ".");
    unsigned offset = 0, length = 0;
    if (std::sscanf(it->second.c_str(), "%u/%u", &offset, &length) != 2 || offset > 31 || length > 8)
        fail("bad " + key + " '" + it->second + "' (offset/length).");
    return {static_cast<uint8_t>(offset), static_cast<uint8_t>(length)};
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> files;
    long tolerance = 0;
    std::string diff_path, count;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--tolerance" && i + 1 < argc) tolerance = std::strtol(argv[++i], nullptr, 10);
        else if (a == "--diff" && i + 1 < argc) diff_path = argv[++i];
        else if (a == "--count" && i + 1 < argc) count = argv[++i];
        else files.push_back(a);
    }
    if (files.size() != 3) fail("usage: fb_compare DUMP.raw DUMP.info REFERENCE.png [--tolerance PIXELS] [--diff OUT.png]");

    const auto info = parse_info(files[1]);
    r::PixelFormat format;
    format.bits_per_pixel = static_cast<uint8_t>(number(info, "bpp"));
    format.red = channel(info, "red");
    format.green = channel(info, "green");
    format.blue = channel(info, "blue");
    if (!format.supported()) fail("the framebuffer's format (" + info.at("bpp") + " bpp) is not one a canvas reads.");
    const long width = number(info, "xres"), height = number(info, "yres");
    const long stride = number(info, "line_length"), xoffset = number(info, "xoffset");
    if (stride < (xoffset + width) * format.bytes_per_pixel()) fail("line_length is shorter than a row.");

    std::ifstream raw_in(files[0], std::ios::binary);
    if (!raw_in) fail("cannot read " + files[0] + ".");
    std::vector<char> raw((std::istreambuf_iterator<char>(raw_in)), std::istreambuf_iterator<char>());
    if (static_cast<long>(raw.size()) < stride * height)
        fail(files[0] + " has " + std::to_string(raw.size()) + " bytes, fewer than " + std::to_string(height) +
             " rows of " + std::to_string(stride) + ".");
    const r::Canvas fb(raw.data() + xoffset * format.bytes_per_pixel(), static_cast<int>(width),
                       static_cast<int>(height), stride, format);

    int ref_w = 0, ref_h = 0;
    std::string rgb, error;
    if (!noneuclid::platform::read_png(files[2], ref_w, ref_h, rgb, error)) fail(error + ".");
    if (ref_w != width || ref_h != height)
        fail("the reference is " + std::to_string(ref_w) + "x" + std::to_string(ref_h) + ", the framebuffer " +
             std::to_string(width) + "x" + std::to_string(height) + ".");

    long differing = 0;
    int worst = 0;
    std::vector<uint8_t> diff(rgb.size());
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
            const r::Rgb got = fb.get(x, y);
            const int want[3] = {static_cast<uint8_t>(rgb[i]), static_cast<uint8_t>(rgb[i + 1]), static_cast<uint8_t>(rgb[i + 2])};
            const int have[3] = {got.r, got.g, got.b};
            int d = 0;
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(have[c] - want[c]));
            if (d > 0) ++differing;
            worst = std::max(worst, d);
            for (int c = 0; c < 3; ++c) diff[i + c] = d > 0 ? 255 : static_cast<uint8_t>(want[c] / 3);
        }
    }
    std::printf("%s: %ld of %ld pixels differ from %s (largest channel difference %d; tolerance %ld pixels)\n",
                files[0].c_str(), differing, width * height, files[2].c_str(), worst, tolerance);
    if (!count.empty()) {
        const unsigned long c = std::strtoul(count.c_str(), nullptr, 16);
        const uint32_t word = format.pack({static_cast<uint8_t>(c >> 16), static_cast<uint8_t>(c >> 8), static_cast<uint8_t>(c)});
        long n = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) n += fb.get_word(x, y) == word;
        std::printf("%s: %ld pixels of #%s\n", files[0].c_str(), n, count.c_str());
    }
    if (!diff_path.empty()) {
        // rgb888's word is 0xRRGGBB little-endian, so its bytes in memory are B, G, R.
        std::vector<uint8_t> bgr(diff.size());
        for (std::size_t i = 0; i + 2 < diff.size(); i += 3) bgr[i] = diff[i + 2], bgr[i + 1] = diff[i + 1], bgr[i + 2] = diff[i];
        const r::Canvas out(bgr.data(), static_cast<int>(width), static_cast<int>(height), width * 3, r::PixelFormat::rgb888());
        if (!noneuclid::platform::write_png(diff_path, out, error)) fail(error + ".");
    }
    return differing <= tolerance ? 0 : 1;
}
