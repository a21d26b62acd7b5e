// The 3D world's step (src/space/world.hpp) against the embedding (tests/space/embedding.hpp):
// a coasting body stays on one geodesic, its embedded points in one 2-plane through the origin of
// R⁴, and moves speed * dt a frame; after 10⁴ frames it is where the geodesic's closed form
// C_K(s) P + S_K(s) V puts it, facing the geodesic's tangent -K S_K(s) P + C_K(s) V (in S³ round
// and round through the antipode, where the limit sphere's wrap must continue the geodesic
// exactly); a spin brings the frame back after a turn; K turned while it flies.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "embedding.hpp"
#include "space/world.hpp"

namespace {
namespace space_world_test {

using namespace noneuclid;
using namespace space_embedding;

constexpr double kDt = 1.0 / 60;

// A world of one coasting body (no ship), at p facing f, at K with limit R.
space::World<double> coasting(double K, double R, const Point<double>& p, const space::Frame<double>& f, double speed) {
    space::Start<double> s;
    s.K = K, s.R = R;
    space::Body<double> b;
    b.at = p, b.frame = f, b.speed = speed;
    s.bodies.push_back(b);
    return space::World<double>(s);
}

space::Frame<double> random_frame(std::mt19937_64& rng) {
    std::normal_distribution<double> n;
    space::Frame<double> f;
    f.forward = space::unit(V3<double>{n(rng), n(rng), n(rng)});
    const V3<double> up{n(rng), n(rng), n(rng)};
    f.up = space::unit(up - space::dot(up, f.forward) * f.forward);
    f.right = space::cross(f.forward, f.up);
    return f;
}

// The part of X (as a plain vector of R⁴) outside the span of P and V.
LD off_plane(R4 P, R4 V, R4 X) {
    auto dot = [](R4 a, R4 b) { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; };
    const LD pp = dot(P, P), pv = dot(P, V), vv = dot(V, V), xp = dot(X, P), xv = dot(X, V);
    const LD det = pp * vv - pv * pv;
    const LD a = (xp * vv - xv * pv) / det, b = (xv * pp - xp * pv) / det;
    const R4 rest = X - (a * P + b * V);
    return std::sqrt(dot(rest, rest));
}

TEST(SpaceWorld, ACoastingBodyStaysOnItsGeodesicFor10000Frames) {
    std::mt19937_64 rng(20261207);
    for (const double K : {-1.0, -0.5, 0.5, 1.0}) {
        // In S³ fast, round the sphere through the antipode again and again (R = pi / sqrt K); in H³
        // slowly, within the limit.
        const double speed = K > 0 ? 0.3 : 0.012, R = K > 0 ? 3.14159265358979323846 / std::sqrt(K) : 3;
        const Point<double> p{0.4, space::unit(V3<double>{1, 2, -0.5})};
        const space::Frame<double> f = random_frame(rng);
        space::World<double> w = coasting(K, R, p, f, speed);
        const R4 P = embed(K, p), V = tangent(K, p, f.forward);
        R4 last = P;
        LD worst_plane = 0, worst_step = 0;
        for (int i = 1; i <= 10000; ++i) {
            w.step(kDt);
            const R4 X = embed(K, w.bodies[0].at);
            worst_plane = std::max(worst_plane, off_plane(P, V, X));
            worst_step = std::max(worst_step, std::fabs(near_distance(K, last, X) - speed * kDt));
            last = X;
        }
        const LD s = 10000 * speed * kDt;
        const R4 want = C(K, s) * P + S(K, s) * V, tangent_want = (-K * S(K, s)) * P + C(K, s) * V;
        const space::Body<double>& b = w.bodies[0];
        const LD at = near_distance(K, want, embed(K, b.at));
        const LD facing = gap(carried(K, embed(K, b.at), tangent_want), b.frame.forward);
        // (Rounding adds up over 10^4 steps: in S³, 50 units, eight times round through the antipode.)
        EXPECT_LT(worst_plane, 1e-8) << "K = " << K;
        EXPECT_LT(worst_step, 1e-12) << "K = " << K;
        EXPECT_LT(at, 1e-8) << "K = " << K;
        EXPECT_LT(facing, 1e-8) << "K = " << K;
        std::printf("K = %+.1f: 10^4 frames, %.2f along: off the plane %.1Le, a step off speed*dt by %.1Le, "
                    "%.1Le from the closed form, facing %.1Le off\n", K, static_cast<double>(s), worst_plane, worst_step, at,
                    facing);
    }
}

// Flat space: a straight line, 50 units in 10^4 frames (the walk's plane turns with the radial
// direction each frame: its rounding adds up to about 1e-8 there).
TEST(SpaceWorld, InFlatSpaceACoastingBodyGoesStraight) {
    std::mt19937_64 rng(7);
    const Point<double> p{0.4, space::unit(V3<double>{1, 2, -0.5})};
    const space::Frame<double> f = random_frame(rng);
    space::World<double> w = coasting(0, 100, p, f, 0.3);
    for (int i = 0; i < 10000; ++i) w.step(kDt);
    const V3<double> want = space::map_position(p) + (10000 * 0.3 * kDt) * f.forward;
    EXPECT_LT(space::norm(space::map_position(w.bodies[0].at) - want), 1e-7);
    EXPECT_LT(space::norm(w.bodies[0].frame.forward - f.forward), 1e-8);
}

// A spin of 0.5 rad/s turns the frame about its axis: after 4 pi seconds (one turn), as it was.
TEST(SpaceWorld, ASpinTurnsTheFrameRoundOnce) {
    space::Start<double> s;
    space::Body<double> b;
    b.at = {0.7, {0, 1, 0}}, b.spin = 0.5, b.spin_axis = space::unit(V3<double>{1, 1, 1});
    s.bodies.push_back(b);
    space::World<double> w(s);
    const long frames = std::lround(4 * 3.14159265358979323846 / kDt);
    for (long i = 0; i < frames / 2; ++i) w.step(kDt);
    EXPECT_GT(space::norm(w.bodies[0].frame.forward - b.frame.forward), 1.0);  // half a turn: turned away
    for (long i = frames / 2; i < frames; ++i) w.step(kDt);
    // (The frames' whole number of steps overshoots the turn by this angle: the vectors by as much.)
    const double over = 0.5 * std::fabs(frames * kDt - 4 * 3.14159265358979323846);
    EXPECT_LT(space::norm(w.bodies[0].frame.forward - b.frame.forward), over + 1e-9);
    EXPECT_LT(space::norm(w.bodies[0].frame.up - b.frame.up), over + 1e-9);
}

// The curvature keys turn K at the scene's rate within [-1, 1], the presets set it, reset restores
// the start.
TEST(SpaceWorld, TheCurvatureActionsTurnKWhileItFlies) {
    space::Start<double> s;
    s.K = 0, s.curvature_rate = 0.5;
    space::Body<double> b;
    b.speed = 0.2;
    s.bodies.push_back(b);
    space::World<double> w(s);
    w.press(world::Action::curvature_up);
    for (int i = 0; i < 60; ++i) w.step(kDt);
    EXPECT_NEAR(w.K, 0.5, 1e-12);
    for (int i = 0; i < 120; ++i) w.step(kDt);
    EXPECT_EQ(w.K, 1.0);  // clamped
    w.release(world::Action::curvature_up);
    w.press(world::Action::hyperbolic);
    EXPECT_EQ(w.K, -1.0);
    w.press(world::Action::reset);
    EXPECT_EQ(w.K, 0.0);
    EXPECT_EQ(w.bodies[0].at.r, 0.0);
}

}  // namespace space_world_test
}  // namespace
