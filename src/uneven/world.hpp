// The uneven world (docs/uneven.md): a scene's bodies on the geodesics of the metric its bumps
// make (uneven/metric.hpp), driven by the same actions as the world of constant K
// (world/world.hpp), so that a session (app/session.cpp) runs either.
//
// State. A body is the constant-K world's (world::Body<double>), read through the chart: its
// centre (r, theta) is the chart point rho_K(r) (cos theta, sin theta), and its angles (travel,
// facing, the acceleration's direction) are the same in both (the chart is conformal, and the
// frame carried from O along a straight line of the chart is the chart's own). So the game
// (world/game.hpp) runs here as it is, its collisions in the world of constant K about each
// body, and with no bumps a body here follows the constant-K world's exactly (tests/uneven).
//
// One step of dt, for every body: velocity += a dt in the tangent plane (the ship's thrust along
// its facing, or the body's own acceleration); the geodesic from its chart point and heading
// walked for speed * dt by RK4 (uneven::step); facing and the acceleration's direction turned with the heading (parallel
// transport keeps their angle to it); spin turns the facing; past the limit circle a body
// comes back at (2R - r, theta + pi), as in the world of constant K.
//
// The limit circle. On the sphere the chart's point at the antipode is at infinity, so the uneven
// world's limit circle is R or, at K > 0, the stereographic view's cut at 120 degrees
// (geo::shown_radius), whichever is nearer: the disc both views show (limit()).
//
// Controls: curvature up and down (and the presets, the sweep, keys 1, 2, 3) change K, every body
// keeping its (r, theta) (a game's level may set K too); strength up and down scale every bump's
// strength by a gain from 0 to its most (gain_most()); reset restores the scene; fire plays the
// game, if the scene has one. The instruments are triangles (uneven/triangle.hpp): the scene's
// [[measure]] triangles and the live one, which the instrument key turns on and off and fire
// then marks where the ship is (a fourth mark starts again). Same actions, same result, bit for
// bit.
//
// Memory: the bodies are allocated when the world is built; step() allocates nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/geometry.hpp"
#include "uneven/geodesic.hpp"
#include "uneven/triangle.hpp"
#include "world/body.hpp"
#include "world/game.hpp"
#include "world/instruments.hpp"
#include "world/scene.hpp"
#include "world/action.hpp"
#include "world/ranges.hpp"

namespace noneuclid::uneven {

using Body = world::Body<double>;

class World {
public:
    using scalar = double;
    static constexpr bool kUneven = true;

    explicit World(const world::Scene& scene);
    World(const World& o) : scene_(o.scene_) { *this = o; }
    World& operator=(const World& o);

    double K = 0, R = 0;  // R: the scene's limit radius (limit() is the one in force)
    double time = 0;
    long frame = 0;
    std::vector<Body> bodies;

    const world::Scene& scene() const { return scene_; }
    const Metric& metric() const { return metric_; }
    // Counts the changes of the metric (K, the gain, a reset): views cache what depends on it.
    uint32_t metric_version() const { return version_; }
    double gain() const { return gain_; }
    double gain_most() const { return gain_most_; }
    // The limit circle in force: R, or at K > 0 the chart's cut if nearer (see above).
    double limit() const;

    bool held(world::Action a) const { return held_[static_cast<int>(a)]; }
    void press(world::Action a);
    void release(world::Action a) { held_[static_cast<int>(a)] = false; }
    void step(double dt);
    void reset();

    // The constant-K polar coordinates of a chart point, and back (at the world's K).
    geo::Polar<double> polar(Vec2 x) const;
    Vec2 chart(geo::Polar<double> p) const;
    // A body's vertex i, as the exponential map from its centre (with the integrator's step).
    Vec2 vertex(const Body& b, std::size_t i) const;

    // For the game's collisions (world/game.hpp): body b's drawn vertices (the exponential map) and
    // centre as 3-vectors of the constant-K model, and a length about b in the model's units (the
    // metric's bumps stretch or shrink it there by e^-beta).
    void shape_vectors(const Body& b, geo::Vec3<double>& c, geo::Vec3<double>* out, std::size_t n) const;
    double model_length(const Body& b, double length) const;

    // The game, if the scene has one (world/game.hpp).
    const world::Game<double>& game() const { return game_; }

    // An instrument: a triangle, its marks and its reading as the panel and the dump take it
    // (world::GaugeReading's triangle fields; k_area_deg is the integral of K dA).
    struct Gauge {
        bool live = false, shown = false;
        int marks = 0;      // placed (the live one's: at most 3, then a new triangle)
        Triangle triangle;
        world::GaugeReading read;
        uint32_t version = 0;  // the metric's it was measured under, +1 (0: not yet)
        bool on() const { return shown; }
        const world::GaugeReading& reading() const { return read; }
    };
    // The scene's triangles, then the live one (last).
    const std::vector<Gauge>& gauges() const { return gauges_; }
    bool measuring() const { return gauges_.back().shown; }
    // A mark of the live triangle at `at` (a tap on the web page), turning it on if it is off.
    void place_mark(geo::Polar<double> at);
    // What a session asks of every world: no zoom here.
    world::ZoomReading zoom() const { return {}; }

private:
    void set_curvature(double k);
    void set_gain(double g);
    void build_metric();
    void fold();
    void drop(Gauge& g, Vec2 x);
    geo::Polar<double> ship_centre() const;
    void read_gauges();
    void settle(Body& b) const;
    void step_body(Body& b, double dt, double turn) const;

    world::Scene scene_;
    Metric metric_;
    double gain_ = 1, gain_most_ = 2;
    uint32_t version_ = 0;
    int sweep_dir_ = 1;
    bool held_[world::kActionCount] = {};
    std::vector<Body> initial_;
    double initial_K_ = 0;
    world::Game<double> game_, initial_game_;
    std::vector<Gauge> gauges_;
};

}  // namespace noneuclid::uneven
