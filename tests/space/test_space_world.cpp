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
#include <tuple>

#include "embedding.hpp"
#include "fixed/fixed.hpp"
#include "space/scene_world.hpp"
#include "space/view.hpp"
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
    b.at = p, b.frame = f, b.travel = f.forward, b.speed = speed;
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

// A body that spins while it coasts: its travel and its frame are carried apart, so it still
// keeps to one geodesic, and its frame is the start's turned by spin * t about its own axis and
// carried along (in the embedding: the part across the geodesic's 2-plane kept, the part along
// the tangent following the tangent), after 10^4 frames.
TEST(SpaceWorld, ASpinningBodyStillCoastsAlongItsGeodesic) {
    std::mt19937_64 rng(11);
    for (const double K : {-1.0, 0.0, 1.0}) {
        const Point<double> p{0.5, space::unit(V3<double>{-1, 0.5, 2})};
        const space::Frame<double> f = random_frame(rng);
        space::Start<double> s;
        s.K = K, s.R = K > 0 ? 3.14159265358979323846 / std::sqrt(K) : 100;
        space::Body<double> b;
        b.at = p, b.frame = f, b.speed = K < 0 ? 0.012 : 0.2;
        b.travel = space::unit(V3<double>{0.3, -1, 0.4}), b.spin = 0.7, b.spin_axis = space::unit(V3<double>{1, -2, 0.5});
        s.bodies.push_back(b);
        space::World<double> w(s);
        for (int i = 0; i < 10000; ++i) w.step(kDt);
        const space::Body<double>& e = w.bodies[0];
        const LD t = 10000 * kDt, dist = b.speed * t;
        if (K == 0) {  // straight, and the frame turned only
            const V3<double> want = space::map_position(p) + static_cast<double>(dist) * b.travel;
            EXPECT_LT(space::norm(space::map_position(e.at) - want), 1e-7);
            continue;
        }
        const R4 P = embed(K, p), V = tangent(K, p, b.travel);
        const R4 at = C(K, dist) * P + S(K, dist) * V, along = (-K * S(K, dist)) * P + C(K, dist) * V;
        EXPECT_LT(near_distance(K, at, embed(K, e.at)), 1e-8) << "K = " << K;
        EXPECT_LT(gap(carried(K, embed(K, e.at), along), e.travel), 1e-8) << "K = " << K;
        // The frame: the spin's rotation (about the body's axis, in the start's carried
        // coordinates), then carried.
        const V3<double> axis = space::unit(b.spin_axis.x * f.forward + b.spin_axis.z * f.up - b.spin_axis.y * f.right);
        const double turn = static_cast<double>(0.7L * t);
        for (int k = 0; k < 2; ++k) {
            const V3<double> v0 = space::turned(k ? f.up : f.forward, axis, turn);
            const R4 X = tangent(K, p, v0);
            const LD a = g(K, X, V);
            const R4 moved = (X - a * V) + a * along;
            EXPECT_LT(gap(carried(K, embed(K, e.at), moved), k ? e.frame.up : e.frame.forward), 1e-7) << "K = " << K;
        }
    }
}

// The ship's turns, each about one of its own axes by turn_rate a second: yaw left turns forward
// toward its left (-right), pitch up toward its up, roll right tips its up toward its right;
// held together, the frame stays orthonormal. Turning leaves the velocity as it was (the 2D rule).
TEST(SpaceWorld, TheShipYawsPitchesAndRollsAboutItsOwnAxes) {
    using world::Action;
    struct Turn {
        Action action;
        V3<double> forward, up;  // after a quarter turn from forward x, up z
    };
    const Turn turns[] = {{Action::left, {0, 1, 0}, {0, 0, 1}},   {Action::right, {0, -1, 0}, {0, 0, 1}},
                          {Action::pitch_up, {0, 0, 1}, {-1, 0, 0}}, {Action::pitch_down, {0, 0, -1}, {1, 0, 0}},
                          {Action::roll_right, {1, 0, 0}, {0, -1, 0}}, {Action::roll_left, {1, 0, 0}, {0, 1, 0}}};
    for (const Turn& t : turns) {
        space::Start<double> s;
        s.turn_rate = 3.14159265358979323846 / 2 / (90 * kDt);  // a quarter turn in 90 frames
        space::Body<double> ship;
        ship.ship = true, ship.speed = 0.1, ship.at = {0.5, {0, 1, 0}};
        s.bodies.push_back(ship);
        space::World<double> w(s);
        w.press(t.action);
        for (int i = 0; i < 90; ++i) w.step(kDt);
        const space::Body<double>& b = w.bodies[0];
        EXPECT_LT(space::norm(b.frame.forward - t.forward), 1e-12) << world::action_name(t.action);
        EXPECT_LT(space::norm(b.frame.up - t.up), 1e-12) << world::action_name(t.action);
        EXPECT_LT(space::norm(b.travel - V3<double>{1, 0, 0}), 1e-9) << world::action_name(t.action);  // (flat K: kept)
    }
    space::Start<double> s;
    space::Body<double> ship;
    ship.ship = true;
    s.bodies.push_back(ship);
    space::World<double> w(s);
    for (Action a : {Action::left, Action::pitch_up, Action::roll_right, Action::thrust}) w.press(a);
    for (int i = 0; i < 6000; ++i) w.step(kDt);
    const space::Frame<double>& f = w.bodies[0].frame;
    EXPECT_NEAR(space::norm(f.forward), 1, 1e-12);
    EXPECT_NEAR(space::dot(f.forward, f.up), 0, 1e-12);
    EXPECT_LT(space::norm(space::cross(f.forward, f.up) - f.right), 1e-12);
    EXPECT_NEAR(w.bodies[0].speed, s.max_speed, 1e-12);  // thrust stops at the top speed
}

