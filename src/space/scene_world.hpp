// The three-dimensional world behind the kinds' contract (kinds/kind.hpp): space::World with
// what every world gives the session — its scene, its instruments (none yet), its game (off),
// its zoom (none) — made from a scene marked `space` (world/scenes.cpp): the ship 1.2 out facing
// O, and a dozen of the five Platonic solids placed, turned, sent and spun by a fixed sequence (the
// same on every machine: no library's random numbers), drifting at 0.05 to 0.2 units a second;
// or, in a honeycomb scene, the ship alone among the honeycomb's cubes (space/honeycomb.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "space/honeycomb.hpp"
#include "space/world.hpp"
#include "world/game.hpp"
#include "world/instruments.hpp"
#include "world/scene.hpp"

namespace noneuclid::space {

// A fixed sequence of numbers in [0, 1): the scene's layout (a 64-bit linear congruential
// generator, Knuth's constants).
struct Sequence {
    uint64_t state = 20261207;
    double next() {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0);
    }
    V3<double> direction() {  // (uniform on the sphere: z uniform, the azimuth uniform)
        const double z = 2 * next() - 1, a = 2 * 3.14159265358979323846 * next(), s = std::sqrt(1 - z * z);
        return {s * std::cos(a), s * std::sin(a), z};
    }
};

inline constexpr int kSpaceBodies = 12;

inline Start<double> space_start(const world::Scene& scene) {
    Start<double> s;
    s.K = scene.curvature, s.R = scene.limit_radius, s.curvature_rate = scene.curvature_rate;
    Body<double> ship;
    ship.ship = true, ship.solid = 0, ship.size = 0.06;
    ship.color[0] = 255, ship.color[1] = 90, ship.color[2] = 90;
    if (scene.honeycomb_cells) {  // (inside the first cube near a corner, looking across it)
        ship.at = {0.7, unit(V3<double>{-1, -0.9, -0.75})};
        ship.frame = orthonormal(Frame<double>{unit(V3<double>{1, 0.85, 0.6}), {0, 0, 1}, {0, -1, 0}});
        ship.travel = ship.frame.forward;
        s.bodies.push_back(ship);
        return s;
    }
    // (1.2 out, off the grid's lines, facing the middle of the bodies: O.)
    ship.at = {1.2, unit(V3<double>{-1, 0.2, 0.12})};
    ship.frame = orthonormal(Frame<double>{unit(V3<double>{1, -0.2, -0.12}), {0, 0, 1}, {0, -1, 0}});
    ship.travel = ship.frame.forward;
    s.bodies.push_back(ship);
    static constexpr uint8_t kColors[5][3] = {{255, 200, 64}, {64, 220, 120}, {120, 160, 255}, {230, 120, 230}, {120, 230, 230}};
    Sequence q;
    for (int i = 0; i < kSpaceBodies; ++i) {
        Body<double> b;
        b.solid = i % kSolidCount;
        b.size = 0.15 + 0.1 * q.next();
        b.at = {0.7 + 1.6 * q.next(), q.direction()};
        const V3<double> f = q.direction();
        const V3<double> d = q.direction();
        const V3<double> up = unit(d - dot(d, f) * f, some_normal(f));
        b.frame = orthonormal(Frame<double>{f, up, cross(f, up)});
        b.travel = q.direction(), b.speed = 0.05 + 0.15 * q.next();
        b.spin_axis = q.direction(), b.spin = 0.2 + 0.6 * q.next();
        for (int c = 0; c < 3; ++c) b.color[c] = kColors[b.solid][c];
        s.bodies.push_back(b);
    }
    return s;
}

class SceneWorld : public World<double> {
public:
    explicit SceneWorld(const world::Scene& scene) : World<double>(space_start(scene)), scene_(scene) {
        if (scene.honeycomb_cells) honeycomb_.set(scene.honeycomb_cells == 3 ? kEightCell : kOrder5Cubic);
    }

    const world::Scene& scene() const { return scene_; }
    // The scene's honeycomb (kind null: none), built for the current K.
    const Honeycomb& honeycomb() {
        honeycomb_.build(K);
        return honeycomb_;
    }
    const Honeycomb& honeycomb_as_set() const { return honeycomb_; }  // (its kind and closing K)

    // No instruments yet: the contract's types, an empty list.
    struct Gauge {
        world::GaugeReading read;
        bool on() const { return false; }
        const world::GaugeReading& reading() const { return read; }
    };
    const std::vector<Gauge>& gauges() const { return gauges_; }
    bool measuring() const { return false; }
    void place_mark(geo::Polar<double>) {}
    const world::Game<double>& game() const { return game_; }  // (off)
    struct ZoomReading {
        bool on = false;
        double z = 1;
        bool least = false, most = false;
    };
    ZoomReading zoom() const { return {}; }

private:
    world::Scene scene_;
    std::vector<Gauge> gauges_;
    Honeycomb honeycomb_;
    world::Game<double> game_;
};

}  // namespace noneuclid::space
