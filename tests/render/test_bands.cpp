// A frame drawn a band of rows at a time (Canvas::band, as the firmware draws it: RAM for half
// a frame) writes the whole frame's pixels, bit for bit: the backdrop (its rows kept or
// computed), fills, lines and the HUD (its text and the game's lives), in bands of any height
// drawn top to bottom, frame after frame of a moving world, aliased and anti-aliased; and a
// band writes nothing outside its own rows' memory.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "render/draw_world.hpp"
#include "render/font.hpp"
#include "render/hud.hpp"
#include "render/layout.hpp"

namespace {

using namespace noneuclid;

void hud(const render::Canvas& c, double K) {
    render::HudInfo h;
    h.K = K, h.scene = "scene", h.projection = "equidistant";
    h.controls = "left right thrust fire: the buttons' legend, long enough to wrap over two lines";
    h.game.on = true, h.game.lives = 3, h.game.score = 120, h.game.level = 2, h.game.screen = render::HudGame::new_level;
    render::draw_hud(c, render::builtin_font(), h, render::layout_hud(c.width(), c.height(), render::builtin_font(), h));
}

// The frames of `scene` drawn whole and in bands of `rows` rows (the last may be shorter).
void bands_equal_whole(const char* scene_name, bool aa, int rows, bool keep_backdrop) {
    world::Scene scene;
    ASSERT_TRUE(world::builtin_scene(scene_name, {}, scene));
    world::World<fx::fixed> w(scene);
    for (world::Action a : {world::Action::thrust, world::Action::left, world::Action::curvature_down}) w.press(a);
    render::DrawScratch<fx::fixed> whole, banded;
    whole.prepare(w), banded.prepare(w);
    const int W = 240, H = 240;
    if (keep_backdrop) banded.backdrop.reserve(H);
    const render::PixelFormat f = render::PixelFormat::rgb565();
    const std::size_t stride = W * 2;
    std::vector<uint8_t> a(stride * H, 0x11), b(stride * H, 0x22);
    constexpr std::size_t kGuard = 64;  // bytes on either side of the band's memory, which it must not write
    std::vector<uint8_t> band(stride * static_cast<std::size_t>(rows) + 2 * kGuard, 0x5A);
    const render::Canvas ca(a.data(), W, H, static_cast<std::ptrdiff_t>(stride), f);
    render::DrawOptions o;
    o.antialias = aa;
    for (int frame = 0; frame < 8; ++frame) {
        w.step(1.0 / 15);
        render::draw_world(ca, w, o, whole);
        hud(ca, static_cast<double>(w.K));
        for (int y0 = 0; y0 < H; y0 += rows) {
            const int y1 = std::min(y0 + rows, H);
            const auto cb = render::Canvas::band(band.data() + kGuard, W, H, static_cast<std::ptrdiff_t>(stride), f, y0, y1);
            render::draw_world(cb, w, o, banded);
            hud(cb, static_cast<double>(w.K));
            std::memcpy(b.data() + stride * static_cast<std::size_t>(y0), band.data() + kGuard,
                        stride * static_cast<std::size_t>(y1 - y0));
            for (std::size_t k = 0; k < kGuard; ++k)
                ASSERT_TRUE(band[k] == 0x5A && band[band.size() - 1 - k] == 0x5A) << "rows " << y0 << " to " << y1;
        }
        ASSERT_EQ(a, b) << scene_name << " aa " << aa << " bands of " << rows << " rows, frame " << frame;
    }
}

TEST(Bands, AFrameInBandsIsTheWholeFrame) {
    for (const char* scene : {"kiosk", "asteroids"})
        for (bool aa : {false, true}) {
            bands_equal_whole(scene, aa, 120, true);
            bands_equal_whole(scene, aa, 37, false);
        }
}

}  // namespace
