// The Asteroids game's rules (world/game.hpp) in the world, in double and in fixed point: firing
// (where a bullet starts and how fast, against the reference model), range and cooldown, the
// split and the score, crashes, lives, the respawn, game over, levels and their K, the limit
// circle's rule, and a seed's determinism. Bodies are placed by hand where a rule needs an exact
// case; the geometry of the hits themselves is tests/geometry/test_collision.cpp's.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <type_traits>

#include "game_world.hpp"
#include "geometry/reference.hpp"
#include "files/dump.hpp"
#include "test_common.hpp"
#include "world/world.hpp"

using namespace noneuclid::world;
using namespace noneuclid::files;
using noneuclid::fx::fixed;
using noneuclid::geo::Polar;
using noneuclid::test::count;
using noneuclid::test::game_scene;
namespace ref = noneuclid::geo::ref;

namespace {

using noneuclid::test::kPi;

template <class W>
int ship_index(const W& w) {
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (w.bodies[i].desc->controlled) return static_cast<int>(i);
    return -1;
}
template <class W>
int first(const W& w, BodyKind k) {
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (w.bodies[i].active && w.bodies[i].desc->kind() == k) return static_cast<int>(i);
    return -1;
}
// Steps until an event of `kind` (at most `steps`); the number of steps taken, -1 if none came.
template <class W>
int until(W& w, GameEvent::Kind kind, int steps, GameEvent* got = nullptr) {
    for (int i = 1; i <= steps; ++i) {
        w.step(1.0 / 60);
        for (int e = 0; e < w.game().event_count(); ++e)
            if (w.game().events()[e].kind == kind) {
                if (got) *got = w.game().events()[e];
                return i;
            }
    }
    return -1;
}
// Starts a game and waits out the respawned ship's safe time.
template <class W>
void start(W& w) {
    w.press(Action::fire);
    w.release(Action::fire);
    EXPECT_EQ(w.game().phase, GamePhase::ready) << "a game begins at the next step";
    w.step(1.0 / 60);
    ASSERT_EQ(w.game().phase, GamePhase::playing);
    while (w.time < w.game().invulnerable_until() + 0.1) w.step(1.0 / 60);
}
// Moves the body to `at`, still (or moving at `speed` along `travel`).
template <class B>
void place(B& b, double r, double theta, double speed = 0, double travel = 0) {
    using T = decltype(b.speed);
    b.centre = {T(r), T(theta)};
    b.speed = T(speed), b.travel = T(travel);
    b.coast = {};
}
// Removes every asteroid but `keep` (with none left the level is cleared, and the next one
// comes after the pause).
template <class W>
void clear_all_but(W& w, int keep) {
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
        if (static_cast<int>(i) != keep && w.bodies[i].desc->kind() == BodyKind::asteroid) w.bodies[i].active = false;
}
// Parks every asteroid below O at distance 1, still: out of the way of shots fired upward from
// O, which on the sphere would have to fly 2 pi - 1.4 > bullet_range to come round to them.
template <class W>
void park_asteroids(W& w) {
    for (auto& b : w.bodies)
        if (b.active && b.desc->kind() == BodyKind::asteroid) place(b, 1.0, -kPi / 2);
}
template <class W>
void clear_bullets(W& w) {
    for (auto& b : w.bodies)
        if (b.desc->kind() == BodyKind::bullet) b.active = false;
}

template <class T>
void a_shot_leaves_the_nose_with_the_ships_velocity() {
    for (double K : {-1.0, 0.0, 1.0}) {
        SCOPED_TRACE(K);
        World<T> w(game_scene(K));
        start(w);
        auto& ship = w.bodies[static_cast<std::size_t>(ship_index(w))];
        // A ship away from O, moving one way and facing another.
        place(ship, 1.3, 0.4, 0.5, 2.0);
        ship.facing = T(-0.7);
        const double v = w.scene().game.bullet_speed, nose = 0.12;
        w.press(Action::fire);
        w.step(1.0 / 60);  // moves the ship one step, then fires from where it is
        const int b = first(w, BodyKind::bullet);
        ASSERT_GE(b, 0);
        const auto& bullet = w.bodies[static_cast<std::size_t>(b)];
        const Polar<double> sc{static_cast<double>(ship.centre.r), static_cast<double>(ship.centre.theta)};
        const double sf = static_cast<double>(ship.facing), st = static_cast<double>(ship.travel);
        // The reference: the nose is (0.12, 0) in the ship's frame; the velocity, in the tangent
        // plane at the centre, is bullet_speed along the facing plus the ship's own.
        const Polar<double> at = ref::vertex(K, sc, sf, {nose, 0});
        constexpr bool kFixed = std::is_same_v<T, fixed>;
        const double tol = kFixed ? 2e-4 : 1e-9;
        EXPECT_LT(ref::distance(K, at, {static_cast<double>(bullet.centre.r), static_cast<double>(bullet.centre.theta)}), tol);
        const double vx = v * std::cos(sf) + 0.5 * std::cos(st), vy = v * std::sin(sf) + 0.5 * std::sin(st);
        EXPECT_NEAR(static_cast<double>(bullet.speed), std::hypot(vx, vy), kFixed ? 1e-4 : 1e-12);
        // Its direction carried to the nose: the frame walked along the facing, turned to the
        // velocity's angle from the facing, read in the carried frame at the nose.
        const glm::dvec3 d = ref::frame(K, sc) * ref::Rot(sf) * ref::Tr(K, nose) * ref::Rot(std::atan2(vy, vx) - sf) *
                             glm::dvec3(0, 1, 0);
        const glm::dvec3 local = ref::frame_inverse(K, at) * d;
        const double chi = std::atan2(local.z, local.y);
        EXPECT_NEAR(std::remainder(static_cast<double>(bullet.travel) - chi, 2 * kPi), 0, kFixed ? 1e-3 : 1e-9);
    }
}

}  // namespace

