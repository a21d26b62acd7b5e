// The three-dimensional world behind the kinds' contract (kinds/kind.hpp): space::World with
// what every world gives the session — its scene, its instruments (none yet), its game (off),
// its zoom (none) — made from a scene marked `space` (world/scenes.cpp): the ship 1.2 out facing
// O, and a dozen of the five Platonic solids placed, turned, sent and spun by a fixed sequence (the
// same on every machine: no library's random numbers), drifting at 0.05 to 0.2 units a second;
// or, in a honeycomb scene, the ship alone among the honeycomb's cubes (space/honeycomb.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
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

// A scene file's solid as a body: a named shape, or its own (kSolidCount + `own`, the index of
// its own shape in the SceneWorld), placed, sent and spun as the file says.
inline Body<double> solid_body(const world::SceneSolid& d, int own) {
    Body<double> b;
    b.solid = own;
    for (int i = 0; i < kSolidCount; ++i)
        if (d.shape == kSolids[i].name) b.solid = i;
    b.size = d.shape.empty() ? 1 : d.size;
    const V3<double> p{d.position[0], d.position[1], d.position[2]}, v{d.velocity[0], d.velocity[1], d.velocity[2]};
    b.at = {norm(p), unit(p)};
    b.speed = norm(v), b.travel = unit(v);
    b.spin = d.spin_deg * 3.14159265358979323846 / 180;
    b.spin_axis = unit(V3<double>{d.spin_axis[0], d.spin_axis[1], d.spin_axis[2]}, {0, 0, 1});
    b.color[0] = d.color.r, b.color[1] = d.color.g, b.color[2] = d.color.b;
    return b;
}

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
    if (!scene.solids.empty()) {  // (a scene file's: its own, numbered after the five)
        int own = kSolidCount;
        for (const world::SceneSolid& d : scene.solids) s.bodies.push_back(solid_body(d, d.shape.empty() ? own++ : 0));
        return s;
    }
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

// A body, and a world's start, in another scalar (the fixed engine's).
template <class T>
Body<T> body_in(const Body<double>& d) {
    const auto v = [](const V3<double>& x) { return V3<T>{T(x.x), T(x.y), T(x.z)}; };
    Body<T> b;
    b.solid = d.solid, b.size = T(d.size), b.at = {T(d.at.r), v(d.at.u)};
    b.frame = {v(d.frame.forward), v(d.frame.up), v(d.frame.right)};
    b.travel = v(d.travel), b.speed = T(d.speed), b.spin_axis = v(d.spin_axis), b.spin = T(d.spin);
    for (int c = 0; c < 3; ++c) b.color[c] = d.color[c];
    b.ship = d.ship;
    return b;
}
template <class T>
Start<T> start_in(const Start<double>& d) {
    Start<T> s;
    s.K = T(d.K), s.R = T(d.R), s.curvature_rate = d.curvature_rate, s.thrust = d.thrust, s.turn_rate = d.turn_rate;
    s.max_speed = d.max_speed;
    for (const Body<double>& b : d.bodies) s.bodies.push_back(body_in<T>(b));
    return s;
}

// The world of a scene on the scalar T: double (the reference) or fx::fixed (the device's).
template <class T>
class SceneWorldOf : public World<T> {
public:
    using World<T>::K;
    explicit SceneWorldOf(const world::Scene& scene) : World<T>(start_in<T>(space_start(scene))), scene_(scene) {
        if (scene.honeycomb_cells) honeycomb_.set(scene.honeycomb_cells == 3 ? kEightCell : kOrder5Cubic);
        for (const world::SceneSolid& d : scene.solids)
            if (d.shape.empty()) own_.push_back(OwnShape::of(d));
        for (const OwnShape& o : own_)  // (after every push: the pointers stay)
            own_solids_.push_back({o.name.c_str(), static_cast<int>(o.lengths.size()), o.edge_count, 0, o.directions.get(),
                                   o.edges.get(), o.lengths.data()});
    }
    SceneWorldOf(const SceneWorldOf&) = delete;  // (its solids' names point into its own storage)
    SceneWorldOf& operator=(const SceneWorldOf&) = delete;

    // A body's shape: one of the five, or a scene file's own.
    const Solid& solid(const Body<T>& b) const {
        return b.solid < kSolidCount ? kSolids[b.solid] : own_solids_[static_cast<std::size_t>(b.solid - kSolidCount)];
    }

    const world::Scene& scene() const { return scene_; }
    // The scene's honeycomb (kind null: none), built for the current K.
    const Honeycomb& honeycomb() {
        honeycomb_.build(static_cast<double>(K));
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
    void place_mark(geo::Polar<T>) {}
    const world::Game<T>& game() const { return game_; }  // (off)
    world::ZoomReading zoom() const { return {}; }  // (no zoom)

private:
    struct OwnShape {  // a scene file's solid of its own: unit directions, lengths, edges (in the
                       // arrays a Solid points to; held on the heap, so they stay where they are)
        std::string name;
        std::unique_ptr<double[][3]> directions;
        std::vector<double> lengths;
        std::unique_ptr<uint8_t[][2]> edges;
        int edge_count = 0;
        static OwnShape of(const world::SceneSolid& d) {
            OwnShape o;
            o.name = d.name;
            o.directions.reset(new double[d.vertices.size()][3]);
            for (std::size_t i = 0; i < d.vertices.size(); ++i) {
                const V3<double> x{d.vertices[i][0], d.vertices[i][1], d.vertices[i][2]};
                const V3<double> u = unit(x);
                o.directions[i][0] = u.x, o.directions[i][1] = u.y, o.directions[i][2] = u.z;
                o.lengths.push_back(norm(x));
            }
            o.edge_count = static_cast<int>(d.edges.size());
            o.edges.reset(new uint8_t[d.edges.size()][2]);
            for (std::size_t i = 0; i < d.edges.size(); ++i)
                o.edges[i][0] = static_cast<uint8_t>(d.edges[i][0]), o.edges[i][1] = static_cast<uint8_t>(d.edges[i][1]);
            return o;
        }
    };
    world::Scene scene_;
    std::vector<OwnShape> own_;
    std::vector<Solid> own_solids_;
    std::vector<Gauge> gauges_;
    Honeycomb honeycomb_;
    world::Game<T> game_;
};
using SceneWorld = SceneWorldOf<double>;

}  // namespace noneuclid::space
