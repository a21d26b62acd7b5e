// The game's settings in a scene file (its [game] table read, its slots made, every bad value
// with its place), the game over the Earth (backdrop = "earth") and the game in the dump (kinds,
// sizes, phase, score, lives, level, events).
#include <gtest/gtest.h>

#include <string>

#include "../world/game_world.hpp"
#include "files/dump.hpp"
#include "files/scene_file.hpp"
#include "world/earth.hpp"
#include "world/world.hpp"

using namespace noneuclid::world;
using namespace noneuclid::files;
using noneuclid::test::count;
using noneuclid::test::game_scene;

namespace {

// A [game] table in a scene file: the settings read, the slots made; bad values get their place.
TEST(Game, SceneFileSettingsAndErrors) {
    const std::string ok = R"(curvature = -1
[[body]]
name = "ship"
vertices = [[0.15, 0], [0.1, 150], [0.1, 210]]
[game]
seed = 42
lives = 5
asteroids = 2
asteroids_max = 3
sizes = [0.4, 0.25, 0.1]
points = [10, 30, 70]
bullets = 4
levels = [-1, 1]
)";
    Scene s;
    SceneError e;
    ASSERT_TRUE(parse_scene(ok, "ok.toml", s, e)) << e.to_string();
    EXPECT_TRUE(s.game.on);
    EXPECT_EQ(s.game.seed, 42u);
    EXPECT_EQ(s.game.lives, 5);
    EXPECT_EQ(s.game.points[2], 70);
    int asteroids = 0, bullets = 0;
    for (const SceneBody& b : s.bodies) asteroids += b.role == BodyKind::asteroid, bullets += b.role == BodyKind::bullet;
    EXPECT_EQ(asteroids, 4 * 3);
    EXPECT_EQ(bullets, 4);
    World<double> w(s);
    w.press(Action::fire);
    w.step(1.0 / 60);
    EXPECT_EQ(w.K, -1.0);
    EXPECT_EQ(w.game().lives, 5);
    EXPECT_EQ(count(w, BodyKind::asteroid), 2);

    struct Bad {
        const char* text;
        const char* says;
    };
    const Bad bad[] = {
        {"[game]\nlives = 3\n", "the game needs a ship"},
        {"[[body]]\nname = \"ship\"\nvertices = [[0.1, 0], [0.1, 200], [0.1, 100]]\n[game]\n", "counter-clockwise"},
        {"[[body]]\nname = \"ship\"\nvertices = [[0.9, 0], [0.1, 140], [0.1, 220]]\n[game]\n", "within 0.5"},
        {"[[body]]\nname = \"ship\"\nvertices = [[0.1, 0], [0.1, 140], [0.1, 220]]\n[game]\nsizes = [0.1, 0.2, 0.3]\n",
         "from the largest"},
        {"[[body]]\nname = \"ship\"\nvertices = [[0.1, 0], [0.1, 140], [0.1, 220]]\n[game]\nbullet_range = 7\n",
         "'bullet_range' must be from 0.1 to 6"},
        {"[[body]]\nname = \"ship\"\nvertices = [[0.1, 0], [0.1, 140], [0.1, 220]]\n[game]\nlevels = [2]\n", "'levels' must be"},
        {"[[body]]\nname = \"ship\"\nvertices = [[0.1, 0], [0.1, 140], [0.1, 220]]\n[game]\nbullet = 3\n", "unknown key 'bullet'"},
        {"game = 3\n[[body]]\nname = \"ship\"\nvertices = [[0.1, 0], [0.1, 140], [0.1, 220]]\n", "expected a [game] table"},
    };
    for (const Bad& b : bad) {
        SCOPED_TRACE(b.text);
        Scene out;
        SceneError err;
        EXPECT_FALSE(parse_scene(b.text, "bad.toml", out, err));
        EXPECT_NE(err.message.find(b.says), std::string::npos) << err.to_string();
        EXPECT_GT(err.line, 0);
    }
}

