// The Asteroids game, in any scene whose settings turn it on (Scene::game; docs/game.md): the
// ship fires bullets, asteroids drift and spin and split when hit, a score, three lives, levels
// that may change K. It plays on the world's own bodies: the ship is the scene's controlled
// body, and asteroids and bullets are slots (bodies made with the scene, off until the game
// spawns into them), so nothing is allocated while it runs. World::step moves every body, then
// calls Game::step for the rules: timers, bullets' range, collisions, firing, levels.
//
// Phases: `ready` (the "press fire" screen: asteroids drift, no ship) -> fire starts a game (at
// the next step) ->
// `playing` -> the last life lost -> `over` (the score shown for game_over_seconds) -> `ready`.
//
// Collisions (geometry/collision.hpp), in the space itself, exact for every K: a bullet hits an
// asteroid when its last step (the geodesic segment from where it was to where it is) meets the
// asteroid's polygon; the ship crashes when its polygon and an asteroid's overlap. Each is
// tested only when the broad phase passes: the haversine distance between the centres within
// the sum of the bounding radii (plus the bullet's step). The limit circle moves a centre that
// crosses it to the far side; it is not a seam of the space, so bodies meet only where their
// shapes overlap in the space (docs/game.md, "The limit circle").
//
// Same seed, same inputs, same game, bit for bit: the random numbers are integer
// (world/game_random.hpp), the timers read the world's time, and the geometry is the engine's.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/collision.hpp"
#include "geometry/geometry.hpp"
#include "world/body.hpp"
#include "world/game_random.hpp"
#include "world/ranges.hpp"
#include "world/scene.hpp"

namespace noneuclid::world {

enum class GamePhase : uint8_t { ready, playing, over };

// What happened in a step, for `dump` and the session: asteroids and bullets by their serial.
struct GameEvent {
    enum Kind : uint8_t { start, hit, crash, level, over };
    Kind kind = start;
    uint32_t bullet = 0, asteroid = 0;  // hit: both; crash: the asteroid
    long value = 0;                     // level: its number; over: the final score
};

inline constexpr int kGameMaxVertices = 32;  // of the ship and of each asteroid (scene files are checked)
inline constexpr int kGameEvents = 64;       // events one step can report (more are dropped)

template <class T>
class Game {
public:
    GamePhase phase = GamePhase::ready;
    long score = 0;
    int lives = 0, level = 0;
    double phase_since = 0;  // world time the phase began
    double level_since = 0;  // world time the level began

    bool on() const { return on_; }
    const GameEvent* events() const { return events_; }
    int event_count() const { return events_n_; }
    // The ship's top speed while the game runs (the world's ceiling otherwise).
    T top_speed(T ceiling) const { return on_ ? T(settings_->ship_speed) : ceiling; }

    // Once, when the world is built: finds the ship and the slots, shows the "press fire" screen.
    template <class W>
    void setup(W& w) {
        settings_ = &w.scene().game;
        on_ = settings_->on;
        if (!on_) return;
        ship_ = -1, asteroids_.clear(), bullets_.clear();
        for (std::size_t i = 0; i < w.bodies.size(); ++i) {
            const BodyKind k = w.bodies[i].desc->kind();
            if (k == BodyKind::ship && ship_ < 0) ship_ = static_cast<int>(i);
            Slot slot;
            slot.body = static_cast<int>(i);
            if (k == BodyKind::asteroid) asteroids_.push_back(slot);
            if (k == BodyKind::bullet) bullets_.push_back(slot);
        }
        for (const geo::Polar<T>& v : w.bodies[static_cast<std::size_t>(ship_)].local)
            if (v.r > nose_) nose_ = v.r;
        rng_.reseed(settings_->seed);
        phase = GamePhase::ready, phase_since = w.time, score = 0, lives = settings_->lives, level = 1;
        w.bodies[static_cast<std::size_t>(ship_)].active = false;
        for (const Slot& s : asteroids_) w.bodies[static_cast<std::size_t>(s.body)].active = false;
        for (const Slot& s : bullets_) w.bodies[static_cast<std::size_t>(s.body)].active = false;
        spawn_level(w, false);
    }

    // The game as a new one set up (setup): every field as a new Game's, its slots' room kept
    // (nothing allocated), then set up. The world's reset.
    template <class W>
    void restart(W& w) {
        std::vector<Slot> a = std::move(asteroids_), b = std::move(bullets_);
        *this = Game{};
        asteroids_ = std::move(a), bullets_ = std::move(b);
        asteroids_.clear(), bullets_.clear();
        setup(w);
    }

    // After the world holding the game was copied: its settings are the copy's.
    void rebind(const GameSettings& g) { settings_ = &g; }

