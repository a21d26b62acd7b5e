// The built-in images (world/image.hpp), generated: the same texels on every machine (integer
// arithmetic and a fixed hash, no floating point).
#include <cstdint>
#include <string>

#include "world/image.hpp"

namespace noneuclid::world {
namespace {

constexpr int kSide = 64;

uint32_t rgb(int r, int g, int b) {
    auto c = [](int v) { return static_cast<uint32_t>(v < 0 ? 0 : v > 255 ? 255 : v); };
    return c(r) << 16 | c(g) << 8 | c(b);
}

// Squares of 8 texels, the light ones running from orange (left) to blue (right) and darker
// toward the bottom, the dark ones grey; a white arrow along +x (the body's facing) through the
// middle, so that a turn or a mirror image shows.
void checker(Image& im) {
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const bool light = ((x >> 3) + (y >> 3)) % 2 == 0;
            const int shade = 255 - y * 2;
            uint32_t c = light ? rgb((255 - x * 3) * shade / 255, (140 + x) * shade / 255, (40 + x * 3) * shade / 255)
                               : rgb(50 + y / 2, 55 + y / 2, 70 + y / 2);
            const int dy = y < 32 ? 31 - y : y - 32;  // 0 on the two middle rows
            const bool shaft = x >= 14 && x < 42 && dy < 3;
            const bool head = x >= 42 && x < 54 && dy < 54 - x;
            if (shaft || head) c = rgb(255, 255, 255);
            im.texels[static_cast<std::size_t>(y * kSide + x)] = c;
        }
}

// A hash of a lattice point, 0..255, repeating every `period` (so the noise tiles).
int lattice(int x, int y, int period, uint32_t seed) {
    uint32_t h = static_cast<uint32_t>((x % period + period) % period) * 374761393u +
                 static_cast<uint32_t>((y % period + period) % period) * 668265263u + seed * 2246822519u;
    h = (h ^ (h >> 13)) * 1274126177u;
    return static_cast<int>((h ^ (h >> 16)) & 255);
}
// Value noise at texel (x, y) on a lattice of `cell` texels, bilinear, 0..255.
int noise(int x, int y, int cell, uint32_t seed) {
    const int period = kSide / cell;
    const int gx = x / cell, gy = y / cell, fx = x % cell, fy = y % cell;
    const int a = lattice(gx, gy, period, seed), b = lattice(gx + 1, gy, period, seed);
    const int c = lattice(gx, gy + 1, period, seed), d = lattice(gx + 1, gy + 1, period, seed);
    const int top = a * (cell - fx) + b * fx, bottom = c * (cell - fx) + d * fx;
    return (top * (cell - fy) + bottom * fy) / (cell * cell);
}

// Grey-brown rock: three octaves of value noise, and four craters (a dark floor, a light rim),
// every distance taken round the edges so that the image repeats without a seam.
void rock(Image& im) {
    const int craters[4][3] = {{18, 20, 9}, {46, 14, 6}, {40, 44, 11}, {10, 50, 5}};  // x, y, radius
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            int v = (noise(x, y, 16, 1) * 4 + noise(x, y, 8, 2) * 2 + noise(x, y, 4, 3)) / 7;
            for (const auto& k : craters) {
                auto wrap = [](int d) { return d > kSide / 2 ? d - kSide : d < -kSide / 2 ? d + kSide : d; };
                const int dx = wrap(x - k[0]), dy = wrap(y - k[1]), d2 = dx * dx + dy * dy, r2 = k[2] * k[2];
                if (d2 < r2 * 64 / 100) v = v * 3 / 5;
                else if (d2 < r2) v = v + 40;
            }
            im.texels[static_cast<std::size_t>(y * kSide + x)] = rgb(60 + v * 3 / 4, 52 + v * 2 / 3, 44 + v / 2);
        }
}

}  // namespace

const char* const* builtin_image_names() {
    static const char* const names[] = {"builtin:checker", "builtin:rock", nullptr};
    return names;
}

bool builtin_image(const std::string& name, Image& out) {
    const bool is_checker = name == "builtin:checker", is_rock = name == "builtin:rock";
    if (!is_checker && !is_rock) return false;
    out.width = out.height = kSide;
    out.texels.assign(static_cast<std::size_t>(kSide * kSide), 0);
    out.source = name;
    if (is_checker) checker(out);
    else rock(out);
    return true;
}

}  // namespace noneuclid::world
