// The palettes' names (docs/accessibility.md): which palettes there are and what each is called,
// for whatever chooses one (a board file's `palette`, --palette, the C interface). Here, below
// the file formats, so that a board file checks its palette without the renderer; the colours
// each palette gives are the renderer's (render/palette.hpp, which names these as its own).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace noneuclid::world {

enum class Palette : uint8_t { scene, colour_blind, high_contrast, print };
inline constexpr Palette kPalettes[] = {Palette::scene, Palette::colour_blind, Palette::high_contrast, Palette::print};

struct PaletteRow {
    Palette p;
    const char* name;
    const char* help;
};
inline constexpr PaletteRow kPaletteRows[] = {
    {Palette::scene, "scene", "every body in its own colour (the default)"},
    {Palette::colour_blind, "colour-blind", "Okabe-Ito colours by role, apart under every colour-vision deficiency"},
    {Palette::high_contrast, "high-contrast", "bright lines and text on black, 7:1 contrast or more"},
    {Palette::print, "print", "dark lines on white paper, each in its own hue (the worksheets' default)"},
};
inline const char* palette_name(Palette p) { return kPaletteRows[static_cast<int>(p)].name; }
inline const char* palette_help(Palette p) { return kPaletteRows[static_cast<int>(p)].help; }
inline bool parse_palette(const std::string& name, Palette& out) {
    for (const PaletteRow& r : kPaletteRows)
        if (name == r.name) {
            out = r.p;
            return true;
        }
    return false;
}
inline std::vector<std::string> palette_names() {
    std::vector<std::string> out;
    for (const PaletteRow& r : kPaletteRows) out.push_back(r.name);
    return out;
}

}  // namespace noneuclid::world
