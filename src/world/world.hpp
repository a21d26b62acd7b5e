// The world: K, the limit radius R and the bodies, stepped at a fixed timestep by the paper's
// physics, driven by the same actions the kiosk buttons send. Templated on the scalar like the
// geometry, and on the engine (geometry/engine.hpp) that moves and draws its bodies: the exact
// forms (geo::Exact<T>, the default) or the paper's literal formulas (geo::Paper, double only).
//
// One step of dt, for every body (the paper, section "movement"):
//  1. acceleration: a body's own (scene files may give one), or for the ship while thrust is
//     held, `thrust` along its facing; velocity += a dt as vectors in the tangent plane at the
//     centre (both are angles in the carried frame there). A coasting body (a = 0) keeps its
//     speed exactly.
//  2. the centre moves speed * dt along the geodesic in its direction of travel; the direction
//     of travel, the facing and the acceleration's direction are carried along (the engine's
//     move: geo::Exact walks the body's coast from where it began, geometry/coast.hpp, so the
//     steps' roundings do not add up; geo::Paper walks each step from the last).
//  3. spin (plus the ship's turn while left/right is held) turns the facing.
// Time: `time` is the world's clock, the sum of the steps' dt exactly as given (1/60 s), in
// every engine. Each step hands the engine a geo::Tick: in fixed point dt rounds to Q16.16
// (1/60 is 0.015% short there), so what moves at a rate (speed * dt, spin * dt) is taken from
// the step's exact share of the clock with its remainder carried, and follows the clock.
//  4. the limit circle: a centre past R reappears at (2R - r, theta + pi), its direction of
//     travel and facing unchanged on screen (the same carried-frame angles). At K > 0 with
//     R = pi/sqrt K this is exactly the geodesic continuing through the antipode (tested).
// Curvature: changing K leaves every body's polar numbers as they are (the paper); held
// curvature up/down changes K by `curvature_rate` per second, clamped to [-1, 1]; next preset
// cycles the scene's presets; reset restores the scene's initial state. In a scene that zooms
// (Scene::zoom, the earth scene) held curvature up/down zooms instead: z, the curvature the
// picture is the sphere of, is multiplied by a constant each step within z's range, K = z, and
// the level for z is shown (its bodies active, their vertices' rho scaled by sqrt(level / z));
// the other levels' bodies are inactive. Same actions, same result, bit for bit: nothing here
// reads a clock or a random number.
//
// Memory: bodies and their vertices are allocated when the world is built; step() allocates
// nothing.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "geometry/engine.hpp"
#include "geometry/geometry.hpp"
#include "world/action.hpp"
#include "world/body.hpp"
#include "world/game.hpp"
#include "world/instruments.hpp"
#include "world/ranges.hpp"
#include "world/scene.hpp"

namespace noneuclid::world {

using geo::Polar;
using geo::Pose;

template <class T, geo::Engine E = geo::Exact<T>>
class World {
    static_assert(std::is_same_v<typename E::scalar, T>, "the engine's scalar is the world's");

public:
    using scalar = T;
    using engine = E;

    explicit World(const Scene& scene) : scene_(scene) {
        R = T(scene_.limit_radius);
        add_gauges();
        bodies.resize(scene_.bodies.size());  // (exactly: no room to spare, in RAM that is scarce)
        start();
        update_gauges();
    }
    World(const World& o) : scene_(o.scene_) { copy_from(o); }
    World& operator=(const World& o) {
        if (this != &o) {
            scene_ = o.scene_;
            copy_from(o);
        }
        return *this;
    }

    T K{}, R{};
    double time = 0;  // seconds simulated
    long frame = 0;   // steps taken
    std::vector<Body<T>> bodies;

    const Scene& scene() const { return scene_; }
    bool held(Action a) const { return held_[static_cast<int>(a)]; }