TEST(Game, AShotLeavesTheNoseWithTheShipsVelocityDouble) { a_shot_leaves_the_nose_with_the_ships_velocity<double>(); }
TEST(Game, AShotLeavesTheNoseWithTheShipsVelocityFixed) { a_shot_leaves_the_nose_with_the_ships_velocity<fixed>(); }

// Fire held: a shot on the press's step and one each cooldown after; a bullet is spent at its
// range, on the sphere too, where it would otherwise come round for ever.
TEST(Game, CooldownAndRange) {
    for (double K : {0.0, 1.0}) {
        SCOPED_TRACE(K);
        World<double> w(game_scene(K));
        start(w);
        park_asteroids(w);
        place(w.bodies[static_cast<std::size_t>(ship_index(w))], 0, 0);
        w.bodies[static_cast<std::size_t>(ship_index(w))].facing = kPi / 2;
        const GameSettings& g = w.scene().game;
        w.press(Action::fire);
        int fired = 0;
        uint32_t last = 0;
        for (int i = 0; i < 60; ++i) {  // one second: shots at 0, 0.2, ... 0.8 s
            w.step(1.0 / 60);
            for (const auto& b : w.bodies)
                if (b.active && b.desc->kind() == BodyKind::bullet && b.serial > last) ++fired, last = b.serial;
        }
        w.release(Action::fire);
        EXPECT_EQ(fired, static_cast<int>(std::ceil(1.0 / g.bullet_cooldown - 1e-9)));
        // One shot lives range / speed seconds (a still ship adds nothing to it).
        while (count(w, BodyKind::bullet) > 0) w.step(1.0 / 60);
        while (w.time < w.game().next_shot()) w.step(1.0 / 60);
        w.press(Action::fire);
        w.step(1.0 / 60);
        w.release(Action::fire);
        ASSERT_EQ(count(w, BodyKind::bullet), 1);
        int steps = 0;
        while (count(w, BodyKind::bullet) > 0) w.step(1.0 / 60), ++steps;
        EXPECT_EQ(steps, static_cast<int>(std::ceil(g.bullet_range / (g.bullet_speed / 60))));
        EXPECT_LT(g.bullet_range, 2 * kPi) << "a bullet must not come round the sphere";
    }
}

