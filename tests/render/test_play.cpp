// The rules every frame loop shares (render/play.hpp): a control's effect on the world, the
// projection cycle, the best score and the game's HUD, against the world's own state.
#include <gtest/gtest.h>

#include <set>

#include "render/play.hpp"
#include "world/engines.hpp"
#include "world/scene.hpp"

namespace {

using namespace noneuclid;
using World = world::World<double>;

World kiosk() {
    world::Scene scene;
    EXPECT_TRUE(world::builtin_scene("kiosk", world::SceneParams{}, scene));
    return World(scene);
}

TEST(Play, AHeldActionActsOnceAndAPressActionOnEveryPress) {
    World w = kiosk();
    using render::Applied;
    EXPECT_EQ(render::apply_control(w, world::Action::thrust, true), Applied::pressed);
    EXPECT_TRUE(w.held(world::Action::thrust));
    EXPECT_EQ(render::apply_control(w, world::Action::thrust, true), Applied::nothing);  // held already
    EXPECT_EQ(render::apply_control(w, world::Action::thrust, false), Applied::released);
    EXPECT_EQ(render::apply_control(w, world::Action::thrust, false), Applied::nothing);
    EXPECT_FALSE(w.held(world::Action::thrust));
    // hyperbolic acts on each press: K is -1 after it, even pressed twice without a release.
    w.K = 0.5;
    EXPECT_EQ(render::apply_control(w, world::Action::hyperbolic, true), Applied::pressed);
    EXPECT_EQ(w.K, -1.0);
    w.K = 0.5;
    EXPECT_EQ(render::apply_control(w, world::Action::hyperbolic, true), Applied::pressed);
    EXPECT_EQ(w.K, -1.0);
    // The view's controls are the caller's.
    EXPECT_EQ(render::apply_control(w, world::Action::projection, true), Applied::not_action);
    EXPECT_EQ(render::apply_control(w, world::Action::hud, true), Applied::not_action);
}

TEST(Play, TheProjectionCycleVisitsEveryProjectionOnce) {
    const std::size_t count = sizeof geo::kProjections / sizeof geo::kProjections[0];
    std::set<geo::Projection> seen;
    geo::Projection p = geo::kProjections[0];
    for (std::size_t i = 0; i < count; ++i) {
        seen.insert(p);
        p = render::next_projection(p);
    }
    EXPECT_EQ(seen.size(), count);
    EXPECT_EQ(p, geo::kProjections[0]);
}

TEST(Play, TheBestScoreIsBeatenOnlyByAHigherGameAndForgottenAtTheNextStart) {
    render::BestScore b{100};
    using E = world::GameEvent;
    b.take(E{E::over, 0, 0, 80});
    EXPECT_EQ(b.best, 100);
    EXPECT_FALSE(b.new_best);
    b.take(E{E::start});
    b.take(E{E::hit});
    b.take(E{E::over, 0, 0, 150});
    EXPECT_EQ(b.best, 150);
    EXPECT_TRUE(b.new_best);
    b.take(E{E::start});
    EXPECT_FALSE(b.new_best);
    EXPECT_EQ(b.best, 150);
}

TEST(Play, TheGamesHudFollowsTheGame) {
    world::Scene scene;
    ASSERT_TRUE(world::builtin_scene("asteroids", world::SceneParams{}, scene));
    World w(scene);
    const render::BestScore best{42, false};
    render::HudGame h = render::hud_game(w, best);
    ASSERT_TRUE(h.on);
    EXPECT_EQ(h.screen, render::HudGame::ready);
    EXPECT_EQ(h.best, 42);
    render::apply_control(w, world::Action::fire, true);  // fire starts a game
    w.step(1.0 / 60);
    h = render::hud_game(w, best);
    EXPECT_EQ(w.game().phase, world::GamePhase::playing);
    EXPECT_EQ(h.screen, render::HudGame::new_level);  // its first level, for two seconds
    EXPECT_EQ(h.lives, w.game().lives);
    EXPECT_EQ(h.level, w.game().level);
    EXPECT_FALSE(render::hud_game(kiosk(), best).on);
}

}  // namespace