// The kiosk's shift: fire held, left and right roll and the curvature buttons pitch; K stays.
TEST(SpaceWorld, WithFireHeldTheKiosksButtonsRollAndPitch) {
    using world::Action;
    for (const auto& [button, forward, up] :
         {std::tuple{Action::left, V3<double>{1, 0, 0}, V3<double>{0, 1, 0}}, {Action::right, {1, 0, 0}, {0, -1, 0}},
          {Action::curvature_up, {0, 0, 1}, {-1, 0, 0}}, {Action::curvature_down, {0, 0, -1}, {1, 0, 0}}}) {
        space::Start<double> s;
        s.K = 0.25, s.turn_rate = 3.14159265358979323846 / 2 / (90 * kDt);
        space::Body<double> ship;
        ship.ship = true;
        s.bodies.push_back(ship);
        space::World<double> w(s);
        w.press(Action::fire), w.press(button);
        for (int i = 0; i < 90; ++i) w.step(kDt);
        EXPECT_LT(space::norm(w.bodies[0].frame.forward - forward), 1e-12) << world::action_name(button);
        EXPECT_LT(space::norm(w.bodies[0].frame.up - up), 1e-12) << world::action_name(button);
        EXPECT_EQ(w.K, 0.25) << world::action_name(button);
        w.release(Action::fire);  // (and without the shift, the button is itself again: K, or a yaw)
        const V3<double> before = w.bodies[0].frame.forward;
        w.step(kDt);
        if (button == Action::curvature_up || button == Action::curvature_down)
            EXPECT_NE(w.K, 0.25) << world::action_name(button);
        else
            EXPECT_GT(space::norm(w.bodies[0].frame.forward - before), 0.01) << world::action_name(button);
    }
}

