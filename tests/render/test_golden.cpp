// Golden images of the paper's scenes. The goldens in tests/golden/ are rendered by the
// double engine (tests/golden/regenerate.sh). Two comparisons, pixel by pixel:
//  - the double engine today against its golden: the same picture, up to 0.05% of the pixels
//    (a libm on another machine may round a sine differently and move a pixel);
//  - the fixed-point engine (the device's) against the same golden: an independent engine
//    drawing the same scene, within the tolerance the geometry report states (0.06 px worst):
//    at most 2% of the pixels differ by more than 24 levels in a channel (anti-aliased edges
//    shift by a few coverage levels), and almost every differing pixel has a pixel of its
//    colour in the golden within one pixel.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "desktop/png_file.hpp"
#include "render/render_scene.hpp"

using namespace noneuclid;

namespace {

struct Golden {
    const char* name;
    const char* scene;
    long frames;
    long timelapse;
    bool aa;
};
const Golden kGoldens[] = {
    {"fig1", "fig1", 120, 0, false},     {"fig14", "fig14", 600, 40, false}, {"fig15", "fig15", 600, 40, false},
    {"fig16", "fig16", 120, 15, false},  {"fig17", "fig17", 250, 25, false}, {"kiosk", "kiosk", 60, 0, true},
};

template <class W>
std::string render_rgb(const Golden& g) {
    world::Scene scene;
    EXPECT_TRUE(world::builtin_scene(g.scene, {}, scene));
    W w(scene);
    std::vector<uint32_t> px(480 * 480);
    const render::Canvas c(px.data(), 480, 480, 480 * 4, render::PixelFormat::xrgb8888());
    render::RenderJob job;
    job.frames = g.frames;
    job.timelapse = g.timelapse;
    job.draw.antialias = g.aa;
    render::render_scene(w, c, job);
    std::string rgb(480 * 480 * 3, '\0');
    for (int i = 0; i < 480 * 480; ++i) {
        rgb[static_cast<std::size_t>(i) * 3] = static_cast<char>(px[static_cast<std::size_t>(i)] >> 16);
        rgb[static_cast<std::size_t>(i) * 3 + 1] = static_cast<char>(px[static_cast<std::size_t>(i)] >> 8);
        rgb[static_cast<std::size_t>(i) * 3 + 2] = static_cast<char>(px[static_cast<std::size_t>(i)]);
    }
    return rgb;
}

std::string load(const Golden& g) {
    int w = 0, h = 0;
    std::string rgb, err;
    const std::string path = std::string(NONEUCLID_GOLDEN_DIR) + "/" + g.name + ".png";
    EXPECT_TRUE(platform::read_png(path, w, h, rgb, err)) << err;
    EXPECT_EQ(w, 480);
    EXPECT_EQ(h, 480);
    return rgb;
}

struct Diff {
    long differing = 0;  // pixels whose colour differs
    long unmatched = 0;  // differing pixels with no pixel of their colour within one pixel
};
Diff compare(const std::string& got, const std::string& want, int tolerance) {
    Diff d;
    auto px = [](const std::string& s, int x, int y) {
        const std::size_t i = (static_cast<std::size_t>(y) * 480 + static_cast<std::size_t>(x)) * 3;
        return s.substr(i, 3);
    };
    auto same = [tolerance](const std::string& a, const std::string& b) {
        for (int k = 0; k < 3; ++k)
            if (std::abs(static_cast<unsigned char>(a[static_cast<std::size_t>(k)]) -
                         static_cast<unsigned char>(b[static_cast<std::size_t>(k)])) > tolerance)
                return false;
        return true;
    };
    for (int y = 0; y < 480; ++y)
        for (int x = 0; x < 480; ++x) {
            const std::string g = px(got, x, y);
            if (same(g, px(want, x, y))) continue;
            ++d.differing;
            bool near = false;
            for (int dy = -1; dy <= 1 && !near; ++dy)
                for (int dx = -1; dx <= 1 && !near; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    near = xx >= 0 && yy >= 0 && xx < 480 && yy < 480 && same(px(want, xx, yy), g);
                }
            if (!near) ++d.unmatched;
        }
    return d;
}

TEST(Golden, TheDoubleEngineRedrawsItsGoldens) {
    for (const Golden& g : kGoldens) {
        const Diff d = compare(render_rgb<world::World<double>>(g), load(g), 0);
        EXPECT_LE(d.differing, 480 * 480 / 2000) << g.name;  // 0.05%
        RecordProperty(std::string(g.name) + "_double_differing", static_cast<int>(d.differing));
    }
}

TEST(Golden, TheFixedEngineDrawsTheSamePictures) {
    for (const Golden& g : kGoldens) {
        const Diff d = compare(render_rgb<world::World<fx::fixed>>(g), load(g), 24);
        RecordProperty(std::string(g.name) + "_fixed_differing", static_cast<int>(d.differing));
        RecordProperty(std::string(g.name) + "_fixed_unmatched", static_cast<int>(d.unmatched));
        EXPECT_LE(d.differing, 480 * 480 / 50) << g.name;  // 2%
        EXPECT_LE(d.unmatched, d.differing / 20 + 5) << g.name;
    }
}

}  // namespace