// backdrop = "earth": the Earth's lines (the earth scene's, built here on their own) are the
// scene's grid, and the game over them is the same game as without them, step for step: the
// asteroids are where they would be with no backdrop (the coastlines and graticule hit nothing).
TEST(Game, PlaysOverTheEarth) {
    const std::string path = std::string(NONEUCLID_SOURCE_DIR) + "/tests/files/data/earth_game.toml";
    Scene over, plain, earth;
    SceneError e;
    ASSERT_TRUE(load_scene_file(path, over, e)) << e.to_string();
    world::earth_scene(earth, 45, 10);
    ASSERT_GT(earth.bodies.size(), 100u);
    std::size_t grid = 0;
    for (const SceneBody& b : over.bodies) grid += b.grid;
    EXPECT_EQ(grid, earth.bodies.size());
    for (std::size_t i = 0; i < earth.bodies.size(); ++i) {  // the same lines, in the same places
        ASSERT_EQ(over.bodies[i].name, earth.bodies[i].name);
        ASSERT_EQ(over.bodies[i].vertices.size(), earth.bodies[i].vertices.size()) << i;
        EXPECT_EQ(over.bodies[i].vertices.back().rho, earth.bodies[i].vertices.back().rho) << i;
    }
    ASSERT_TRUE(parse_scene("curvature = 0\n[[body]]\nname = \"ship\"\n"
                            "vertices = [[0.12, 0.0], [0.08, 140.0], [0.08, 220.0]]\n[game]\n",
                            "plain.toml", plain, e))
        << e.to_string();
    World<double> a(over), b(plain);
    a.press(Action::fire), b.press(Action::fire);
    int moved = 0;
    for (int step = 0; step < 1200; ++step) {  // 20 s: the asteroids drift across many lines
        a.step(1.0 / 60), b.step(1.0 / 60);
        if (step == 0) a.release(Action::fire), b.release(Action::fire);
    }
    EXPECT_EQ(count(a, BodyKind::grid), static_cast<int>(earth.bodies.size()));
    EXPECT_EQ(count(a, BodyKind::asteroid), count(b, BodyKind::asteroid));
    EXPECT_EQ(a.game().lives, b.game().lives);
    std::vector<const Body<double>*> ra, rb;
    for (const auto& x : a.bodies)
        if (x.active && x.desc->kind() == BodyKind::asteroid) ra.push_back(&x);
    for (const auto& x : b.bodies)
        if (x.active && x.desc->kind() == BodyKind::asteroid) rb.push_back(&x);
    ASSERT_EQ(ra.size(), rb.size());
    ASSERT_GE(ra.size(), 4u);
    for (std::size_t i = 0; i < ra.size(); ++i) {
        EXPECT_NEAR(ra[i]->centre.r, rb[i]->centre.r, 1e-12) << i;
        EXPECT_NEAR(ra[i]->centre.theta, rb[i]->centre.theta, 1e-12) << i;
        moved += ra[i]->centre.r > 0.3;
    }
    EXPECT_GT(moved, 0);
}

// The dump names kinds and sizes, and reports the events of the step that led to each frame.
TEST(Game, DumpHasKindsScoreLivesLevelAndEvents) {
    World<double> w(game_scene(0));
    std::string line;
    dump_frame(w, {}, line);
    EXPECT_NE(line.find("\"phase\":\"ready\""), std::string::npos);
    EXPECT_NE(line.find("\"kind\":\"asteroid\",\"size\":0"), std::string::npos);
    EXPECT_NE(line.find("\"kind\":\"grid\""), std::string::npos);
    EXPECT_EQ(line.find("\"kind\":\"ship\""), std::string::npos) << "no ship before the game";
    w.press(Action::fire);
    w.step(1.0 / 60);
    line.clear();
    dump_frame(w, {}, line);
    EXPECT_NE(line.find("\"phase\":\"playing\",\"score\":0,\"lives\":3,\"level\":1,\"events\":[{\"start\":true}]"), std::string::npos) << line.substr(0, 200);
    EXPECT_NE(line.find("\"name\":\"ship\",\"kind\":\"ship\""), std::string::npos);
    Scene kiosk;
    ASSERT_TRUE(builtin_scene("kiosk", {}, kiosk));
    World<double> plain(kiosk);
    line.clear();
    dump_frame(plain, {}, line);
    EXPECT_EQ(line.find("\"score\""), std::string::npos) << "no game, no game fields";
}

}  // namespace
