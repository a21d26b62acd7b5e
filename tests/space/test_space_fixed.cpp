// The 3D world on the fixed engine (Q16.16: src/space/world.hpp on fx::fixed) against the
// embedding (tests/space/embedding.hpp) in long double: after 10⁴ frames a coasting body is where
// the geodesic's closed form C_K(s) P + S_K(s) V puts it, facing its tangent, at K = -1, -0.5, 0,
// 0.5, 1; while K sweeps and the ship thrusts, every body stays near the double engine's. The
// coast (each frame walked from where the body's geodesic began) keeps the roundings from adding
// up over the frames.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <random>

#include "embedding.hpp"
#include "fixed/fixed.hpp"
#include "space/scene_world.hpp"
#include "world/scene.hpp"

namespace {
namespace space_fixed_test {

using namespace noneuclid;
using namespace space_embedding;
using fx::fixed;

constexpr double kDt = 1.0 / 60;

Point<double> in_double(const space::Point<fixed>& p) {
    return {static_cast<double>(p.r), {static_cast<double>(p.u.x), static_cast<double>(p.u.y), static_cast<double>(p.u.z)}};
}
V3<double> in_double(const V3<fixed>& v) { return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)}; }

// The distance between two embedded points at any K (flat: their spatial parts).
LD apart(LD K, R4 P, R4 Q) {
    if (K != 0) return near_distance(K, P, Q);
    return std::sqrt((P.x - Q.x) * (P.x - Q.x) + (P.y - Q.y) * (P.y - Q.y) + (P.z - Q.z) * (P.z - Q.z));
}

TEST(SpaceFixed, ACoastingBodyIsWhereItsGeodesicPutsItAfter10000Frames) {
    std::mt19937_64 rng(20261208);
    std::normal_distribution<double> n;
    LD worst_at = 0, worst_facing = 0;
    for (const double K : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
        // (In S³ round and round through the antipode; elsewhere within the limit.)
        const double speed = K > 0 ? 0.3 : 0.012, R = K > 0 ? 3.14159265358979323846 / std::sqrt(K) : 3;
        const Point<double> p{0.4, space::unit(V3<double>{1, 2, -0.5})};
        space::Frame<double> f;
        f.forward = space::unit(V3<double>{n(rng), n(rng), n(rng)});
        const V3<double> up{n(rng), n(rng), n(rng)};
        f.up = space::unit(up - space::dot(up, f.forward) * f.forward);
        f.right = space::cross(f.forward, f.up);
        space::Start<double> s;
        s.K = K, s.R = R;
        space::Body<double> b;
        b.at = p, b.frame = f, b.travel = f.forward, b.speed = speed;
        s.bodies.push_back(b);
        space::World<fixed> w(space::start_in<fixed>(s));
        for (int i = 0; i < 10000; ++i) w.step(kDt);
        // (The start as the fixed engine holds it: the closed form from the same numbers.)
        const space::Body<fixed>& start = w.start().bodies[0];
        const Point<double> p0 = in_double(start.at);
        const R4 P = embed(K, p0), V = tangent(K, p0, space::unit(in_double(start.travel)));
        const LD d = 10000 * static_cast<LD>(static_cast<double>(start.speed)) * kDt;  // (its speed in Q16.16: 0.012 is 0.0119934)
        const R4 want = C(K, d) * P + S(K, d) * V, tangent_want = (-K * S(K, d)) * P + C(K, d) * V;
        const Point<double> at = in_double(w.bodies[0].at);
        const LD off = apart(K, want, embed(K, at));
        const LD facing = gap(carried(K == 0 ? 1e-30L : K, embed(K, at), tangent_want), in_double(w.bodies[0].frame.forward));
        // (5e-4 of a unit: an eighth of a pixel at a unit's distance in the inhabitant's view.)
        EXPECT_LT(off, 5e-4) << "K = " << K;
        EXPECT_LT(facing, 5e-4) << "K = " << K;
        worst_at = std::max(worst_at, off), worst_facing = std::max(worst_facing, facing);
        std::printf("fixed, K = %+.1f: 10^4 frames, %.2f along: %.1Le from the closed form, facing %.1Le off\n", K,
                    static_cast<double>(d), off, facing);
    }
    RecordProperty("worst_position", std::to_string(static_cast<double>(worst_at)));
    RecordProperty("worst_facing", std::to_string(static_cast<double>(worst_facing)));
}

// The space scene on both engines while K sweeps its whole range, from +1 to -1 and back (8 s
// at the scene's rate), the ship thrusting for the first 4 s: every body within `bound` of the
// double engine's (away from the limit sphere, where one engine may wrap it a frame before the
// other), and the ship's speed near the double one's. While K turns, every body starts a new coast each
// frame (the paper's rule: K changes, the bodies' places stay), so the frames' roundings, about
// 2^-16 each, add up while it turns (docs/space.md gives the figures); at a constant K they do not.
TEST(SpaceFixed, TheSpaceSceneFollowsTheDoubleEngineWhileKSweeps) {
    world::Scene scene;
    ASSERT_TRUE(world::builtin_scene("space", {}, scene));
    scene.curvature = 1;
    space::SceneWorldOf<fixed> f(scene);
    space::SceneWorldOf<double> d(scene);
    double worst = 0, worst_speed = 0;
    for (int i = 0; i < 480; ++i) {
        const auto act = [&](auto& w) {
            w.release(world::Action::curvature_up), w.release(world::Action::curvature_down), w.release(world::Action::thrust);
            w.press(i < 240 ? world::Action::curvature_down : world::Action::curvature_up);
            if (i < 240) w.press(world::Action::thrust);
            w.step(kDt);
        };
        act(f), act(d);
        // (K in Q16.16: each frame's change rounded to 2^-16, so the sweeps differ by a few steps.)
        ASSERT_NEAR(static_cast<double>(f.K), d.K, 2e-3) << "frame " << i;
        const LD K = d.K;
        const double near_rim = static_cast<double>(d.limit()) - 0.05;
        for (std::size_t b = 1; b < d.bodies.size(); ++b) {  // (the ship: its speed)
            const Point<double> a = in_double(f.bodies[b].at);
            if (a.r > near_rim || d.bodies[b].at.r > near_rim) continue;
            worst = std::max(worst, static_cast<double>(apart(K, embed(K, a), embed(K, d.bodies[b].at))));
        }
        worst_speed = std::max(worst_speed, std::fabs(static_cast<double>(f.bodies[0].speed) / d.bodies[0].speed - 1));
    }
    // (Measured 0.047 and 4.3%: the bounds guard those figures, which docs/space.md states; the
    // double engine is the reference, and the fixed one is not yet as close while K turns as the
    // plane's, whose coast keeps finer numbers than Q16.16.)
    EXPECT_LT(worst, 0.06);
    EXPECT_LT(worst_speed, 0.06);
    RecordProperty("worst_sweep", std::to_string(worst));
    std::printf("fixed against double, K from +1 to -1 and back in 8 s: worst body %.2e apart, the ship's speed %.2e off\n",
                worst, worst_speed);
}

}  // namespace space_fixed_test
}  // namespace
