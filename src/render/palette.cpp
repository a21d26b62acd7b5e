// The palettes' colours (render/palette.hpp).
#include "render/palette.hpp"

#include <cmath>

namespace noneuclid::render {

namespace {

// sRGB <-> linear, for keeping a grid line's brightness (relative luminance).
double linear(uint8_t c) {
    const double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
uint8_t encoded(double v) {
    v = v <= 0 ? 0 : (v >= 1 ? 1 : v);
    const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
    return static_cast<uint8_t>(std::lround(s * 255));
}
double luminance(Rgb c) { return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b); }

// `hue` scaled (in linear light) to the luminance y, at most hue itself.
Rgb at_luminance(Rgb hue, double y) {
    const double k = std::fmin(1.0, y / luminance(hue));
    return {encoded(linear(hue.r) * k), encoded(linear(hue.g) * k), encoded(linear(hue.b) * k)};
}

constexpr Rgb kPurple{204, 121, 167};  // Okabe-Ito's reddish purple
// High contrast: a line's least relative luminance, 7:1 against black ((0.3 + 0.05) / 0.05) with
// room for the rounding to 8 bits.
constexpr double kLeast = 0.305;
// Print: a line's most relative luminance, 4.5:1 against white paper ((1 + 0.05) / (0.18 +
// 0.05)); a grid line's, lighter than the lines it carries but still 3:1 ((1.05) / (0.29 + 0.05),
// with room for the rounding to 8 bits).
constexpr double kPrintLine = 0.18, kPrintGrid = 0.29;
// `own` in its own hue at luminance y or darker; a grey with no hue to keep (black, white) grey.
Rgb darkened(Rgb own, double y) {
    if (luminance(own) <= y) return own;
    if (own.r == own.g && own.g == own.b) return at_luminance({255, 255, 255}, y);
    return at_luminance(own, y);
}

}  // namespace

Rgb palette_line(Palette p, LineRole role, Rgb own) {
    switch (p) {
        case Palette::scene: return own;
        case Palette::colour_blind:
            switch (role) {
                case LineRole::ship: return {230, 159, 0};          // orange
                case LineRole::asteroid: return {86, 180, 233};     // sky blue
                case LineRole::bullet: return {240, 228, 66};       // yellow
                case LineRole::body: return {0, 114, 178};          // blue
                case LineRole::instrument: return {213, 94, 0};     // vermillion
                case LineRole::grid: return at_luminance(kPurple, luminance(own));
            }
            break;
        case Palette::high_contrast:
            switch (role) {
                case LineRole::ship: return {255, 255, 255};
                case LineRole::asteroid: return {255, 255, 0};
                case LineRole::bullet: return {0, 255, 255};
                case LineRole::body: return {255, 128, 255};
                case LineRole::instrument: return {0, 255, 0};
                case LineRole::grid: {  // its own hue, raised to kLeast's luminance at least (7:1 on black)
                    const double y = luminance(own);
                    if (y >= kLeast) return own;
                    if (y <= 0) return {151, 151, 151};
                    const double k = kLeast / y;
                    double r = std::fmin(1.0, linear(own.r) * k), g = std::fmin(1.0, linear(own.g) * k),
                           b = std::fmin(1.0, linear(own.b) * k);
                    // A channel that saturated lost luminance: toward white for the rest (luminance
                    // is linear in the channels, so this t gives kLeast again).
                    const double left = 0.2126 * r + 0.7152 * g + 0.0722 * b;
                    const double t = left < kLeast ? (kLeast - left) / (1 - left) : 0;
                    r += t * (1 - r), g += t * (1 - g), b += t * (1 - b);
                    return {encoded(r + 1e-9), encoded(g + 1e-9), encoded(b + 1e-9)};
                }
            }
            break;
        case Palette::print: return darkened(own, role == LineRole::grid ? kPrintGrid : kPrintLine);
    }
    return own;
}

PaletteFrame palette_frame(Palette p) {
    PaletteFrame f;
    if (p == Palette::colour_blind) f.rim = {255, 255, 255};
    if (p == Palette::high_contrast) {
        f.background = {0, 0, 0}, f.outside = {28, 28, 28}, f.rim = {255, 255, 255};
        f.text = {255, 255, 255}, f.dim = {200, 200, 200};
    }
    if (p == Palette::print) {  // white paper, the rest dark (a page uses little toner)
        f.background = {255, 255, 255}, f.outside = {245, 245, 245}, f.rim = {60, 60, 60};
        f.text = {20, 20, 20}, f.dim = {90, 90, 90};
    }
    return f;
}

}  // namespace noneuclid::render