// A body far out when the limit shrinks under it (K > 0: the limit is pi / sqrt K): it settles
// on the same point of S³, read within the limit, however many times round that is.
TEST(SpaceWorld, ABodyPastTheAntipodeSettlesOnTheSamePoint) {
    for (const double r : {3.5, 10.0, 40.0}) {
        space::Start<double> s;
        s.K = 1, s.R = 50;
        space::Body<double> b;
        b.at = {r, space::unit(V3<double>{0.3, -1, 0.2})};
        s.bodies.push_back(b);
        space::World<double> w(s);
        w.step(kDt);
        EXPECT_LE(w.bodies[0].at.r, 3.14159265358979323846) << r;
        EXPECT_GE(w.bodies[0].at.r, 0.0) << r;
        EXPECT_LT(near_distance(1, embed(1, b.at), embed(1, w.bodies[0].at)), 1e-12) << r;
    }
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

// While K sweeps (curvature down from +1 to -1, then up, 8 s), a coasting body follows the
// paper's rule: each frame, at that frame's K, its place and direction of travel kept and then
// walked speed * dt along the geodesic. The reference does the same frame by frame in the
// embedding, in long double: C_K(s) P + S_K(s) V and its tangent, carried back.
struct Reference {
    LD r;
    V3<LD> u, travel;
};
Reference reference_step(LD K, const Reference& b, LD s) {
    if (K == 0) {  // (flat: a straight line)
        const V3<LD> x{b.r * b.u.x + s * b.travel.x, b.r * b.u.y + s * b.travel.y, b.r * b.u.z + s * b.travel.z};
        const LD n = std::sqrt(x.x * x.x + x.y * x.y + x.z * x.z);
        return {n, {x.x / n, x.y / n, x.z / n}, b.travel};
    }
    const R4 P{C(K, b.r), S(K, b.r) * b.u.x, S(K, b.r) * b.u.y, S(K, b.r) * b.u.z};
    // (the carried travel as a tangent, in long double: tangent() takes doubles)
    const LD a = b.travel.x * b.u.x + b.travel.y * b.u.y + b.travel.z * b.u.z;
    const R4 radial{-K * S(K, b.r), C(K, b.r) * b.u.x, C(K, b.r) * b.u.y, C(K, b.r) * b.u.z};
    const R4 V = a * radial + R4{0, b.travel.x - a * b.u.x, b.travel.y - a * b.u.y, b.travel.z - a * b.u.z};
    const R4 Q = C(K, s) * P + S(K, s) * V, T = (-K * S(K, s)) * P + C(K, s) * V;
    const LD sq = std::sqrt(Q.x * Q.x + Q.y * Q.y + Q.z * Q.z);
    const LD r = K > 0 ? std::atan2(std::sqrt(K) * sq, Q.w) / std::sqrt(K) : std::atanh(std::sqrt(-K) * sq / Q.w) / std::sqrt(-K);
    return {r, {Q.x / sq, Q.y / sq, Q.z / sq}, carried(K, Q, T)};
}

// The sweep on engine T: the body's worst distance from the rule's reference (map coordinates).
template <class T>
LD sweep_off_the_rule() {
    space::Start<double> s;
    s.K = 1, s.R = 3, s.curvature_rate = 0.5;
    space::Body<double> b;
    b.at = {0.5, space::unit(V3<double>{1, -0.4, 0.3})};
    b.travel = space::unit(V3<double>{-0.2, 1, 0.5}), b.frame.forward = b.travel, b.speed = 0.2;
    s.bodies.push_back(b);
    space::World<T> w(space::start_in<T>(s));
    const auto ld = [](T v) { return static_cast<LD>(static_cast<double>(v)); };
    const space::Body<T>& b0 = w.bodies[0];
    Reference ref{ld(b0.at.r), {ld(b0.at.u.x), ld(b0.at.u.y), ld(b0.at.u.z)}, {ld(b0.travel.x), ld(b0.travel.y), ld(b0.travel.z)}};
    const LD n = std::sqrt(ref.u.x * ref.u.x + ref.u.y * ref.u.y + ref.u.z * ref.u.z);
    const LD m = std::sqrt(ref.travel.x * ref.travel.x + ref.travel.y * ref.travel.y + ref.travel.z * ref.travel.z);
    ref.u = {ref.u.x / n, ref.u.y / n, ref.u.z / n}, ref.travel = {ref.travel.x / m, ref.travel.y / m, ref.travel.z / m};
    LD worst = 0;
    for (int i = 0; i < 480; ++i) {
        w.release(world::Action::curvature_up), w.release(world::Action::curvature_down);
        w.press(i < 240 ? world::Action::curvature_down : world::Action::curvature_up);
        w.step(kDt);
        ref = reference_step(ld(w.K), ref, ld(b0.speed) * static_cast<LD>(kDt));
        const space::Point<T>& at = w.bodies[0].at;
        const LD r = ld(at.r), dx = r * ld(at.u.x) - ref.r * ref.u.x, dy = r * ld(at.u.y) - ref.r * ref.u.y,
                 dz = r * ld(at.u.z) - ref.r * ref.u.z;
        worst = std::max(worst, std::sqrt(dx * dx + dy * dy + dz * dz));  // (in the map's coordinates: K-free)
    }
    return worst;
}

TEST(SpaceWorld, WhileKSweepsABodyFollowsTheRuleInTheEmbedding) {
    const LD d = sweep_off_the_rule<double>(), f = sweep_off_the_rule<fx::fixed>();
    EXPECT_LT(d, 1e-10);
    // (The fixed engine: a new coast each frame while K turns, and each frame's walk turns the
    // direction of travel by up to 8e-5 of rounding, about five steps of 2^-16: measured 0.124
    // after the body's 1.6 units. The bound guards that figure, which docs/space.md states.)
    EXPECT_LT(f, 0.2);
    RecordProperty("sweep_double", std::to_string(static_cast<double>(d)));
    RecordProperty("sweep_fixed", std::to_string(static_cast<double>(f)));
    std::printf("K swept +1 to -1 and back in 8 s: the body within %.1Le (double), %.1Le (fixed) of the rule in the "
                "embedding\n", d, f);
}
}  // namespace space_world_test
}  // namespace
