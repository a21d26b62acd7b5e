// The three-dimensional world (src/space) as a kind behind the session (kinds/space.hpp): the
// `space` scene's dump, two seconds on at K = -1, 0, +1, against the geodesics of its start in
// the tests' own embedding (tests/space/embedding.hpp, long double): each body's "r" and "dir"
// where C_K(s) P + S_K(s) V puts it, its "facing" the start's turned by its spin and carried
// along; and the session's two views, P switching them, the map's bodies all inside the limit
// sphere's outline.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "../space/embedding.hpp"
#include "app/options.hpp"
#include "app/recorder.hpp"
#include "app/session.hpp"
#include "app/setup.hpp"
#include "render/font.hpp"
#include "space/scene_world.hpp"

namespace noneuclid {
namespace {

using namespace space_embedding;

struct Dumped {
    char kind[16] = {}, solid[16] = {};
    double r = 0, dir[3] = {}, facing[3] = {}, speed = 0;
};

// The bodies of one dump line, read field by field as a script would.
std::vector<Dumped> read_bodies(const std::string& line, double& t, double& K) {
    std::vector<Dumped> out;
    EXPECT_EQ(std::sscanf(line.c_str(), "{\"frame\":%*d,\"t\":%lf,\"K\":%lf,\"kind\":\"space\"", &t, &K), 2) << line;
    for (std::size_t at = line.find("{\"kind\":"); at != std::string::npos; at = line.find("{\"kind\":", at + 1)) {
        Dumped d;
        const int n = std::sscanf(line.c_str() + at,
                                  "{\"kind\":\"%15[a-z]\",\"solid\":\"%15[a-z]\",\"r\":%lf,\"dir\":[%lf,%lf,%lf],"
                                  "\"facing\":[%lf,%lf,%lf],\"speed\":%lf}",
                                  d.kind, d.solid, &d.r, &d.dir[0], &d.dir[1], &d.dir[2], &d.facing[0], &d.facing[1],
                                  &d.facing[2], &d.speed);
        EXPECT_EQ(n, 10) << line.substr(at, 200);
        out.push_back(d);
    }
    return out;
}

std::unique_ptr<app::Session> space_session(const std::string& name = "space", const char* engine = "fixed") {
    app::Options o = app::defaults(app::Command::render);
    o.scene = name;
    o.engine = app::engine_value("--engine", engine);
    const world::Scene scene = app::load_scene(o);
    const kinds::KindChoice kind = app::world_kind(o, scene);
    return app::make_session(kind, scene, app::session_options(o, scene, o.legend, kind), render::builtin_font(), nullptr);
}

TEST(SpaceSession, TheDumpIsTheGeodesicsOfTheStart) {
    world::Scene scene;
    ASSERT_TRUE(world::builtin_scene("space", {}, scene));
    const space::Start<double> start = space::space_start(scene);
    ASSERT_EQ(start.bodies.size(), 13u);  // the ship and a dozen
    // (The fixed engine holds the start in Q16.16, 2^-16 apart, and walks in it.)
    for (const auto& [engine, within] : {std::pair{"double", 1e-7}, std::pair{"fixed", 5e-4}})
    for (const world::Action preset : {world::Action::hyperbolic, world::Action::flat, world::Action::spherical}) {
        const auto s = space_session("space", engine);
        app::ScriptPlayer none;
        s->start(none);
        s->queue({preset, true}), s->queue({preset, false});
        for (int f = 0; f < 120; ++f) s->advance(none);  // (2 s: every body still inside the limit)
        std::string line;
        s->dump(800, 480, line);
        double t = 0, K = 0;
        const std::vector<Dumped> got = read_bodies(line, t, K);
        ASSERT_EQ(got.size(), start.bodies.size());
        EXPECT_NEAR(t, 2.0, 1e-9);
        EXPECT_STREQ(got[0].kind, "ship");
        LD worst_at = 0, worst_facing = 0;
        for (std::size_t i = 1; i < got.size(); ++i) {
            const space::Body<double>& b = start.bodies[i];
            const Dumped& d = got[i];
            EXPECT_STREQ(d.kind, "body");
            EXPECT_STREQ(d.solid, space::kSolids[b.solid].name);
            EXPECT_NEAR(std::hypot(d.dir[0], std::hypot(d.dir[1], d.dir[2])), 1.0, within / 10);
            EXPECT_NEAR(std::hypot(d.facing[0], std::hypot(d.facing[1], d.facing[2])), 1.0, within / 10);
            const LD dist = b.speed * t;
            const V3<double> axis =
                space::unit(b.spin_axis.x * b.frame.forward + b.spin_axis.z * b.frame.up - b.spin_axis.y * b.frame.right);
            const V3<double> turned = space::turned(b.frame.forward, axis, b.spin * t);
            const Point<double> at{d.r, {d.dir[0], d.dir[1], d.dir[2]}};
            const V3<double> facing{d.facing[0], d.facing[1], d.facing[2]};
            if (K == 0) {  // straight lines, and a carried vector is a vector
                const V3<double> want = space::map_position(b.at) + static_cast<double>(dist) * b.travel;
                worst_at = std::max<LD>(worst_at, space::norm(space::map_position(at) - want));
                worst_facing = std::max<LD>(worst_facing, space::norm(facing - turned));
                continue;
            }
            const R4 P = embed(K, b.at), V = tangent(K, b.at, b.travel);
            const R4 along = (-K * S(K, dist)) * P + C(K, dist) * V;
            worst_at = std::max(worst_at, near_distance(K, C(K, dist) * P + S(K, dist) * V, embed(K, at)));
            const R4 X = tangent(K, b.at, turned);  // the part along the travel follows the tangent
            const LD a = g(K, X, V);
            worst_facing = std::max(worst_facing, gap(carried(K, embed(K, at), (X - a * V) + a * along), facing));
        }
        // (The dump's 9 significant digits and the step's rounding.)
        EXPECT_LT(worst_at, within) << engine << ", K = " << K;
        EXPECT_LT(worst_facing, within) << engine << ", K = " << K;
        std::printf("%s, K = %+.0f: 12 bodies after 2 s, %.1Le from their geodesics, facings %.1Le off\n", engine, K,
                    worst_at, worst_facing);
    }
}

// Both views at K = -1, 0, +1: the inhabitant's view (the default) shows the bodies ahead and the
// grid, to the disc's rim; P gives the map, where everything lies inside the limit sphere's
// outline, a circle 80% of the disc across; P again, the inhabitant's view. Nothing is drawn
// outside the disc, which is shaded as the 2D world's outside is.
TEST(SpaceSession, BothViewsDrawAndTheMapHoldsTheWorldInItsBall) {
    const int W = 800, H = 480;
    std::vector<uint32_t> px(static_cast<std::size_t>(W) * H);
    const render::PixelFormat fmt = render::PixelFormat::xrgb8888();
    const render::Canvas c(px.data(), W, H, W * 4, fmt);
    // (The fixed engine holds the start in Q16.16, 2^-16 apart, and walks in it.)
    for (const auto& [engine, within] : {std::pair{"double", 1e-7}, std::pair{"fixed", 5e-4}})
    for (const world::Action preset : {world::Action::hyperbolic, world::Action::flat, world::Action::spherical}) {
        const auto s = space_session("space", engine);
        app::ScriptPlayer none;
        s->start(none);
        s->queue({preset, true}), s->queue({preset, false});
        for (int f = 0; f < 30; ++f) s->advance(none);
        const geo::Projection first = s->options().draw.projection;
        const uint32_t background = fmt.pack(s->options().draw.background), outside = fmt.pack(s->options().draw.outside);
        for (int view = 0; view < 3; ++view) {
            s->draw_world(c);
            int lit = 0, outside_ball = 0, outside_disc = 0;
            const double disc = s->layout(W, H).disc / 2.0, ball = 0.8 * disc;  // (the map's outline)
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) {
                    const double r = std::hypot(x + 0.5 - W / 2.0, y + 0.5 - H / 2.0);
                    if (c.get_word(x, y) == background) continue;
                    if (c.get_word(x, y) == outside) {
                        EXPECT_GT(r, (view == 1 ? ball : disc) - 1);  // (the shade: only outside the disc, or the ball)
                        continue;
                    }
                    ++lit;
                    if (r > ball + 2.5 && r < disc - 2.5) ++outside_ball;
                    if (r > disc + 2.5) ++outside_disc;
                }
            EXPECT_EQ(outside_disc, 0);
            SCOPED_TRACE("K preset " + std::to_string(static_cast<int>(preset)) + ", view " + std::to_string(view));
            EXPECT_GT(lit, 2000);  // the grid and the bodies
            if (view == 1) {
                EXPECT_NE(s->options().draw.projection, first);
                EXPECT_EQ(outside_ball, 0);
            } else {
                EXPECT_EQ(s->options().draw.projection, first);
                EXPECT_GT(outside_ball, 200);  // the inhabitant's view fills the disc
            }
            s->queue({world::Action::projection, true}), s->queue({world::Action::projection, false});
            s->advance(none);
        }
    }
}

// A scene file's own solid (tests/files/data/solids.toml): each vertex where the file puts it in
// the solid's frame — at its length from the centre, and at the flat angle from every other as
// seen from the centre (the exponential map keeps both), measured in the embedding at the file's
// K = -0.5; the dump names it and its centre coasts along its geodesic.
TEST(SpaceSession, AScenesOwnSolidIsPlacedAsItsFileSays) {
    app::Options o = app::defaults(app::Command::render);
    o.scene = NONEUCLID_SOURCE_DIR "/tests/files/data/solids.toml";
    const world::Scene scene = app::load_scene(o);
    ASSERT_TRUE(scene.space);
    space::SceneWorld w(scene);
    const space::Body<double>& prism = w.bodies[1];
    const space::Solid& shape = w.solid(prism);
    EXPECT_STREQ(shape.name, "prism");
    ASSERT_EQ(shape.vertex_count, 6);
    const LD K = w.K;
    const R4 centre = embed(K, prism.at);
    LD worst_length = 0, worst_angle = 0;
    for (int i = 0; i < 6; ++i) {
        const auto& v = scene.solids[0].vertices[static_cast<std::size_t>(i)];
        const R4 p = embed(K, space::vertex_of(w.K, prism.at, prism.frame, shape, i, prism.size));
        worst_length = std::max(worst_length, std::fabs(ref_distance(K, centre, p) - std::hypot(v[0], std::hypot(v[1], v[2]))));
        for (int j = 0; j < i; ++j) {
            const auto& u = scene.solids[0].vertices[static_cast<std::size_t>(j)];
            const R4 q = embed(K, space::vertex_of(w.K, prism.at, prism.frame, shape, j, prism.size));
            // (the angle at the centre between the geodesics to p and q: their tangents there)
            const R4 tp = p - form(K, centre, p) * centre, tq = q - form(K, centre, q) * centre;
            const LD seen = std::acos(g(K, tp, tq) / std::sqrt(g(K, tp, tp) * g(K, tq, tq)));
            const LD flat = std::acos((v[0] * u[0] + v[1] * u[1] + v[2] * u[2]) /
                                      (std::hypot(v[0], std::hypot(v[1], v[2])) * std::hypot(u[0], std::hypot(u[1], u[2]))));
            worst_angle = std::max(worst_angle, std::fabs(seen - flat));
        }
    }
    EXPECT_LT(worst_length, 1e-12);
    EXPECT_LT(worst_angle, 1e-9);
    EXPECT_EQ(shape.edge_count, 9);
    const auto s = space_session(o.scene, "double");
    app::ScriptPlayer none;
    s->start(none);
    for (int f = 0; f < 120; ++f) s->advance(none);
    std::string line;
    s->dump(800, 480, line);
    double t = 0, dK = 0;
    const std::vector<Dumped> got = read_bodies(line, t, dK);
    ASSERT_EQ(got.size(), 3u);
    EXPECT_STREQ(got[1].solid, "prism");
    EXPECT_STREQ(got[2].solid, "cube");
    const LD dist = prism.speed * t;
    const R4 want = C(K, dist) * centre + S(K, dist) * tangent(K, prism.at, prism.travel);
    EXPECT_LT(near_distance(K, want, embed(K, Point<double>{got[1].r, {got[1].dir[0], got[1].dir[1], got[1].dir[2]}})), 1e-7);
}

// Attract mode in the 3D world: after a second with no input the autopilot flies a tour — it
// thrusts to cruising speed, turns every 5 s and sweeps K — and, there being no instrument,
// neither turns one on nor drops marks (its recording has no instrument or fire).
TEST(SpaceSession, AttractModeFliesATour) {
    world::Scene scene;
    ASSERT_TRUE(world::builtin_scene("space", {}, scene));
    app::SessionOptions so;
    so.attract = {1, 10, 0.25};
    kinds::KindChoice kind;
    std::string why;
    ASSERT_TRUE(kinds::choose_kind(scene, nullptr, kind, why)) << why;
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    app::Recorder rec(f);
    const auto s = app::make_session(kind, scene, so, render::builtin_font(), &rec);
    app::ScriptPlayer none;
    s->start(none);
    std::string line;
    double t = 0, K = 0, least = 0, most = 0;
    for (int i = 0; i < 60 * 12; ++i) {
        s->advance(none);
        s->dump(800, 480, line);
        read_bodies(line, t, K);
        least = std::min(least, K), most = std::max(most, K);
    }
    EXPECT_TRUE(s->attract());
    const std::vector<Dumped> got = read_bodies(line, t, K);
    ASSERT_FALSE(got.empty());
    EXPECT_GT(most - least, 1.0);  // (0.2 a second for 11 s: up to +1, then back down past 0)
    EXPECT_GT(got[0].speed, 0.2);                 // cruising
    EXPECT_LT(got[0].facing[0], 0.999);           // turned from where it started (nearly +x)
    std::rewind(f);
    std::string text;
    for (int c; (c = std::fgetc(f)) != EOF;) text += static_cast<char>(c);
    std::fclose(f);
    EXPECT_NE(text.find("press thrust"), std::string::npos) << text.substr(0, 400);
    EXPECT_NE(text.find("press left"), std::string::npos);
    EXPECT_EQ(text.find("instrument"), std::string::npos);
    EXPECT_EQ(text.find("fire"), std::string::npos);
}

}  // namespace
}  // namespace noneuclid
