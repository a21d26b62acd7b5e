// The HUD's layout (render/layout.hpp) as a session draws it: at the four screen sizes people
// use (the square 480x480, the kiosk's 800x480, 1280x720 and 1920x1080), for the kiosk, the
// game, a lesson's caption, the instruments' two panels, a large HUD, the German and French
// texts and a figure's title. The check is on pixels drawn, not on the layout's own numbers:
// the world is drawn alone, then the HUD alone on a blank canvas, and every pixel the HUD lights
// must be one where the world shows the outside of the disc. The layout's boxes must not meet,
// and every lit pixel of the HUD must lie in one of them.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "app/options.hpp"
#include "app/session.hpp"
#include "app/setup.hpp"
#include "render/font.hpp"
#include "render/layout.hpp"

namespace noneuclid {
namespace {

struct Case {
    const char* what;
    const char* scene;
    const char* legend = "buttons";
    const char* language = "en";
    bool large = false;
    const char* caption = "";
    const char* title = "";
    bool hud = true;
    bool fire = false;  // start the game and wait past its new level's screen
};

struct Size {
    int width, height;
};

const Case kCases[] = {
    {.what = "the kiosk", .scene = "kiosk"},
    {.what = "the kiosk's keys, in German", .scene = "kiosk", .legend = "keys", .language = "de"},
    {.what = "the game, in French", .scene = "asteroids", .legend = "keys", .language = "fr", .fire = true},
    {.what = "a lesson's caption",
     .scene = "measure",
     .legend = "keys",
     .caption = "Press fire to go on. The triangle's angles add up to more than 180 degrees where K > 0: "
                "watch the sum while the curvature keys turn K from -1 to +1."},
    {.what = "a large HUD", .scene = "kiosk", .legend = "keys", .large = true},
    {.what = "the Earth's zoom line", .scene = "earth", .legend = "keys"},
    {.what = "an uneven world's note", .scene = "hills", .legend = "keys"},
    {.what = "the three-dimensional world", .scene = "space", .legend = "keys"},
    {.what = "a figure's title, no HUD", .scene = "fig4", .title = "{7,3}, K = -1, stereographic", .hud = false},
};
const Size kSizes[] = {{480, 480}, {800, 480}, {1280, 720}, {1920, 1080}};

struct Drawn {
    int hud_pixels = 0;     // pixels the HUD lit
    int on_disc = 0;        // of them, where the world is not the outside
    int outside_boxes = 0;  // of them, in none of the layout's boxes
    render::HudLayout layout;
    struct {
        int x = -1, y = -1;
    } first_on_disc, first_outside;  // the first of each, for the message
};

Drawn draw(const Case& k, Size size) {
    app::Options o = app::defaults(app::Command::render);
    o.scene = k.scene, o.width = size.width, o.height = size.height, o.hud = k.hud, o.large_hud = k.large;
    o.caption = k.caption, o.title = k.title, o.language = k.language, o.legend = k.legend;
    const world::Scene scene = app::load_scene(o);
    const kinds::KindChoice kind = app::world_kind(o, scene);
    const auto s = app::make_session(kind, scene, app::session_options(o, scene, o.legend, kind),
                                     render::builtin_font(), nullptr);
    app::ScriptPlayer none;
    s->start(none);
    if (k.fire) s->queue({world::Action::fire, true}), s->queue({world::Action::fire, false});
    for (int f = 0; f < (k.fire ? 160 : 20); ++f) s->advance(none);

    const render::PixelFormat fmt = render::PixelFormat::xrgb8888();
    const std::size_t n = static_cast<std::size_t>(size.width) * size.height;
    std::vector<uint32_t> world_px(n), hud_px(n);
    const render::Canvas w(world_px.data(), size.width, size.height, size.width * 4, fmt);
    const render::Canvas h(hud_px.data(), size.width, size.height, size.width * 4, fmt);
    s->draw_world(w);
    const render::Rgb blank{1, 2, 3};
    h.clear(blank);
    s->draw_hud(h);
    Drawn d;
    d.layout = s->layout(size.width, size.height);
    const uint32_t outside = fmt.pack(s->options().draw.outside), none_lit = fmt.pack(blank);
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
            if (h.get_word(x, y) == none_lit) continue;
            ++d.hud_pixels;
            if (w.get_word(x, y) != outside && d.on_disc++ == 0) d.first_on_disc = {x, y};
            bool in = false;
            for (int i = 0; i < render::HudLayout::kBoxes; ++i) {
                const render::Box& b = d.layout.box(i);
                in = in || (x >= b.x && x < b.x + b.w && y >= b.y && y < b.y + b.h);
            }
            if (!in && d.outside_boxes++ == 0) d.first_outside = {x, y};
        }
    return d;
}

TEST(HudLayout, NothingTheHudDrawsCrossesTheDiscOrAnotherPart) {
    for (const Case& k : kCases)
        for (Size size : kSizes) {
            SCOPED_TRACE(std::string(k.what) + " at " + std::to_string(size.width) + "x" + std::to_string(size.height));
            const Drawn d = draw(k, size);
            EXPECT_GT(d.hud_pixels, 100);  // (the HUD was drawn)
            EXPECT_EQ(d.on_disc, 0) << "disc " << d.layout.disc << ", first at " << d.first_on_disc.x << ","
                                    << d.first_on_disc.y;
            EXPECT_EQ(d.outside_boxes, 0) << "first at " << d.first_outside.x << "," << d.first_outside.y;
            for (int i = 0; i < render::HudLayout::kBoxes; ++i)
                for (int j = i + 1; j < render::HudLayout::kBoxes; ++j)
                    EXPECT_FALSE(render::overlap(d.layout.box(i), d.layout.box(j))) << "boxes " << i << " and " << j;
            // The disc keeps at least two thirds of the smaller side.
            EXPECT_GE(d.layout.disc * 3, 2 * std::min(size.width, size.height)) << d.layout.disc;
        }
}

// Where the corners leave room (the kiosk at 800x480, the wide screens), the disc keeps the
// whole height: the HUD goes beside it.
TEST(HudLayout, TheKioskDiscKeepsTheWholeHeight) {
    for (Size size : {Size{800, 480}, Size{1280, 720}, Size{1920, 1080}}) {
        const Drawn d = draw(kCases[0], size);
        EXPECT_EQ(d.layout.disc, size.height) << size.width << "x" << size.height;
    }
}

// The instrument's panel, beside the disc at 800x480 and up; none on a square canvas.
TEST(HudLayout, ThePanelSitsBesideTheDisc) {
    Case k{.what = "an instrument", .scene = "measure", .legend = "keys"};
    for (Size size : kSizes) {
        const Drawn d = draw(k, size);
        const bool room = size.width > size.height;
        EXPECT_EQ(!d.layout.panel[0].empty(), room) << size.width << "x" << size.height;
        EXPECT_EQ(d.on_disc, 0) << size.width << "x" << size.height;
    }
}

}  // namespace
}  // namespace noneuclid
