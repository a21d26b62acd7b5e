// noneuclid on a microcontroller (docs/microcontroller.md): one built-in scene on the fixed
// engine, its game and HUD, drawn by the CPU rasteriser into a static 240x240 RGB565 buffer
// that the board presents (board.hpp). The world and its drawing buffers are made once at start (the
// heap's only use); the frames allocate nothing, which the firmware checks and reports.
//
// The frame order is the program's (kinds/step.hpp's start_run and advance_run, which the
// session runs too): the controls due at time 0, then frame 0 drawn; each next frame one step
// of 1/60 s, the controls due at the new time, the frame drawn. The controls act, and the HUD's game is filled, by the rules the program's
// session uses (render/play.hpp; the session's attract mode aside), so a recording's frames
// equal render's, pixel for pixel.
#include <cstdio>

#include "board.hpp"
#include "heap.hpp"
#include "render/canvas.hpp"
#include "render/font.hpp"
#include "render/hud.hpp"
#include "render/layout.hpp"
#include "render/palette.hpp"
#include "render/play.hpp"
#include "kinds/kinds.hpp"
#include "kinds/step.hpp"
#include "world/scene.hpp"

namespace noneuclid::mcu {
namespace {

// The firmware's kind of world: the world of constant K on the fixed engine (kinds/kinds.hpp;
// the scene is checked to be of this kind, whose Capabilities say firmware).
using Kind = kinds::Constant<world::World<fx::fixed>>;
using World = Kind::World;
constexpr double kDt = kinds::kStepSeconds;  // world seconds a step: the program's

// The picture, drawn a band of rows at a time (Canvas::band), each band presented when drawn:
// RAM holds half a frame. Static, so that it is counted in the firmware's RAM, never on the heap.
constexpr int kBands = 2, kBandRows = board::kHeight / kBands;
static_assert(kBandRows * kBands == board::kHeight);
alignas(4) uint16_t g_pixels[board::kWidth * kBandRows];

// The view: the drawing options and the HUD, which the projection and hud controls change.
struct View {
    render::DrawOptions draw;
    bool hud = false;
    render::BestScore best;  // the game's high score
};

// A control as the program's session takes it (render/play.hpp): a world action, or the
// projection control, the next projection on its press; hud, the HUD on or off on its press.
void apply(World& w, View& v, world::Action c, bool pressed) {
    if (render::apply_control(w, c, pressed) != render::Applied::not_action || !pressed) return;
    if (c == world::Action::hud) v.hud = !v.hud;
    if (c == world::Action::projection) v.draw.projection = render::next_projection(v.draw.projection);
}

// The controls due by the world's time now.
void play_due(World& w, View& o) {
    RecordedEvent e[8];
    for (int n; (n = board::controls(w.time, e, 8)) > 0;)
        for (int i = 0; i < n; ++i) {
            apply(w, o, e[i].control, e[i].pressed);
            if (e[i].tap) apply(w, o, e[i].control, false);
        }
}

// render's options for this recording (app/setup.cpp's session_options): its projection and
// anti-aliasing, lines one pixel wide, the scene palette's frame colours.
render::DrawOptions draw_options(const Recording& r) {
    render::DrawOptions o;
    o.projection = r.projection;
    o.antialias = r.aa;
    o.line_width = render::kSub;
    const render::PaletteFrame frame = render::palette_frame(o.palette);
    o.background = frame.background, o.outside = frame.outside, o.rim = frame.rim;
    return o;
}

// After a step: the best score (render/play.hpp), as the program's session keeps it.
void game_events(const World& w, View& v) {
    const auto& g = w.game();
    for (int i = 0; i < g.event_count(); ++i) v.best.take(g.events()[i]);
}

// The HUD as app/session.cpp's hud_info fills it for a recording played by render: English, the
// built-in font, the buttons' legend (attract mode's laid out beside it), no frame rate, no
// instruments' panels (none is on).
render::HudInfo hud_info(const World& w, const View& v, const char* scene) {
    using lang::Text;
    const world::Scene& s = w.scene();
    const bool fire = s.game.on || !s.measures.empty();
    render::HudInfo info;
    info.on = v.hud;
    info.K = static_cast<double>(w.K);
    info.scene = scene;
    info.projection = render::projection_words(v.draw.projection, lang::Language::en);
    info.controls = lang::text(s.zoom.on() ? Text::legend_zoom_buttons : fire ? Text::legend_buttons
                                                                              : Text::legend_buttons_no_fire,
                               lang::Language::en);
    info.other_legend = lang::text(s.game.on ? Text::legend_attract_game : Text::legend_attract, lang::Language::en);
    info.game = render::hud_game(w, v.best);
    return info;
}

[[noreturn]] void run() {
    static Recording setup;  // (static: its events are kilobytes, the stack is small)
    if (!board::start(setup)) board::finish(false, "noneuclid firmware: no start.");
    char why[160] = "";
    Kind* made = nullptr;
    {  // The scene is copied into the world: its own copy is freed before the buffers are made.
        world::Scene scene;
        std::string reason;
        if (!world::builtin_scene(setup.scene, world::SceneParams{}, scene, &reason)) {
            std::snprintf(why, sizeof why, "noneuclid firmware: no built-in scene '%s'.", setup.scene);
            board::finish(false, why);
        }
        kinds::KindChoice kind;
        std::string reason_kind;
        constexpr world::EngineKind fixed = world::engine_named("fixed");
        if (!kinds::choose_kind(scene, &fixed, kind, reason_kind) || !kinds::kind_can(kind.kind).firmware) {
            std::snprintf(why, sizeof why, "noneuclid firmware: the scene '%s' is not a kind of world it runs.", setup.scene);
            board::finish(false, why);
        }
        made = new Kind(scene);
    }
    Kind& kind = *made;
    World& w = kind.world;
    // (No room kept for still bodies' points: RAM is short; the backdrop's rows kept: the same
    // every frame.)
    kind.prepare_one_thread(false).backdrop.reserve(board::kHeight);
    View o{draw_options(setup), setup.hud, {setup.best}};
    const std::size_t allocations = heap_allocations();

    kinds::start_run([&] { play_due(w, o); });
    for (long f = 0;; ++f) {
        const render::HudInfo info = hud_info(w, o, setup.scene);
        const render::HudLayout layout = render::layout_hud(board::kWidth, board::kHeight, render::builtin_font(), info);
        o.draw.disc = layout.disc;
        const render::PaletteFrame colours = render::palette_frame(o.draw.palette);
        for (int y0 = 0; y0 < board::kHeight; y0 += kBandRows) {  // (each band: what the whole frame has there)
            const auto canvas = render::Canvas::band(g_pixels, board::kWidth, board::kHeight, board::kWidth * 2,
                                                     render::PixelFormat::rgb565(), y0, y0 + kBandRows);
            kind.draw(canvas, o.draw);
            if (o.hud) render::draw_hud(canvas, render::builtin_font(), info, layout, colours.text, colours.dim);
            if (!board::present(g_pixels, y0, y0 + kBandRows, f)) board::finish(false, "noneuclid firmware: the display failed.");
        }
        if (f == setup.frames && !board::runs_forever()) break;
        kinds::advance_run(
            [&] {
                w.step(kDt);
                game_events(w, o);
            },
            [&] { play_due(w, o); });
    }
    const std::size_t after = heap_allocations() - allocations;
    std::snprintf(why, sizeof why,
                  "noneuclid firmware: %ld frames of %s; heap %u of %u bytes, %u allocations at start, %u in the frames.",
                  setup.frames + 1, setup.scene, static_cast<unsigned>(heap_used()), static_cast<unsigned>(heap_room()),
                  static_cast<unsigned>(allocations), static_cast<unsigned>(after));
    board::finish(after == 0, why);
}

}  // namespace
}  // namespace noneuclid::mcu

int main() { noneuclid::mcu::run(); }
