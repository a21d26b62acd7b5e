// What every frame loop does alike with a world it plays (the program's session,
// app/session.cpp; the firmware's, platform/mcu/firmware.cpp; the C interface's, src/capi): a
// control's effect on the world, the next projection, the best score and the game's part of the
// HUD. One copy of these rules, so that a recording plays the same everywhere.
#pragma once

#include <cstddef>

#include "geometry/projection.hpp"
#include "render/hud.hpp"
#include "world/action.hpp"
#include "world/game.hpp"
#include "world/world.hpp"

namespace noneuclid::render {

// What a control did to the world: it is no world action (a view control: the caller's), it
// changed nothing (a press of what is held, a release of what is not, but for the actions that
// act on each press), or it was pressed or released.
enum class Applied { not_action, nothing, pressed, released };

template <class W>
Applied apply_action(W& w, world::Action a, bool pressed) {
    if (pressed == w.held(a) && !world::acts_on_press(a)) return Applied::nothing;
    if (pressed) w.press(a);
    else w.release(a);
    return pressed ? Applied::pressed : Applied::released;
}
template <class W>
Applied apply_control(W& w, world::Action c, bool pressed) {
    return world::is_world_action(c) ? apply_action(w, c, pressed) : Applied::not_action;
}

// The projection after p, cycling through every projection (the projection control).
inline geo::Projection next_projection(geo::Projection p) {
    constexpr std::size_t count = sizeof geo::kProjections / sizeof geo::kProjections[0];
    std::size_t i = 0;
    while (i < count && geo::kProjections[i] != p) ++i;
    return geo::kProjections[(i + 1) % count];
}

// The high score as the HUD shows it: a game that starts has no new best yet; one that ends
// may beat the best.
struct BestScore {
    long best = 0;
    bool new_best = false;
    void take(const world::GameEvent& e) {
        if (e.kind == world::GameEvent::start) new_best = false;
        if (e.kind != world::GameEvent::over) return;
        new_best = e.value > best;
        if (new_best) best = e.value;
    }
};

// The game's part of the HUD: its score, lives and level, and the screen its phase shows (a
// new level's for two seconds).
template <class W>
HudGame hud_game(const W& w, const BestScore& best) {
    HudGame h;
    const auto& g = w.game();
    h.on = g.on();
    if (!h.on) return h;
    h.score = g.score, h.best = best.best, h.new_best = best.new_best, h.lives = g.lives, h.level = g.level;
    switch (g.phase) {
        case world::GamePhase::ready: h.screen = HudGame::ready; break;
        case world::GamePhase::over: h.screen = HudGame::over; break;
        case world::GamePhase::playing:
            h.screen = w.time - g.level_since < 2 ? HudGame::new_level : HudGame::none;
            break;
    }
    return h;
}

}  // namespace noneuclid::render
