// The palettes (render/palette.hpp) against their claims, with independent references: the
// colour-blind palette's line colours at least 15 apart in CIELAB (CIE76) under normal vision
// and under protanopia, deuteranopia and tritanopia simulated by Machado, Oliveira and
// Fernandes' matrices (2009, severity 1, applied in linear RGB); the high-contrast palette's
// lines and text at 7:1 or more against its background by WCAG 2's contrast ratio; and drawn
// frames whose every pixel is one of the palette's colours. The large HUD's text twice the
// height, and the controls' legend wrapped inside a narrow canvas.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "render/draw_world.hpp"
#include "render/font.hpp"
#include "render/hud.hpp"
#include "render/layout.hpp"
#include "render/palette.hpp"
#include "world/world.hpp"

namespace {
namespace palette_test {  // (a unity batch shares this file's scope with others)

using namespace noneuclid;
using render::LineRole;
using render::Palette;
using render::Rgb;

using Matrix = std::array<std::array<double, 3>, 3>;
constexpr Matrix kNormal{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
constexpr Matrix kProtan{{{0.152286, 1.052583, -0.204868}, {0.114503, 0.786281, 0.099216}, {-0.003882, -0.048116, 1.051998}}};
constexpr Matrix kDeutan{{{0.367322, 0.860646, -0.227968}, {0.280085, 0.672501, 0.047413}, {-0.011820, 0.042940, 0.968881}}};
constexpr Matrix kTritan{{{1.255528, -0.076749, -0.178779}, {-0.078411, 0.930809, 0.147602}, {0.004733, 0.691367, 0.303900}}};
constexpr std::array<const Matrix*, 4> kVisions{&kNormal, &kProtan, &kDeutan, &kTritan};
constexpr const char* kVisionNames[] = {"normal", "protanopia", "deuteranopia", "tritanopia"};

double lin(uint8_t c) {
    const double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
// CIELAB (D65) of c as a viewer with vision m sees it.
std::array<double, 3> lab(Rgb c, const Matrix& m) {
    const double in[3] = {lin(c.r), lin(c.g), lin(c.b)};
    double v[3];
    for (int i = 0; i < 3; ++i) v[i] = std::clamp(m[i][0] * in[0] + m[i][1] * in[1] + m[i][2] * in[2], 0.0, 1.0);
    const double X = 0.4124 * v[0] + 0.3576 * v[1] + 0.1805 * v[2], Y = 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2],
                 Z = 0.0193 * v[0] + 0.1192 * v[1] + 0.9505 * v[2];
    auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116; };
    const double fx = f(X / 0.95047), fy = f(Y), fz = f(Z / 1.08883);
    return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}
double delta_e(Rgb a, Rgb b, const Matrix& m) {
    const auto p = lab(a, m), q = lab(b, m);
    return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}
// WCAG 2: (L1 + 0.05) / (L2 + 0.05), L the relative luminance.
double contrast(Rgb a, Rgb b) {
    auto L = [](Rgb c) { return 0.2126 * lin(c.r) + 0.7152 * lin(c.g) + 0.0722 * lin(c.b); };
    const double x = L(a), y = L(b);
    return (std::max(x, y) + 0.05) / (std::min(x, y) + 0.05);
}

struct Named {
    const char* name;
    Rgb c;
};
// The worst pair's distance over the four visions, with its names.
double worst_pair(const std::vector<Named>& colours, std::string& which) {
    double worst = 1e9;
    for (std::size_t i = 0; i < colours.size(); ++i)
        for (std::size_t j = i + 1; j < colours.size(); ++j)
            for (std::size_t v = 0; v < kVisions.size(); ++v) {
                const double d = delta_e(colours[i].c, colours[j].c, *kVisions[v]);
                if (d < worst) worst = d, which = std::string(colours[i].name) + " and " + colours[j].name + " (" + kVisionNames[v] + ")";
            }
    return worst;
}

TEST(Palette, TheColourBlindPalettesLinesStayApartUnderEveryDeficiency) {
    const Palette p = Palette::colour_blind;
    const render::PaletteFrame f = render::palette_frame(p);
    const std::vector<Named> lines = {
        {"ship", render::palette_line(p, LineRole::ship, {255, 64, 64})},
        {"asteroid", render::palette_line(p, LineRole::asteroid, {200, 190, 170})},
        {"bullet", render::palette_line(p, LineRole::bullet, {255, 255, 160})},
        {"body", render::palette_line(p, LineRole::body, {120, 160, 255})},
        {"instrument", render::palette_line(p, LineRole::instrument, {255, 210, 90})},
        {"the Earth's coast", render::palette_line(p, LineRole::grid, {130, 215, 150})},
        {"the limit circle", f.rim},
        {"background", f.background},
    };
    std::string which;
    const double worst = worst_pair(lines, which);
    EXPECT_GE(worst, 15) << which;
    // A dim grid line (the kiosk's, the Earth's graticule) against the background.
    for (const Rgb dim : {Rgb{70, 90, 120}, Rgb{55, 70, 95}, Rgb{45, 58, 80}})
        for (const Matrix* m : kVisions) EXPECT_GE(delta_e(render::palette_line(p, LineRole::grid, dim), f.background, *m), 15);
    // Brighter grid lines stay brighter: the coast over the graticule.
    EXPECT_GT(lab(render::palette_line(p, LineRole::grid, {130, 215, 150}), kNormal)[0],
              lab(render::palette_line(p, LineRole::grid, {55, 70, 95}), kNormal)[0] + 20);
    // What it is for: the kiosk's own colours have a pair far closer (its blue and pink bodies
    // under protanopia), which the test would refuse.
    const std::vector<Named> own = {{"square", {255, 200, 64}}, {"triangle", {64, 220, 120}}, {"hexagon", {120, 160, 255}},
                                    {"circle", {230, 120, 230}}, {"ship", {255, 64, 64}}};
    EXPECT_LT(worst_pair(own, which), 10) << which;
}

// Every colour a built-in scene gives a body, in every role.
std::vector<Rgb> scene_colours() {
    std::vector<Rgb> out;
    for (const std::string& name : world::builtin_scene_names()) {
        world::Scene s;
        if (!world::builtin_scene(name, {}, s)) continue;
        for (const world::SceneBody& b : s.bodies) out.push_back({b.color.r, b.color.g, b.color.b});
    }
    out.push_back({0, 0, 120});  // (a dim saturated one: raised toward white)
    out.push_back({0, 0, 0});
    return out;
}

TEST(Palette, TheHighContrastPalettesLinesAndTextAreAtSevenToOne) {
    const Palette p = Palette::high_contrast;
    const render::PaletteFrame f = render::palette_frame(p);
    double worst = 1e9;
    for (const Rgb own : scene_colours())
        for (int role = 0; role <= static_cast<int>(LineRole::instrument); ++role)
            worst = std::min(worst, contrast(render::palette_line(p, static_cast<LineRole>(role), own), f.background));
    for (const Rgb c : {f.rim, f.text, f.dim}) worst = std::min(worst, contrast(c, f.background));
    EXPECT_GE(worst, 7.0);
    // (The scene palette's own dim grid lines are far below it.)
    EXPECT_LT(contrast({45, 58, 80}, render::PaletteFrame{}.background), 3);
}

// CIELAB hue angle, degrees.
double hue(Rgb c) {
    const auto l = lab(c, kNormal);
    return std::atan2(l[2], l[1]) * 180 / 3.14159265358979323846;
}

// The print palette: on white paper every line of every scene's colours at 4.5:1 or more (WCAG
// AA for text), a grid line at 3:1 and lighter than the lines; each keeps its own hue (colour
// kept for meaning) within 5 degrees of CIELAB hue, a colour darkened rather than replaced.
TEST(Palette, ThePrintPalettesLinesAreDarkOnWhiteInTheirOwnHue) {
    const Palette p = Palette::print;
    const render::PaletteFrame f = render::palette_frame(p);
    EXPECT_EQ(f.background, (Rgb{255, 255, 255}));
    double worst_line = 1e9, worst_grid = 1e9, worst_hue = 0;
    for (const Rgb own : scene_colours())
        for (int role = 0; role <= static_cast<int>(LineRole::instrument); ++role) {
            const Rgb c = render::palette_line(p, static_cast<LineRole>(role), own);
            const double k = contrast(c, f.background);
            if (static_cast<LineRole>(role) == LineRole::grid) worst_grid = std::min(worst_grid, k);
            else worst_line = std::min(worst_line, k);
            const auto l = lab(own, kNormal);
            if (std::hypot(l[1], l[2]) > 10) {  // (a colour with a hue to keep)
                const double d = std::fabs(std::remainder(hue(c) - hue(own), 360.0));
                worst_hue = std::max(worst_hue, d);
            }
        }
    for (const Rgb c : {f.rim, f.text, f.dim}) worst_line = std::min(worst_line, contrast(c, f.background));
    EXPECT_GE(worst_line, 4.5);
    EXPECT_GE(worst_grid, 3.0);
    for (const Rgb own : scene_colours())  // a grid line no darker than a body of its colour
        EXPECT_LE(contrast(render::palette_line(p, LineRole::grid, own), f.background),
                  contrast(render::palette_line(p, LineRole::body, own), f.background) + 1e-9);
    EXPECT_LT(worst_hue, 5.0);
}

// A frame of `scene` drawn aliased in palette p on a memory canvas: the set of its pixels'
// colours, and the set the palette allows (its frame's colours and each body's line colour).
void drawn_colours(const char* scene, Palette p, std::set<uint32_t>& seen, std::set<uint32_t>& allowed, Rgb& ship) {
    world::Scene s;
    ASSERT_TRUE(world::builtin_scene(scene, {}, s));
    world::World<double> w(s);
    render::DrawOptions o;
    o.palette = p;
    const render::PaletteFrame f = render::palette_frame(p);
    o.background = f.background, o.outside = f.outside, o.rim = f.rim;
    const render::PixelFormat fmt = render::PixelFormat::xrgb8888();
    std::vector<uint8_t> px(640 * 400 * 4);
    const render::Canvas c(px.data(), 640, 400, 640 * 4, fmt);
    render::DrawScratch<double> scratch;
    scratch.prepare(w);
    w.step(1.0 / 60);
    render::draw_world(c, w, o, scratch);
    auto key = [](Rgb x) { return uint32_t{x.r} << 16 | uint32_t{x.g} << 8 | x.b; };
    for (const Rgb x : {f.background, f.outside, f.rim}) allowed.insert(key(x));
    for (const auto& b : w.bodies) {
        const Rgb line = render::body_color(b, o);
        allowed.insert(key(line));
        if (b.desc->controlled) ship = line;
    }
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x) seen.insert(key(c.get(x, y)));
}

TEST(Palette, DrawnFramesUseOnlyThePalettesColours) {
    for (const char* scene : {"kiosk", "earth", "asteroids"})
        for (const Palette p : {Palette::colour_blind, Palette::high_contrast, Palette::print}) {
            SCOPED_TRACE(std::string(scene) + " " + render::palette_name(p));
            std::set<uint32_t> seen, allowed;
            Rgb ship{};
            drawn_colours(scene, p, seen, allowed, ship);
            for (const uint32_t c : seen) EXPECT_TRUE(allowed.count(c)) << std::hex << c;
            if (p != Palette::print) {  // (print: by its own colour)
                EXPECT_EQ(ship, render::palette_line(p, LineRole::ship, {}));
            }
            if (std::string(scene) != "asteroids") {  // (the game's ship waits for "press fire")
                EXPECT_TRUE(seen.count(uint32_t{ship.r} << 16 | uint32_t{ship.g} << 8 | ship.b)) << "the ship is drawn in its role's colour";
            }
        }
}

// The HUD on a canvas: the height of its first line of text (the rows with a lit pixel from the
// top down to the first empty row), and the rightmost lit pixel of its bottom quarter.
struct HudExtent {
    int first_line_height = 0, legend_right = -1;
};
HudExtent hud_extent(int width, int height, bool large) {
    const render::PixelFormat fmt = render::PixelFormat::xrgb8888();
    std::vector<uint8_t> px(static_cast<std::size_t>(width) * height * 4, 0);
    const render::Canvas c(px.data(), width, height, width * 4, fmt);
    render::HudInfo h;
    h.K = 0.5, h.scene = "kiosk", h.projection = "equidistant", h.large = large;
    h.controls = "arrows/WASD  Space fire  +/- K  1 2 3 K=-1,0,1  P projection  M measure  H HUD  R reset  Esc";
    render::draw_hud(c, render::builtin_font(), h, render::layout_hud(width, height, render::builtin_font(), h));
    auto lit = [&](int x, int y) { return !(c.get(x, y) == Rgb{}); };
    HudExtent e;
    int top = -1;
    for (int y = 0; y < height / 2; ++y) {
        bool any = false;
        for (int x = 0; x < width / 2 && !any; ++x) any = lit(x, y);
        if (any && top < 0) top = y;
        if (!any && top >= 0) {
            e.first_line_height = y - top;
            break;
        }
    }
    for (int y = height * 3 / 4; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (lit(x, y)) e.legend_right = std::max(e.legend_right, x);
    return e;
}

TEST(Palette, TheLargeHudIsTwiceTheHeightAndItsLegendFits) {
    const HudExtent normal = hud_extent(800, 480, false), large = hud_extent(800, 480, true);
    ASSERT_GT(normal.first_line_height, 4);
    EXPECT_NEAR(double(large.first_line_height) / normal.first_line_height, 2.0, 0.15);
    // The legend, wider than the canvas at this size, wraps: nothing runs into the right margin.
    for (const auto& [w, h] : {std::pair{800, 480}, {400, 300}, {330, 480}}) {
        const HudExtent e = hud_extent(w, h, true);
        EXPECT_GE(e.legend_right, 0) << w;
        EXPECT_LT(e.legend_right, w - 6) << w << "x" << h << ": the legend reaches the edge";
    }
}

}  // namespace palette_test
}  // namespace
