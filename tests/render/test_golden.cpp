// Golden images of the paper's figures (app/figures.hpp: the table the demo draws). The goldens
// in tests/render/golden/ are the demo's pictures by the double engine at 480x480 without the HUD
// (tests/render/golden/regenerate.sh), drawn here by the same path (app::render_figure: a figure's
// panels side by side, each 480x480). Two
// comparisons, pixel by pixel:
//  - the double engine today against its golden: the same picture, up to 0.05% of the pixels
//    (a libm on another machine may round a sine differently and move a pixel);
//  - the fixed-point engine (the device's) against the same golden: an independent engine
//    drawing the same scene, within the tolerance the geometry report states (0.06 px worst):
//    at most 2% of the pixels differ by more than 24 levels in a channel (anti-aliased edges
//    shift by a few coverage levels), and almost every differing pixel has a pixel of its
//    colour in the golden within one pixel (its colour up to what a line moved by the chords'
//    0.35 px changes: 90 levels).
#include <gtest/gtest.h>

#include <cstdlib>
#include <span>
#include <string>
#include <vector>

#include "app/figures.hpp"
#include "app/picture.hpp"
#include "app/platform.hpp"
#include "app/setup.hpp"

using namespace noneuclid;

namespace {

using app::Figure;

// A figure as the demo draws it (app::render_figure: its panels side by side, each 480x480 and
// labelled), without the HUD, as 8-bit RGB; its width in `width`.
std::string render_rgb(const Figure& g, world::EngineKind engine, int& width) {
    app::Options o = app::defaults(app::Command::render);
    o.engine = engine, o.hud = false;
    o.width = o.height = 480;
    app::Picture picture;
    app::render_figure(g, o, render::builtin_font(), picture);
    width = picture.canvas.width();
    std::string rgb(static_cast<std::size_t>(width) * 480 * 3, '\0');
    for (int y = 0; y < 480; ++y)
        for (int x = 0; x < width; ++x) {
            const render::Rgb c = picture.canvas.get(x, y);
            const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
            rgb[i] = static_cast<char>(c.r), rgb[i + 1] = static_cast<char>(c.g), rgb[i + 2] = static_cast<char>(c.b);
        }
    return rgb;
}

std::string load(const Figure& g, int width) {
    int w = 0, h = 0;
    std::string rgb, err;
    const std::string path = std::string(NONEUCLID_GOLDEN_DIR) + "/" + g.name + ".png";
    EXPECT_TRUE(platform::read_png(path, w, h, rgb, err)) << err;
    EXPECT_EQ(w, width) << g.name;
    EXPECT_EQ(h, 480) << g.name;
    if (w != width || h != 480) rgb.assign(static_cast<std::size_t>(width) * 480 * 3, '\0');
    return rgb;
}

struct Diff {
    long differing = 0;  // pixels whose colour differs
    long unmatched = 0;  // differing pixels with no pixel of their colour within one pixel
};
// `near`: the colour tolerance of the pixel within one pixel that matches a differing one.
Diff compare(const std::string& got, const std::string& want, int width, int tolerance, int near_tolerance) {
    Diff d;
    auto px = [width](const std::string& s, int x, int y) {
        const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
        return s.substr(i, 3);
    };
    auto same_within = [](const std::string& a, const std::string& b, int tolerance) {
        for (int k = 0; k < 3; ++k)
            if (std::abs(static_cast<unsigned char>(a[static_cast<std::size_t>(k)]) -
                         static_cast<unsigned char>(b[static_cast<std::size_t>(k)])) > tolerance)
                return false;
        return true;
    };
    for (int y = 0; y < 480; ++y)
        for (int x = 0; x < width; ++x) {
            const std::string g = px(got, x, y);
            if (same_within(g, px(want, x, y), tolerance)) continue;
            ++d.differing;
            bool near = false;
            for (int dy = -1; dy <= 1 && !near; ++dy)
                for (int dx = -1; dx <= 1 && !near; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    near = xx >= 0 && yy >= 0 && xx < width && yy < 480 && same_within(px(want, xx, yy), g, near_tolerance);
                }
            if (!near) ++d.unmatched;
        }
    return d;
}

TEST(Golden, TheDoubleEngineRedrawsItsGoldens) {
    ASSERT_EQ(app::kFigureCount, 9);  // (a figure added needs its golden: regenerate.sh)
    for (const Figure& g : std::span(app::kFigures, app::kFigureCount)) {
        int width = 0;
        const std::string got = render_rgb(g, world::engine_named("double"), width);
        const Diff d = compare(got, load(g, width), width, 0, 0);
        EXPECT_LE(d.differing, width * 480 / 2000) << g.name;  // 0.05%
        RecordProperty(std::string(g.name) + "_double_differing", static_cast<int>(d.differing));
    }
}

// A differing pixel of the fixed engine's picture is matched by a golden pixel within one pixel
// whose colour is within what a line moved by the chords' tolerance changes: two engines may cut
// the same edge into different chords, each within 0.35 px of the curve (geo::kChordTolerance),
// and an anti-aliased pixel's coverage changes by up to that fraction of a full step.
constexpr int kChordShift = static_cast<int>(255 * geo::kChordTolerance / 256.0 + 1);

TEST(Golden, TheFixedEngineDrawsTheSamePictures) {
    for (const Figure& g : std::span(app::kFigures, app::kFigureCount)) {
        int width = 0;
        const std::string got = render_rgb(g, world::engine_named("fixed"), width);
        const Diff d = compare(got, load(g, width), width, 24, kChordShift);
        RecordProperty(std::string(g.name) + "_fixed_differing", static_cast<int>(d.differing));
        RecordProperty(std::string(g.name) + "_fixed_unmatched", static_cast<int>(d.unmatched));
        EXPECT_LE(d.differing, width * 480 / 50) << g.name;  // 2%
        EXPECT_LE(d.unmatched, d.differing / 20 + 5) << g.name;
    }
}

}  // namespace