    void press(Action a) {
        held_[static_cast<int>(a)] = true;
        switch (a) {
            case Action::preset: next_preset(); break;
            case Action::reset: reset(); break;
            case Action::hyperbolic: K = T(-1); break;
            case Action::flat: K = T(0); break;
            case Action::spherical: K = T(1); break;
            case Action::fire:
                if (measuring()) gauges_.back().drop(ship_position());
                else game_.press_fire();
                break;
            case Action::instrument: gauges_.back().cycle(); break;
            default: break;
        }
        show_zoom();  // (K set apart from the zoom, or back to it: the level's other build)
    }
    void release(Action a) { held_[static_cast<int>(a)] = false; }

    // One step of dt seconds.
    void step(double dt) {
        const geo::Tick<T> tick = tick_of(dt);
        const int dk = held(Action::curvature_up) - held(Action::curvature_down);
        if (dk != 0 && scene_.zoom.on()) zoom_by(dk);
        else if (dk != 0) K = clamp_k(K + geo::times_dt(T(scene_.curvature_rate) * T(dk), tick));
        if (scene_.zoom.on()) show_zoom();
        if (scene_.sweep_rate != 0) {
            K = K + geo::times_dt(T(scene_.sweep_rate) * T(sweep_dir_), tick);
            if (K >= T(1)) K = T(1), sweep_dir_ = -1;
            if (K <= T(-1)) K = T(-1), sweep_dir_ = 1;
        }
        const T turn = T(scene_.turn_rate_deg * kDegree) * T(held(Action::left) - held(Action::right));
        const Steering steer{T(scene_.thrust), turn, game_.top_speed(T(Ranges::kSpeed)), held(Action::thrust)};
        for (Body<T>& b : bodies)
            if (b.active) step_body(b, tick, steer);
        time += dt;
        ++frame;
        game_.step(*this, tick.dt, held(Action::fire) && !measuring());
        update_gauges();
    }

    // A mark of the live instrument at `at` (a tap on the web page), turning it on if it is off.
    void place_mark(Polar<T> at) {
        if (!measuring()) gauges_.back().cycle();
        gauges_.back().drop(at);
        update_gauges();
    }

    // The instruments: the scene's, then the live one (last).
    const std::vector<Gauge<T>>& gauges() const { return gauges_; }
    // Whether the live instrument is on (fire drops marks).
    bool measuring() const { return gauges_.back().on(); }

    // The game, if the scene has one (world/game.hpp): its phase, score, lives, level, events.
    const Game<T>& game() const { return game_; }

    // The next of the scene's presets above the current K (cycling).
    void next_preset() {
        const std::vector<double>& p = scene_.presets;
        if (p.empty()) return;
        const double k = static_cast<double>(K);
        for (double v : p)
            if (v > k + 1e-9) {
                K = T(v);
                return;
            }
        K = T(p.front());
    }
    void reset() {
        start();
        sweep_dir_ = 1;
        for (Gauge<T>& g : gauges_) g.touch();
        update_gauges();
    }

    // The zoom (Scene::zoom): z, and whether it is at either end of its range. Off: no zoom.
    ZoomReading zoom() const {
        const Zoom& zm = scene_.zoom;
        return {zm.on(), zoom_, zm.on() && zoom_ <= zm.least, zm.on() && zoom_ >= zm.most};
    }

