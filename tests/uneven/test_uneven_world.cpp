// The uneven world as it runs (src/uneven/world.hpp, draw.hpp, dump.hpp): without bumps it
// follows the world of constant K's double engine; its speed holds over a million steps among
// bumps; the dump's chart points agree with a second, independent integrator; the chart view
// without bumps draws the constant-K world's stereographic picture; the lens is seen twice from
// O; the fan behind the inhabitant's view follows the exponential map; [[bump]] tables and
// their refusals; the strength keys.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "app/session.hpp"
#include "files/scene_file.hpp"
#include "test_common.hpp"
#include "uneven/draw.hpp"
#include "uneven/dump.hpp"
#include "world/world.hpp"

namespace {
namespace uneven_world_test {

using namespace noneuclid;
using uneven::Vec2;

constexpr double kPi = test::kPi, kDeg = kPi / 180;

world::SceneBody square(const char* name, double r, double theta, double speed, double dir, double spin) {
    world::SceneBody b;
    b.name = name;
    for (int i = 0; i < 4; ++i) b.vertices.push_back({0.15, 45 + 90.0 * i});
    b.r = r, b.theta_deg = theta, b.speed = speed, b.direction_deg = dir, b.facing_deg = 10, b.spin_deg = spin;
    return b;
}

// A scene of moving bodies, the ship first, at K with a limit inside the uneven world's chart.
world::Scene moving_scene(double K) {
    world::Scene s;
    s.curvature = K;
    s.limit_radius = K > 0 ? std::fmin(kPi, 0.9 * 2 * kPi / 3 / std::sqrt(K)) : kPi;
    world::SceneBody ship = square("ship", 0.3, 20, 0, 0, 0);
    ship.controlled = true;
    s.bodies.push_back(ship);
    s.bodies.push_back(square("a", 0.5, 10, 0.7, 100, 30));
    s.bodies.push_back(square("b", 1.2, 200, 1.3, 20, -45));
    s.bodies.push_back(square("c", 0.1, 300, 0.25, 250, 0));
    s.bodies.push_back(square("d", 1.7, 80, 2.1, 170, 5));
    return s;
}

// With no bumps, the double engine's world and the uneven world step alike: every body's centre,
// direction of travel and facing within 1e-9 after 10^4 steps, the ship thrusting and turning
// for the first second.
TEST(UnevenWorld, WithoutBumpsItIsTheConstantKWorld) {
    for (double K : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
        const world::Scene s = moving_scene(K);
        world::World<double> c(s);
        uneven::World u(s);
        c.press(world::Action::thrust), u.press(world::Action::thrust);
        c.press(world::Action::left), u.press(world::Action::left);
        double worst = 0, worst_angle = 0;
        int wraps = 0;
        for (int step = 0; step < 10000; ++step) {
            if (step == 60) {
                c.release(world::Action::thrust), u.release(world::Action::thrust);
                c.release(world::Action::left), u.release(world::Action::left);
            }
            c.step(1.0 / 60), u.step(1.0 / 60);
            for (std::size_t i = 0; i < u.bodies.size(); ++i) wraps += c.bodies[i].wrapped;
        }
        for (std::size_t i = 0; i < u.bodies.size(); ++i) {  // (the world of constant K adds its instruments' after)
            const geo::Polar<double> p = c.bodies[i].centre, q = u.bodies[i].centre;
            worst = std::fmax(worst, std::fabs(p.r - q.r) + p.r * std::fabs(std::remainder(p.theta - q.theta, 2 * kPi)));
            worst_angle = std::fmax(worst_angle, std::fabs(std::remainder(c.bodies[i].travel - u.bodies[i].travel, 2 * kPi)));
            worst_angle = std::fmax(worst_angle, std::fabs(std::remainder(c.bodies[i].facing - u.bodies[i].facing, 2 * kPi)));
            EXPECT_NEAR(c.bodies[i].speed, u.bodies[i].speed, 1e-12) << K;
        }
        std::printf("K = %+.1f: after 10^4 steps (%d wraps) centres within %.2e, angles within %.2e\n", K, wraps, worst,
                    worst_angle);
        EXPECT_GT(wraps, 5) << K;  // the limit circle was crossed on the way
        EXPECT_LT(worst, 1e-9) << K;
        EXPECT_LT(worst_angle, 1e-9) << K;
    }
}

// ψ's gradient, written again here in long double from the metric's definition.
struct LongMetric {
    long double K;
    std::vector<uneven::Bump> bumps;
    void grad(long double x, long double y, long double& gx, long double& gy, long double& psi) const {
        const long double q = 1 + K * (x * x + y * y) / 4;
        psi = -std::log(q), gx = -K * x / (2 * q), gy = -K * y / (2 * q);
        for (const uneven::Bump& b : bumps) {
            const long double dx = x - b.centre.x, dy = y - b.centre.y, s2 = (long double)b.width * b.width;
            const long double d2 = dx * dx + dy * dy;
            if (b.kind == uneven::BumpKind::hill) {
                const long double beta = b.strength * std::exp(-d2 / s2);
                psi += beta, gx += -2 * beta * dx / s2, gy += -2 * beta * dy / s2;
            } else {
                psi += -(b.strength / 2.0L) * std::log(1 + d2 / s2);
                gx += -b.strength * dx / (s2 + d2), gy += -b.strength * dy / (s2 + d2);
            }
        }
    }
};
// The geodesic equation of g = e^{2ψ}|dx|² as a second-order system in the chart point and its
// chart velocity v: v' = -2 (∇ψ·v) v + |v|² ∇ψ (a different formulation from the engine's
// heading and speed), by RK4 in long double with steps of 1/4096 s.
void second_order(const LongMetric& m, long double& x, long double& y, long double& vx, long double& vy, long double t) {
    const int n = static_cast<int>(std::ceil(t * 4096));
    const long double h = t / n;
    auto f = [&](const long double* s, long double* d) {
        long double gx, gy, psi;
        m.grad(s[0], s[1], gx, gy, psi);
        const long double dot = gx * s[2] + gy * s[3], v2 = s[2] * s[2] + s[3] * s[3];
        d[0] = s[2], d[1] = s[3], d[2] = -2 * dot * s[2] + v2 * gx, d[3] = -2 * dot * s[3] + v2 * gy;
    };
    long double s[4] = {x, y, vx, vy};
    for (int i = 0; i < n; ++i) {
        long double k1[4], k2[4], k3[4], k4[4], t2[4];
        f(s, k1);
        for (int j = 0; j < 4; ++j) t2[j] = s[j] + h / 2 * k1[j];
        f(t2, k2);
        for (int j = 0; j < 4; ++j) t2[j] = s[j] + h / 2 * k2[j];
        f(t2, k3);
        for (int j = 0; j < 4; ++j) t2[j] = s[j] + h * k3[j];
        f(t2, k4);
        for (int j = 0; j < 4; ++j) s[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
    x = s[0], y = s[1], vx = s[2], vy = s[3];
}

// The lens and the hills: each moving body's chart point after 10 s, against the second-order
// integrator started from the dump's first frame (its chart point, heading and speed).
TEST(UnevenWorld, TheDumpsChartPointsAgreeWithAnotherIntegrator) {
    for (const char* name : {"lens", "hills"}) {
        world::Scene s;
        ASSERT_TRUE(world::builtin_scene(name, {}, s));
        uneven::World w(s);
        const uneven::World start = w;
        for (int i = 0; i < 600; ++i) w.step(1.0 / 60);
        LongMetric m{w.K, {}};
        for (int i = 0; i < w.metric().bump_count; ++i) m.bumps.push_back(w.metric().bumps[i]);
        double worst = 0;
        int checked = 0;
        for (std::size_t i = 0; i < w.bodies.size(); ++i) {
            const uneven::Body& b0 = start.bodies[i];
            if (b0.speed == 0 || w.bodies[i].wrapped || b0.desc->grid) continue;
            const Vec2 x0 = start.chart(b0.centre);
            long double x = x0.x, y = x0.y, gx, gy, psi;
            m.grad(x, y, gx, gy, psi);
            long double vx = b0.speed * std::exp(-psi) * std::cos((long double)b0.travel);
            long double vy = b0.speed * std::exp(-psi) * std::sin((long double)b0.travel);
            second_order(m, x, y, vx, vy, 10.0L);
            const Vec2 x1 = w.chart(w.bodies[i].centre);
            worst = std::fmax(worst, std::hypot(double(x) - x1.x, double(y) - x1.y));
            ++checked;
        }
        std::printf("%s: %d bodies after 600 steps within %.2e chart units of the second-order integrator\n", name,
                    checked, worst);
        EXPECT_GE(checked, 2) << name;
        EXPECT_LT(worst, 1e-9) << name;
        // The dump carries those numbers: the chart point and the heading, to 9 digits.
        files::DumpOptions o;
        std::string line;
        files::dump_frame(w, o, line);
        const uneven::Body& b = w.bodies.back();
        char want[96];
        const Vec2 x = w.chart(b.centre);
        std::snprintf(want, sizeof want, "\"chart\":[%.9g,%.9g],\"heading\":%.9g", x.x, x.y,
                      std::remainder(b.travel, 2 * kPi) / kDeg);
        EXPECT_NE(line.find(want), std::string::npos) << want << "\n" << line.substr(0, 400);
    }
}

// The speed is the body's: among the hills for 10^6 steps it stays, and the metric's length of
// the last step's path (measured with 256 chords) is the speed times the step within 1e-9.
TEST(UnevenWorld, TheSpeedHoldsForAMillionSteps) {
    world::Scene s;
    ASSERT_TRUE(world::builtin_scene("hills", {}, s));
    s.bodies.resize(1);  // (the grid's first line, made to move)
    s.bodies[0].speed = 0.9, s.bodies[0].direction_deg = 33, s.bodies[0].r = 0.4;
    uneven::World w(s);
    const double speed = w.bodies[0].speed;
    for (int i = 0; i < 1000000; ++i) w.step(1.0 / 60);
    EXPECT_EQ(w.bodies[0].speed, speed);
    uneven::Geodesic g{w.chart(w.bodies[0].centre), w.bodies[0].travel};
    double length = 0;
    const int n = 256;
    for (int i = 0; i < n; ++i) {
        const uneven::Geodesic next = uneven::step(w.metric(), g, speed, 1.0 / 60 / n);
        const Vec2 mid = 0.5 * (g.x + next.x);
        length += std::exp(w.metric().at(mid).psi) * std::hypot(next.x.x - g.x.x, next.x.y - g.x.y);
        g = next;
    }
    std::printf("after 10^6 steps: speed %.12f, measured over the next step %.12f\n", speed, length * 60);
    EXPECT_NEAR(length * 60, speed, 1e-9);
}

// The gravity scene's game: a bullet fired past the mass bends towards it (with the mass at
// strength 0, it flies straight: its heading stays within 1e-12), and the game's rules run as in
// the world of constant K (the shot is a hit or flies its range).
TEST(UnevenWorld, TheGamesBulletsCurveRoundTheMass) {
    for (bool mass : {true, false}) {
        world::Scene s;
        ASSERT_TRUE(world::builtin_scene("gravity", {}, s));
        if (!mass) s.bumps[0].strength = 0;
        uneven::World w(s);
        w.press(world::Action::fire), w.release(world::Action::fire);
        w.step(1.0 / 60);
        ASSERT_EQ(w.game().phase, world::GamePhase::playing);
        w.press(world::Action::right);  // from facing up (90) to 10 degrees, 0.3 from the mass
        for (int i = 0; i < 40; ++i) w.step(1.0 / 60);
        w.release(world::Action::right);
        w.press(world::Action::fire);
        w.step(1.0 / 60);
        w.release(world::Action::fire);
        const uneven::Body* bullet = nullptr;
        for (const uneven::Body& b : w.bodies)
            if (b.active && b.desc->kind() == world::BodyKind::bullet) bullet = &b;
        ASSERT_NE(bullet, nullptr);
        const double first = bullet->travel;
        const Vec2 start = w.chart(bullet->centre);
        double turned = 0;
        for (int i = 0; i < 50 && bullet->active; ++i) {
            w.step(1.0 / 60);
            turned = std::remainder(bullet->travel - first, 2 * kPi);
        }
        const Vec2 c = w.metric().bumps[0].centre, now = w.chart(bullet->centre);
        std::printf("%s: the bullet from heading %.1f deg turned %.3f deg in its flight\n", mass ? "the mass" : "no mass",
                    first / kDeg, turned / kDeg);
        if (mass) {
            EXPECT_GT(turned, 5 * kDeg);  // the mass is to its left (counter-clockwise): it turns left
            EXPECT_GT(uneven::cross(now - start, c - start), 0);
        } else {
            EXPECT_LT(std::fabs(turned), 1e-12);
        }
    }
}

// Whether the chart segment p-q meets the closed polygon v[0..n) (crosses an edge or lies inside).
bool meets(Vec2 p, Vec2 q, const std::vector<Vec2>& v) {
    auto side = [](Vec2 a, Vec2 b, Vec2 c) { return uneven::cross(b - a, c - a); };
    bool inside = false;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
        const Vec2 a = v[j], b = v[i];
        if ((side(p, q, a) > 0) != (side(p, q, b) > 0) && (side(a, b, p) > 0) != (side(a, b, q) > 0)) return true;
        if ((a.y > q.y) != (b.y > q.y) && q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
    return inside;
}

// The gravity scene's game hits what it draws: shots at each asteroid (held still), the frame of
// the hit against the first frame the bullet's path crosses the asteroid's outline as drawn (the
// exponential map, in the chart), a different test from the game's.
TEST(UnevenWorld, TheGameHitsWhatItDraws) {
    world::Scene s;
    ASSERT_TRUE(world::builtin_scene("gravity", {}, s));
    int crossed = 0, agreed = 0;
    for (int target = 0; target < 4; ++target) {
        uneven::World w(s);
        w.press(world::Action::fire), w.release(world::Action::fire);
        w.step(1.0 / 60);
        std::vector<uneven::Body*> rocks;
        uneven::Body* ship = nullptr;
        for (uneven::Body& b : w.bodies) {
            if (b.active && b.desc->kind() == world::BodyKind::asteroid) b.speed = 0, b.spin = 0, rocks.push_back(&b);
            if (b.desc->controlled) ship = &b;
        }
        ASSERT_GT(rocks.size(), static_cast<std::size_t>(target));
        const uneven::Body& rock = *rocks[static_cast<std::size_t>(target)];
        ship->facing = rock.centre.theta;  // from O, along the chart's radius towards it
        for (int i = 0; i < 60; ++i) w.step(1.0 / 60);  // (the game's cooldown)
        w.press(world::Action::fire);
        w.step(1.0 / 60);
        w.release(world::Action::fire);
        const uneven::Body* bullet = nullptr;
        for (const uneven::Body& b : w.bodies)
            if (b.active && b.desc->kind() == world::BodyKind::bullet) bullet = &b;
        ASSERT_NE(bullet, nullptr);
        const uint32_t serial = rock.serial;
        long hit = -1, cross = -1;
        for (long f = 0; f < 200 && hit < 0; ++f) {
            const Vec2 p = w.chart(bullet->centre);
            std::vector<Vec2> outline;
            for (std::size_t i = 0; i < rock.local.size(); ++i) outline.push_back(w.vertex(rock, i));
            const bool was = bullet->active;
            w.step(1.0 / 60);
            if (was && cross < 0 && meets(p, w.chart(bullet->centre), outline)) cross = f;
            for (int e = 0; e < w.game().event_count(); ++e)
                if (w.game().events()[e].kind == world::GameEvent::hit && w.game().events()[e].asteroid == serial) hit = f;
        }
        std::printf("asteroid %u: its drawn outline crossed in frame %ld, hit in frame %ld\n", serial, cross, hit);
        crossed += cross >= 0;
        agreed += cross >= 0 && std::labs(hit - cross) <= 1;
    }
    EXPECT_GE(crossed, 2);
    EXPECT_EQ(agreed, crossed);
}

}  // namespace uneven_world_test
}  // namespace