// A large asteroid hit splits into two medium ones, a medium into two small, a small one is
// gone; each hit scores its size's points; the pieces fly apart from where it was hit.
template <class T>
void splits_and_scores() {
    World<T> w(game_scene(-1));
    start(w);
    const int s = ship_index(w);
    const GameSettings& g = w.scene().game;
    long expected = 0;
    for (int size = 0; size < 3; ++size) {
        SCOPED_TRACE(size);
        // The asteroid of this size: the first active one of it, placed straight above the ship.
        int a = -1;
        for (std::size_t i = 0; i < w.bodies.size(); ++i)
            if (w.bodies[i].active && w.game().size_of(i) == size) a = static_cast<int>(i);
        ASSERT_GE(a, 0);
        clear_all_but(w, a);
        place(w.bodies[static_cast<std::size_t>(a)], 0.7, kPi / 2);
        place(w.bodies[static_cast<std::size_t>(s)], 0, 0);
        w.bodies[static_cast<std::size_t>(s)].facing = T(kPi / 2);
        const uint32_t serial = w.bodies[static_cast<std::size_t>(a)].serial;
        const Polar<T> where = w.bodies[static_cast<std::size_t>(a)].centre;
        while (w.time < w.game().next_shot()) w.step(1.0 / 60);
        w.press(Action::fire);
        GameEvent hit;
        ASSERT_GT(until(w, GameEvent::hit, 120, &hit), 0);
        w.release(Action::fire);
        clear_bullets(w);  // the shots after the hit, which could hit a piece
        EXPECT_EQ(hit.asteroid, serial);
        expected += g.points[size];
        EXPECT_EQ(w.game().score, expected);
        EXPECT_FALSE(w.bodies[static_cast<std::size_t>(a)].active && w.bodies[static_cast<std::size_t>(a)].serial == serial);
        int pieces = 0;
        for (std::size_t i = 0; i < w.bodies.size(); ++i) {
            const auto& b = w.bodies[i];
            if (!b.active || b.desc->kind() != BodyKind::asteroid) continue;
            ++pieces;
            EXPECT_EQ(w.game().size_of(i), size + 1);
            EXPECT_LT(noneuclid::geo::distance(w.K, b.centre, where), T(0.05)) << "born where it was hit";
            EXPECT_GT(b.serial, serial);
        }
        EXPECT_EQ(pieces, size < 2 ? 2 : 0);
        if (pieces == 2) {  // they fly apart
            const int p = first(w, BodyKind::asteroid);
            int q = -1;
            for (std::size_t i = static_cast<std::size_t>(p) + 1; i < w.bodies.size(); ++i)
                if (w.bodies[i].active && w.bodies[i].desc->kind() == BodyKind::asteroid) q = static_cast<int>(i);
            const T d0 = noneuclid::geo::distance(w.K, w.bodies[static_cast<std::size_t>(p)].centre, w.bodies[static_cast<std::size_t>(q)].centre);
            for (int i = 0; i < 30; ++i) w.step(1.0 / 60);
            const T d1 = noneuclid::geo::distance(w.K, w.bodies[static_cast<std::size_t>(p)].centre, w.bodies[static_cast<std::size_t>(q)].centre);
            EXPECT_GT(d1, d0 + T(0.5 * g.split_speed));  // apart at 2 split_speed, for half a second
        }
    }
    EXPECT_EQ(expected, g.points[0] + g.points[1] + g.points[2]);
}
TEST(Game, SplitsAndScoresDouble) { splits_and_scores<double>(); }
TEST(Game, SplitsAndScoresFixed) { splits_and_scores<fixed>(); }