    // The body's vertices in global polar coordinates.
    void vertices(const Body<T>& b, Polar<T>* out) const {
        for (std::size_t i = 0; i < b.local.size(); ++i) out[i] = engine::vertex(K, b.centre, b.facing, b.local[i]);
    }

private:
    static constexpr double kDegree = 3.14159265358979323846 / 180;
    // What the held keys do to the controlled body this step: thrust along its facing, turn.
    struct Steering {
        T thrust{}, turn{};
        T top{};  // its top speed (the game's; the world's ceiling otherwise)
        bool thrusting = false;
    };
    // The start: K, the bodies, the game and the zoom as the scene gives them, made in place (no
    // copy of them is kept for the reset: RAM is scarce on a microcontroller; the vertex lists
    // keep their sizes, so a reset allocates nothing). The game's setup reads the clock and the
    // step count, both 0 at the start. The live instrument's parts are left to the next
    // update_gauges (it was off at the start: it only hides them); the scene's instruments are
    // placed as at the start, so that their shape counts follow the same course.
    void start() {
        K = T(scene_.curvature);
        for (std::size_t i = 0; i < bodies.size(); ++i) init_body(bodies[i], scene_.bodies[i]);
        const double now = time;
        const long steps = frame;
        time = 0, frame = 0;
        game_.restart(*this);
        time = now, frame = steps;
        for (Gauge<T>& g : gauges_)
            if (!g.live()) g.touch(), g.update(K, R, bodies);
        zoom_ = scene_.zoom.start;
        shown_level_ = -1, shown_zoom_ = 0;
        show_zoom();
    }
    // One body's step (steps 1-4 above): reads K, R and the body, writes only the body.
    void step_body(Body<T>& b, const geo::Tick<T>& dt, const Steering& steer) const {
        using geo::dot2, geo::hypot, geo::wrap_pi;  // and fx:: ones by ADL for fixed
        using std::atan2, std::cos, std::sin;
        T a = b.accel, adir = b.accel_dir;
        if (b.desc->controlled && steer.thrusting) a = steer.thrust, adir = b.facing;
        if (a != T(0)) {  // velocity += a dt, in the tangent plane at the centre
            const T adt = geo::times_dt(a, dt);
            const T vx = dot2(b.speed, cos(b.travel), adt, cos(adir));
            const T vy = dot2(b.speed, sin(b.travel), adt, sin(adir));
            b.speed = hypot(vx, vy);
            if (b.speed != T(0)) b.travel = atan2(vy, vx);
            if (b.speed > T(Ranges::kSpeed)) b.speed = T(Ranges::kSpeed);  // the ceiling (ranges.hpp)
            if (b.desc->controlled && b.speed > steer.top) b.speed = steer.top;
        }
        const bool walked = b.speed != T(0) && engine::move(K, b, dt);
        const T spin = b.desc->controlled ? b.spin + steer.turn : b.spin;
        if (spin != T(0)) b.facing = geo::turn_by(b.facing, spin, dt, b.spin_rest);
        engine::settle(b, R, walked);  // the limit circle (step 4)
    }
    // The gauges' bodies appended to the scene (our copy), the live one's last.
    void add_gauges() {
        for (const MeasureDecl& d : scene_.measures) {
            gauges_.emplace_back(d, static_cast<int>(scene_.bodies.size()), false);
            add_gauge_bodies(scene_, d, false);
        }
        gauges_.emplace_back(live_decl_, static_cast<int>(scene_.bodies.size()), true);
        add_gauge_bodies(scene_, live_decl_, true);
    }
    void update_gauges() {
        for (Gauge<T>& g : gauges_) g.update(K, R, bodies);
    }
    // Where the live instrument's next mark goes: the ship's centre (O without a ship).
    Polar<T> ship_position() const {
        for (const Body<T>& b : bodies)
            if (b.active && b.desc->controlled) return b.centre;
        return {};
    }
    // The step of dt from `time`: in fixed point its share of the clock is the difference of
    // the clock read in Q32 seconds after and before it, so that the shares add up to the clock.
    geo::Tick<T> tick_of(double dt) const {
        geo::Tick<T> t;
        t.dt = T(dt);
        if constexpr (std::is_same_v<T, fx::fixed>) {
            constexpr double kQ32 = 4294967296.0;
            t.q32 = std::llround((time + dt) * kQ32) - std::llround(time * kQ32);
        }
        return t;
    }
    static T clamp_k(T k) { return k < T(-1) ? T(-1) : (k > T(1) ? T(1) : k); }
    // Held zoom in (dk < 0) or out: z by Zoom::kStep within its range, and K = z.
    void zoom_by(int dk) {
        const Zoom& zm = scene_.zoom;
        const double z = dk > 0 ? zoom_ / Zoom::kStep : zoom_ * Zoom::kStep;
        zoom_ = z < zm.least ? zm.least : (z > zm.most ? zm.most : z);
        K = T(zoom_);
    }
    // The level for z and K active (the others not), its vertices scaled to z; nothing done
    // when neither changed. Allocates nothing: a level's bodies keep their vertex counts.
    void show_zoom() {
        const Zoom& zm = scene_.zoom;
        if (!zm.on()) return;
        const bool bent = K != T(zoom_);
        int pick = -1;
        for (int i = 0; i < static_cast<int>(zm.levels.size()); ++i) {
            const ZoomLevel& l = zm.levels[i];
            if (l.bent == bent && l.curvature >= zoom_ && (pick < 0 || l.curvature < zm.levels[pick].curvature)) pick = i;
        }
        if (pick < 0 || (pick == shown_level_ && zoom_ == shown_zoom_)) return;
        const ZoomLevel& l = zm.levels[pick];
        const double f = std::sqrt(l.curvature / zoom_);
        const float image_scale = bent ? 0.0f : static_cast<float>(1 / std::sqrt(zoom_));
        for (const ZoomLevel& o : zm.levels)
            for (int b = o.first; b < o.first + o.count; ++b) {
                bodies[b].active = &o == &l;
                bodies[b].image_scale = &o == &l ? image_scale : 0.0f;
            }
        for (int b = l.first; b < l.first + l.count; ++b) {
            Body<T>& body = bodies[b];
            const std::vector<SceneBody::Vertex>& v = scene_.bodies[b].vertices;
            for (std::size_t i = 0; i < v.size(); ++i) body.local[i].r = T(v[i].rho * f);
            ++body.sized;
        }
        shown_level_ = pick, shown_zoom_ = zoom_;
    }
    // Body b as the scene body describes it, every other field as a new Body's; its vertex list's
    // room reused.
    void init_body(Body<T>& b, const SceneBody& sb) const {
        std::vector<Polar<T>> local = std::move(b.local);
        b = Body<T>{};
        local.resize(sb.vertices.size());
        for (std::size_t i = 0; i < local.size(); ++i) local[i] = {T(sb.vertices[i].rho), T(sb.vertices[i].phi_deg * kDegree)};
        b.local = std::move(local);
        b.desc = &sb;
        b.centre = {T(sb.r), geo::wrap_pi(T(sb.theta_deg * kDegree))};
        b.facing = geo::wrap_pi(T(sb.facing_deg * kDegree));
        b.speed = T(sb.speed);
        b.travel = geo::wrap_pi(T(sb.direction_deg * kDegree));
        b.accel = T(sb.accel);
        b.accel_dir = geo::wrap_pi(T(sb.accel_direction_deg * kDegree));
        b.spin = T(sb.spin_deg * kDegree);
    }
    void copy_from(const World& o) {
        K = o.K, R = o.R, time = o.time, frame = o.frame;
        zoom_ = o.zoom_, shown_zoom_ = o.shown_zoom_;
        shown_level_ = o.shown_level_;
        bodies = o.bodies;
        game_ = o.game_;
        game_.rebind(scene_.game);
        sweep_dir_ = o.sweep_dir_;
        gauges_ = o.gauges_;
        for (std::size_t i = 0; i < gauges_.size(); ++i) gauges_[i].rebind(i < scene_.measures.size() ? scene_.measures[i] : live_decl_);
        for (int i = 0; i < kActionCount; ++i) held_[i] = o.held_[i];
        for (std::size_t i = 0; i < bodies.size(); ++i) bodies[i].desc = &scene_.bodies[i];
    }

    Scene scene_;
    MeasureDecl live_decl_;  // the live instrument's construction (the defaults)
    std::vector<Gauge<T>> gauges_;
    Game<T> game_;
    int sweep_dir_ = 1;
    bool held_[kActionCount] = {};
    double zoom_ = 1;                 // z (Scene::zoom)
    int shown_level_ = -1;            // the level shown, and the z its vertices were scaled to
    double shown_zoom_ = 0;
};

}  // namespace noneuclid::world