    // Fire was pressed: on the "press fire" screen, a new game begins at the next step (so that
    // everything a game does happens in a step, and is reported with it).
    void press_fire() {
        if (on_ && phase == GamePhase::ready) starting_ = true;
    }

    // The rules, after World::step has moved every body by dt (w.time is the time after it).
    template <class W>
    void step(W& w, T dt, bool fire) {
        events_n_ = 0;
        if (!on_) return;
        const GameSettings& g = *settings_;
        const double t = w.time;
        if (starting_) start(w);
        if (phase == GamePhase::over && t - phase_since >= g.game_over_seconds) phase = GamePhase::ready, phase_since = t;
        if (respawn_at_ >= 0 && t >= respawn_at_) respawn(w);
        if (phase == GamePhase::playing && level_at_ >= 0 && t >= level_at_) {
            level_at_ = -1, ++level;
            spawn_level(w, true);
            emit({GameEvent::level, 0, 0, level});
        }
        for (Slot& s : bullets_) {  // spent at their range
            Body<T>& b = body(w, s);
            if (b.active && (s.travelled = s.travelled + b.speed * dt) >= T(g.bullet_range)) b.active = false;
        }
        if (phase == GamePhase::playing) {
            bullets_hit(w, dt);
            ship_crash(w);
            if (fire && ship(w).active && t >= next_shot_) shoot(w);
            if (level_at_ < 0 && !any_asteroid(w)) level_at_ = t + g.level_pause;
        }
        for (Slot& s : bullets_) s.prev = body(w, s).centre;
        Body<T>& sh = ship(w);
        sh.hidden = sh.active && t < invulnerable_until_ && std::fmod(invulnerable_until_ - t, 0.2) < 0.1;
    }

    // The size of the asteroid in body i (0 large, 1 medium, 2 small); -1 if it is none.
    int size_of(std::size_t i) const {
        for (const Slot& s : asteroids_)
            if (static_cast<std::size_t>(s.body) == i) return s.size;
        return -1;
    }
    // When the next shot may be fired (world time), and when the respawned ship becomes
    // vulnerable.
    double next_shot() const { return next_shot_; }
    double invulnerable_until() const { return invulnerable_until_; }

    // For the attract mode's autopilot: the nearest asteroid's direction from the ship's facing
    // (radians, counter-clockwise) and its distance; false with no ship or no asteroid.
    template <class W>
    bool aim(const W& w, double& turn, double& dist) const {
        if (!on_ || !w.bodies[static_cast<std::size_t>(ship_)].active) return false;
        const Body<T>& s = w.bodies[static_cast<std::size_t>(ship_)];
        bool found = false;
        for (const Slot& a : asteroids_) {
            const Body<T>& b = w.bodies[static_cast<std::size_t>(a.body)];
            if (!b.active) continue;
            const double d = static_cast<double>(geo::distance(w.K, s.centre, b.centre));
            if (found && d >= dist) continue;
            found = true, dist = d;
            turn = static_cast<double>(geo::wrap_pi(geo::bearing(w.K, s.centre, b.centre) - s.facing));
        }
        return found;
    }

private:
    struct Slot {
        int body = -1;
        int size = 0;        // asteroid: 0 large, 1 medium, 2 small
        T radius{};          // asteroid: its largest rho
        long born = -1;      // asteroid: the frame it was spawned in (not hit in that step)
        T travelled{};       // bullet: the distance flown
        geo::Polar<T> prev{};  // bullet: where the last step began
    };

    template <class W>
    static Body<T>& body(W& w, const Slot& s) {
        return w.bodies[static_cast<std::size_t>(s.body)];
    }
    template <class W>
    Body<T>& ship(W& w) const {
        return w.bodies[static_cast<std::size_t>(ship_)];
    }
    void emit(const GameEvent& e) {
        if (events_n_ < kGameEvents) events_[events_n_++] = e;
    }
    template <class W>
    bool any_asteroid(W& w) const {
        for (const Slot& s : asteroids_)
            if (body(w, s).active) return true;
        return false;
    }

    template <class W>
    void start(W& w) {
        starting_ = false;
        rng_.reseed(settings_->seed ^ static_cast<uint32_t>(w.frame * 2654435761u));
        phase = GamePhase::playing, phase_since = w.time, score = 0, lives = settings_->lives, level = 1;
        level_at_ = -1, next_shot_ = w.time + settings_->bullet_cooldown;
        for (const Slot& s : bullets_) body(w, s).active = false;
        spawn_level(w, true);
        respawn(w);
        emit({GameEvent::start, 0, 0, 0});
    }