// An asteroid on the ship: a crash, a life gone, the ship back at O after the respawn delay,
// safe (and blinking) for a while even on top of an asteroid; the last life ends the game, whose
// screen gives way to "press fire", where fire starts a new game.
TEST(Game, CrashesLivesRespawnAndGameOver) {
    World<fixed> w(game_scene(1));
    start(w);
    const GameSettings& g = w.scene().game;
    const int s = ship_index(w);
    for (int life = g.lives; life >= 1; --life) {
        SCOPED_TRACE(life);
        const int a = first(w, BodyKind::asteroid);
        ASSERT_GE(a, 0);
        clear_all_but(w, a);
        const auto& sh = w.bodies[static_cast<std::size_t>(s)];
        place(w.bodies[static_cast<std::size_t>(a)], static_cast<double>(sh.centre.r), static_cast<double>(sh.centre.theta));
        GameEvent crash;
        const uint32_t serial = w.bodies[static_cast<std::size_t>(a)].serial;  // (its slot may take a piece)
        ASSERT_EQ(until(w, GameEvent::crash, 1, &crash), 1);
        EXPECT_EQ(crash.asteroid, serial);
        EXPECT_EQ(w.game().lives, life - 1);
        EXPECT_FALSE(sh.active);
        if (life == 1) break;
        EXPECT_EQ(w.game().phase, GamePhase::playing);
        // Back after the respawn delay, at O, at rest.
        const double crashed = w.time;
        while (!sh.active) w.step(1.0 / 60);
        EXPECT_NEAR(w.time - crashed, g.respawn_delay, 1.0 / 60 + 1e-9);
        EXPECT_EQ(sh.centre.r, fixed(0));
        EXPECT_EQ(sh.speed, fixed(0));
        // Safe while it blinks, even inside an asteroid.
        const int b = first(w, BodyKind::asteroid);
        int hidden = 0, shown = 0;
        while (w.time < w.game().invulnerable_until() - 1.0 / 60) {
            place(w.bodies[static_cast<std::size_t>(b)], 0, 0);
            w.step(1.0 / 60);
            for (int e = 0; e < w.game().event_count(); ++e) EXPECT_NE(w.game().events()[e].kind, GameEvent::crash);
            (sh.hidden ? hidden : shown)++;
        }
        EXPECT_GT(hidden, 5);
        EXPECT_GT(shown, 5);
        place(w.bodies[static_cast<std::size_t>(b)], 2.5, 0);
        w.step(1.0 / 60);
        EXPECT_FALSE(sh.hidden);
    }
    EXPECT_EQ(w.game().phase, GamePhase::over);
    // Fire does nothing on the game-over screen; it ends after game_over_seconds.
    w.press(Action::fire), w.release(Action::fire);
    EXPECT_EQ(w.game().phase, GamePhase::over);
    const double over = w.game().phase_since;
    while (w.game().phase == GamePhase::over) w.step(1.0 / 60);
    EXPECT_NEAR(w.time - over, g.game_over_seconds, 1.0 / 60 + 1e-9);
    EXPECT_EQ(w.game().phase, GamePhase::ready);
    w.press(Action::fire);
    w.step(1.0 / 60);
    EXPECT_EQ(w.game().phase, GamePhase::playing);
    EXPECT_EQ(w.game().lives, g.lives);
    EXPECT_EQ(w.game().score, 0);
}

// A level is cleared when no asteroid is left: after the pause the next one begins, with one
// more asteroid and the next K of the progression.
TEST(Game, LevelsAddAsteroidsAndSetK) {
    Scene scene = game_scene(0);
    scene.game.levels = {0, -1, 1};
    World<double> w(scene);
    start(w);
    const GameSettings& g = w.scene().game;
    for (int level = 1; level <= 4; ++level) {
        SCOPED_TRACE(level);
        EXPECT_EQ(w.game().level, level);
        EXPECT_EQ(count(w, BodyKind::asteroid), std::min(g.asteroids + (level - 1) * g.asteroids_step, g.asteroids_max));
        EXPECT_EQ(w.K, g.levels[static_cast<std::size_t>(level - 1) % 3]);
        clear_all_but(w, -1);
        GameEvent next;
        const int steps = until(w, GameEvent::level, 1000, &next);
        EXPECT_GE(steps, static_cast<int>(g.level_pause * 60));  // (the step that found none left, then the pause)
        EXPECT_LE(steps, static_cast<int>(g.level_pause * 60) + 2);
        EXPECT_EQ(next.value, level + 1);
    }
}

// The limit circle moves a centre across it; it is not a seam of the space. So at K = 0 a bullet
// just inside the rim does not hit an asteroid just inside the rim opposite it (they are 2R
// apart), until it has crossed and is where the asteroid is; at K = +1 with R = pi the rim is
// one point, the antipode, and the same two bodies are the same place: a hit at once.
template <class T>
void limit_circle_rule() {
    for (double K : {0.0, 1.0}) {
        SCOPED_TRACE(K);
        World<T> w(game_scene(K));
        start(w);
        const int a = first(w, BodyKind::asteroid);
        clear_all_but(w, a);
        place(w.bodies[static_cast<std::size_t>(a)], kPi - 0.05, 0);
        const int s = ship_index(w);
        w.bodies[static_cast<std::size_t>(s)].facing = T(-kPi / 2);  // away from both
        while (w.time < w.game().next_shot()) w.step(1.0 / 60);
        w.press(Action::fire);
        w.step(1.0 / 60);
        w.release(Action::fire);
        const int b = first(w, BodyKind::bullet);
        ASSERT_GE(b, 0);
        auto& bullet = w.bodies[static_cast<std::size_t>(b)];
        // Just inside the rim, opposite the asteroid, flying outward.
        place(bullet, kPi - 0.05, kPi, 0.6, kPi);
        const int steps = until(w, GameEvent::hit, 60);
        if (K == 1.0) {
            EXPECT_EQ(steps, 1) << "the same place on the sphere";
        } else {
            // Past the rim after 0.05 / 0.6 s, then inside the asteroid: not before the crossing.
            EXPECT_GT(steps, static_cast<int>(0.05 / 0.6 * 60) - 1);
            EXPECT_LT(steps, 30);
        }
        // Flying inward from there instead, it never meets it at K = 0.
        if (K == 0.0) {
            World<T> v(game_scene(K));
            start(v);
            const int a2 = first(v, BodyKind::asteroid);
            clear_all_but(v, a2);
            place(v.bodies[static_cast<std::size_t>(a2)], kPi - 0.05, 0);
            v.bodies[static_cast<std::size_t>(ship_index(v))].facing = T(-kPi / 2);
            while (v.time < v.game().next_shot()) v.step(1.0 / 60);
            v.press(Action::fire);
            v.step(1.0 / 60);
            v.release(Action::fire);
            place(v.bodies[static_cast<std::size_t>(first(v, BodyKind::bullet))], kPi - 0.05, kPi, 0.6, 0);
            EXPECT_EQ(until(v, GameEvent::hit, 90), -1);
        }
    }
}
TEST(Game, TheLimitCircleIsNotASeamDouble) { limit_circle_rule<double>(); }
TEST(Game, TheLimitCircleIsNotASeamFixed) { limit_circle_rule<fixed>(); }

// The same seed and the same presses give the same game, bit for bit (the dump's lines, every
// tenth frame, and every event); another seed another game.
TEST(Game, ASeedReplaysBitForBit) {
    auto play = [](uint32_t seed, int& hits) {
        Scene s = game_scene(0);
        s.game.levels = {0, -1, 1};
        s.game.seed = seed;
        World<fixed> w(s);
        std::string out;
        w.press(Action::fire);
        hits = 0;
        for (int i = 0; i < 900; ++i) {
            if (i % 97 == 10) w.press(Action::left);
            if (i % 97 == 40) w.release(Action::left);
            if (i % 50 == 0) w.press(Action::fire);
            if (i % 50 == 25) w.release(Action::fire);
            w.step(1.0 / 60);
            for (int e = 0; e < w.game().event_count(); ++e) {
                const GameEvent& ev = w.game().events()[e];
                hits += ev.kind == GameEvent::hit;
                out += std::to_string(ev.kind) + ":" + std::to_string(ev.bullet) + ":" + std::to_string(ev.asteroid) + ";";
            }
            if (i % 10 == 0) dump_frame(w, {}, out);
        }
        return out;
    };
    int hits_a = 0, hits_b = 0, hits_c = 0;
    const std::string a = play(5, hits_a), b = play(5, hits_b), c = play(6, hits_c);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    EXPECT_GT(hits_a, 0) << "the game was played";
}