    // The ship at O, at rest, facing up the screen, blinking and safe for a while.
    template <class W>
    void respawn(W& w) {
        Body<T>& s = ship(w);
        s.centre = {T(0), T(0)};
        s.facing = s.travel = geo::pi_v<T> / T(2);
        s.speed = T(0), s.accel = T(0);
        s.coast = {};
        s.active = true;
        respawn_at_ = -1;
        invulnerable_until_ = w.time + settings_->invulnerable;
    }

    // A level's large asteroids (all others cleared), away from the ship; with `set_k`, the
    // level's K.
    template <class W>
    void spawn_level(W& w, bool set_k) {
        const GameSettings& g = *settings_;
        level_since = w.time;
        if (set_k && !g.levels.empty()) w.K = T(g.levels[static_cast<std::size_t>(level - 1) % g.levels.size()]);
        for (const Slot& s : asteroids_) body(w, s).active = false;
        const long count = std::min<long>(g.asteroids + static_cast<long>(level - 1) * g.asteroids_step, g.asteroids_max);
        const Body<T>& sh = ship(w);
        for (long k = 0; k < count; ++k) {
            geo::Polar<T> at;
            for (int tries = 0; tries < 8; ++tries) {  // not on top of the ship
                at = {T(static_cast<double>(w.R) * rng_.range(0.35, 0.9)), geo::wrap_pi(T(rng_.range(-3.14159, 3.14159)))};
                if (!sh.active || geo::distance(w.K, at, sh.centre) > T(1)) break;
            }
            const double speed = rng_.range(g.speed_min, g.speed_max), dir = rng_.range(-3.14159, 3.14159);
            spawn_asteroid(w, 0, at, T(speed), T(dir));
        }
    }

    // Spawns an asteroid of `size` at `at` with the given velocity into the first free slot.
    template <class W>
    void spawn_asteroid(W& w, int size, geo::Polar<T> at, T speed, T travel) {
        for (Slot& s : asteroids_) {
            Body<T>& b = body(w, s);
            if (b.active) continue;
            const GameSettings& g = *settings_;
            double rho[kGameMaxVertices], phi[kGameMaxVertices];
            const int n = static_cast<int>(b.local.size());
            const double most = asteroid_outline(rng_, n, g.sizes[size], rho, phi);
            for (int i = 0; i < n; ++i) b.local[static_cast<std::size_t>(i)] = {T(rho[i]), T(phi[i])};
            b.centre = at, b.speed = speed, b.travel = geo::wrap_pi(travel);
            b.facing = geo::wrap_pi(T(rng_.range(-3.14159, 3.14159)));
            b.spin = T(rng_.range(-g.spin_deg, g.spin_deg) * (3.14159265358979323846 / 180));
            b.accel = T(0), b.coast = {}, b.active = true, b.hidden = false, b.wrapped = false;
            ++b.shape, b.serial = ++asteroid_serial_;
            s.size = size, s.radius = T(most), s.born = w.frame;
            return;
        }
    }

    // A hit asteroid: gone, or (large, medium) two of the next size flying apart from its centre.
    template <class W>
    void split(W& w, Slot& s) {
        Body<T>& b = body(w, s);
        b.active = false;
        if (s.size >= 2) return;
        using geo::dot2, geo::hypot, std::atan2, std::cos, std::sin;  // and fx:: ones by ADL for fixed
        const T apart = geo::wrap_pi(T(rng_.range(-3.14159, 3.14159))), push = T(settings_->split_speed);
        const geo::Polar<T> at = b.centre;
        const T speed = b.speed, travel = b.travel;
        const int size = s.size + 1;  // (a piece may take s's own slot, now free)
        for (int k = 0; k < 2; ++k) {
            const T dir = k == 0 ? apart : geo::wrap_pi(apart + geo::pi_v<T>);
            const T vx = dot2(speed, cos(travel), push, cos(dir));
            const T vy = dot2(speed, sin(travel), push, sin(dir));
            spawn_asteroid(w, size, at, hypot(vx, vy), atan2(vy, vx));
        }
    }

    // The 3-vectors of body b's vertices into out, its centre's into c: in a world that draws its
    // bodies otherwise than the constant-K model does (an uneven world, uneven/world.hpp), the
    // vertices it draws, so that what is hit is what is seen.
    template <class W>
    static std::size_t vectors(const W& w, const Body<T>& b, geo::Vec3<T>& c, geo::Vec3<T>* out) {
        const std::size_t n = b.local.size() < kGameMaxVertices ? b.local.size() : kGameMaxVertices;
        if constexpr (requires { w.shape_vectors(b, c, out, n); })
            w.shape_vectors(b, c, out, n);
        else
            geo::body_vectors(w.K, b.centre, b.facing, b.local.data(), n, c, out);
        return n;
    }
    // A world length about body b as the constant-K model measures it (the broad phase's), the
    // same in the world of constant K.
    template <class W>
    static T model_length(const W& w, const Body<T>& b, T length) {
        if constexpr (requires { w.model_length(b, length); })
            return w.model_length(b, length);
        else
            return length;
    }

    template <class W>
    void bullets_hit(W& w, T dt) {
        geo::Vec3<T> verts[kGameMaxVertices], centre;
        for (Slot& u : bullets_) {
            Body<T>& bu = body(w, u);
            if (!bu.active) continue;
            const T step = bu.speed * dt;
            const geo::Vec3<T> q = geo::to_vec(w.K, bu.centre);
            const geo::Vec3<T> p = bu.wrapped ? q : geo::to_vec(w.K, u.prev);  // across the rim: no path
            for (Slot& a : asteroids_) {
                const Body<T>& ab = body(w, a);
                if (!ab.active || a.born == w.frame ||
                    geo::distance(w.K, bu.centre, ab.centre) > model_length(w, ab, a.radius) + model_length(w, bu, step))
                    continue;
                const std::size_t n = vectors(w, ab, centre, verts);
                if (!geo::segment_meets_star(centre, verts, n, p, q)) continue;
                bu.active = false;
                score += settings_->points[a.size];
                emit({GameEvent::hit, bu.serial, ab.serial, 0});
                split(w, a);
                break;
            }
        }
    }

    template <class W>
    void ship_crash(W& w) {
        Body<T>& sh = ship(w);
        if (!sh.active || w.time < invulnerable_until_) return;
        geo::Vec3<T> sv[kGameMaxVertices], sc, av[kGameMaxVertices], ac;
        const std::size_t m = vectors(w, sh, sc, sv);
        for (Slot& a : asteroids_) {
            const Body<T>& ab = body(w, a);
            if (!ab.active || geo::distance(w.K, sh.centre, ab.centre) > model_length(w, ab, a.radius) + model_length(w, sh, nose_))
                continue;
            const std::size_t n = vectors(w, ab, ac, av);
            if (!geo::polygons_overlap(ac, av, n, sc, sv, m)) continue;
            emit({GameEvent::crash, 0, ab.serial, 0});
            split(w, a);
            sh.active = false;
            if (--lives > 0) {
                respawn_at_ = w.time + settings_->respawn_delay;
            } else {
                phase = GamePhase::over, phase_since = w.time;
                emit({GameEvent::over, 0, 0, score});
            }
            return;
        }
    }

    // A bullet from the ship's nose along its facing, with the ship's velocity added (both in
    // the tangent plane at the ship's centre), carried to the nose along the facing.
    template <class W>
    void shoot(W& w) {
        for (Slot& u : bullets_) {
            Body<T>& b = body(w, u);
            if (b.active) continue;
            using geo::dot2, geo::hypot, std::atan2, std::cos, std::sin;  // and fx:: ones by ADL
            const Body<T>& s = ship(w);
            const T v = T(settings_->bullet_speed);
            const T vx = dot2(v, cos(s.facing), s.speed, cos(s.travel));
            const T vy = dot2(v, sin(s.facing), s.speed, sin(s.travel));
            const geo::Walk<T> nose = geo::walk(w.K, s.centre, s.facing, T(nose_));
            const T speed = hypot(vx, vy);
            b.centre = nose.end;
            b.speed = speed < T(Ranges::kSpeed) ? speed : T(Ranges::kSpeed);
            b.travel = b.facing = geo::wrap_pi((speed != T(0) ? atan2(vy, vx) : s.facing) + nose.turn);
            b.coast = {}, b.active = true, b.hidden = false, b.wrapped = false, b.serial = ++bullet_serial_;
            u.travelled = T(0), u.prev = b.centre;
            next_shot_ = w.time + settings_->bullet_cooldown;
            return;
        }
    }

    const GameSettings* settings_ = nullptr;
    bool on_ = false, starting_ = false;
    int ship_ = -1;
    T nose_{};  // the ship's largest rho: where bullets start, and its bounding radius
    std::vector<Slot> asteroids_, bullets_;
    GameRandom rng_;
    uint32_t asteroid_serial_ = 0, bullet_serial_ = 0;
    double next_shot_ = 0, respawn_at_ = -1, level_at_ = -1, invulnerable_until_ = 0;
    GameEvent events_[kGameEvents];
    int events_n_ = 0;
};

}  // namespace noneuclid::world
