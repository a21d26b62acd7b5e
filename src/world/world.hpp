// The world: K, the limit radius R and the bodies, stepped at a fixed timestep by the paper's
// physics, driven by the same actions the kiosk buttons send. Templated on the scalar like the
// geometry; `Paper = true` (double only) moves bodies with the paper's literal formulas.
//
// One step of dt, for every body (the paper, section "movement"):
//  1. acceleration: a body's own (scene files may give one), or for the ship while thrust is
//     held, `thrust` along its facing; velocity += a dt as vectors in the tangent plane at the
//     centre (both are angles in the carried frame there). A coasting body (a = 0) keeps its
//     speed exactly.
//  2. the centre moves speed * dt along the geodesic in its direction of travel; the direction
//     of travel, the facing and the acceleration's direction are carried along (geo::move).
//  3. spin (plus the ship's turn while left/right is held) turns the facing.
//  4. the limit circle: a centre past R reappears at (2R - r, theta + pi), its direction of
//     travel and facing unchanged on screen (the same carried-frame angles). At K > 0 with
//     R = pi/sqrt K this is exactly the geodesic continuing through the antipode (tested).
// Curvature: changing K leaves every body's polar numbers as they are (the paper); held
// curvature up/down changes K by `curvature_rate` per second, clamped to [-1, 1]; next preset
// cycles the scene's presets; reset restores the scene's initial state. Same actions, same
// result, bit for bit: nothing here reads a clock or a random number.
//
// Memory: bodies and their vertices are allocated when the world is built; step() allocates
// nothing.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "fixed/coast.hpp"
#include "geometry/geometry.hpp"
#include "geometry/paper.hpp"
#include "world/ranges.hpp"
#include "world/scene.hpp"

namespace noneuclid::world {

using geo::Polar;
using geo::Pose;

// What the buttons and keys ask of the world. Held actions (thrust, the turns, curvature up and
// down) act while held; the others act once, on the press: the next preset, reset, and K set
// to -1, 0 or +1 (the desktop's keys 1, 2, 3).
enum class Action : uint8_t {
    thrust, turn_left, turn_right, curvature_up, curvature_down, next_preset, reset, hyperbolic, flat, spherical
};
inline constexpr int kActionCount = 10;
inline const char* action_name(Action a) {
    static const char* const names[] = {"thrust",      "left",  "right",      "curvature_up", "curvature_down",
                                        "preset",      "reset", "hyperbolic", "flat",         "spherical"};
    return names[static_cast<int>(a)];
}
// Whether the action acts once on its press (rather than while held).
inline bool acts_on_press(Action a) { return a >= Action::next_preset; }
inline bool parse_action(const std::string& s, Action& out) {
    for (int i = 0; i < kActionCount; ++i)
        if (s == action_name(static_cast<Action>(i))) {
            out = static_cast<Action>(i);
            return true;
        }
    return false;
}

// How a coast keeps its start: in fixed point the distance from O in Q24 and the angles as
// binary angles (fx::angle: a turn adds exactly, and the limit circle's theta + pi and 2R - r
// round nothing); in floating point the scalar itself.
template <class T>
struct CoastNumbers {
    using length = T;
    using angle = T;
    static T length_of(T r) { return r; }
    static T scalar(T r) { return r; }
    static T reflect(T R, T r) { return T(2) * R - r > T(0) ? T(2) * R - r : T(0); }  // 2R - r, or 0
    static T angle_of(T radians) { return radians; }
    static T radians(T a) { return a; }
    static T opposite(T a) { return geo::wrap_pi(a + geo::pi_v<T>); }
};
template <>
struct CoastNumbers<fx::fixed> {
    using length = int64_t;  // Q24
    using angle = fx::angle;
    static length length_of(fx::fixed r) { return int64_t{r.raw()} << 8; }
    static fx::fixed scalar(length r) { return fx::fixed::from_raw(fx::detail::saturate32((r + 128) >> 8)); }
    static length reflect(fx::fixed R, length r) {
        const length twice = int64_t{R.raw()} << 9;
        return twice - r > 0 ? twice - r : 0;
    }
    static angle angle_of(fx::fixed radians) { return angle::from_radians(radians); }
    static fx::fixed radians(angle a) { return a.to_radians(); }
    static angle opposite(angle a) { return a + angle::from_raw(angle::half_turn); }
};

// A coast: the straight stretch a body is on, walked from where it began. While nothing but
// its straight motion acts on a body (the same velocity, the same K, no wrap at the limit
// circle), its centre after distance D is one walk of D from the coast's start, not the last of
// many short walks, so the steps' roundings do not add up: the fixed engine follows the exact
// path (docs/accuracy.md, "The long run"). In fixed point the distance walked is exact (a sum of
// mul_carry's steps), the walk is fx::coast_walk's, and the angles are binary angles.
template <class T>
struct Coast {
    using Numbers = CoastNumbers<T>;
    using Length = typename Numbers::length;
    using Angle = typename Numbers::angle;
    using Distance = std::conditional_t<std::is_same_v<T, float>, double, T>;
    Length r0{};         // the start: distance from O, bearing, heading
    Angle theta0{}, chi0{};
    Distance walked{};   // the distance walked from the start
    T turn{};            // the heading's turn over `walked`, as the facing was turned by it
    T K{};               // the curvature it is walked in
    Length next_r{};     // where the next coast starts (the last step's end, wrapped if it
    Angle next_theta{}, next_chi{};  // was), in the coast's numbers
    Polar<T> left;       // the centre and direction of travel the last step left: a body
    T left_travel{};     // found elsewhere (a change of velocity, a reset) starts a new coast
    bool on = false;     // a coast has been walked
    bool fresh = false;  // the next step starts a new coast at next_* (after a wrap)
};

template <class T>
struct alignas(64) Body {
    Polar<T> centre;
    T facing{}, speed{}, travel{}, accel{}, accel_dir{}, spin{};
    std::vector<Polar<T>> local;  // (rho, phi from the facing), radians
    int64_t step_carry = 0;       // what speed * dt rounding left over (fixed point)
    Coast<T> coast;
    const SceneBody* desc = nullptr;  // name, colour, closed, tessellation, flags
};

// The engine's geometry: the exact forms, or the paper's (double only).
template <class T, bool Paper>
struct Engine {
    static Pose<T> move(T K, Pose<T> p, T d) { return geo::move(K, p, d); }
    static Polar<T> vertex(T K, Polar<T> c, T facing, Polar<T> local) {
        return geo::vertex_position(K, c, facing, local);
    }
    template <class Out>
    static void edge_points(T K, Polar<T> p, Polar<T> q, int n, Out&& out) {
        geo::edge_points(K, p, q, n, out);
    }
};
template <>
struct Engine<double, true> {
    static Pose<double> move(double K, Pose<double> p, double d) { return geo::paper::move(K, p, d); }
    static Polar<double> vertex(double K, Polar<double> c, double facing, Polar<double> local) {
        return geo::paper::vertex_position(K, c, facing, local);
    }
    template <class Out>
    static void edge_points(double K, Polar<double> p, Polar<double> q, int n, Out&& out) {
        out(0, p);
        for (int k = 1; k < n; ++k) out(k, geo::paper::edge_point(K, p, q, static_cast<double>(k) / n));
        out(n, q);
    }
};

template <class T, bool Paper = false>
class World {
    static_assert(!Paper || std::is_same_v<T, double>, "the paper's formulas are double only");

public:
    using scalar = T;
    using engine = Engine<T, Paper>;

    explicit World(const Scene& scene) : scene_(scene) {
        K = T(scene_.curvature);
        R = T(scene_.limit_radius);
        for (const SceneBody& sb : scene_.bodies) bodies.push_back(make_body(sb));
        // desc pointers refer to scene_ (a copy we own): fix them up after the copy above.
        for (std::size_t i = 0; i < bodies.size(); ++i) bodies[i].desc = &scene_.bodies[i];
        initial_ = bodies;
        initial_K_ = K;
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
            case Action::next_preset: next_preset(); break;
            case Action::reset: reset(); break;
            case Action::hyperbolic: K = T(-1); break;
            case Action::flat: K = T(0); break;
            case Action::spherical: K = T(1); break;
            default: break;
        }
    }
    void release(Action a) { held_[static_cast<int>(a)] = false; }

    void step(T dt) {
        const int dk = held(Action::curvature_up) - held(Action::curvature_down);
        if (dk != 0) K = clamp_k(K + T(scene_.curvature_rate) * dt * T(dk));
        if (scene_.sweep_rate != 0) {
            K = K + T(scene_.sweep_rate) * dt * T(sweep_dir_);
            if (K >= T(1)) K = T(1), sweep_dir_ = -1;
            if (K <= T(-1)) K = T(-1), sweep_dir_ = 1;
        }
        const T turn = T(scene_.turn_rate_deg * kDegree) * T(held(Action::turn_left) - held(Action::turn_right));
        const Steering steer{T(scene_.thrust), turn, held(Action::thrust)};
        for (Body<T>& b : bodies) step_body(b, dt, steer);
        time += static_cast<double>(dt);
        ++frame;
    }

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
        bodies = initial_;
        K = initial_K_;
        sweep_dir_ = 1;
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
        bool thrusting = false;
    };
    // One body's step (steps 1-4 above): reads K, R and the body, writes only the body.
    void step_body(Body<T>& b, T dt, const Steering& steer) const {
        using geo::dot2, geo::hypot, geo::mul_carry, geo::wrap_pi;  // and fx:: ones by ADL for fixed
        using std::atan2, std::cos, std::sin;
        T a = b.accel, adir = b.accel_dir;
        if (b.desc->controlled && steer.thrusting) a = steer.thrust, adir = b.facing;
        if (a != T(0)) {  // velocity += a dt, in the tangent plane at the centre
            const T vx = dot2(b.speed, cos(b.travel), a * dt, cos(adir));
            const T vy = dot2(b.speed, sin(b.travel), a * dt, sin(adir));
            b.speed = hypot(vx, vy);
            if (b.speed != T(0)) b.travel = atan2(vy, vx);
            if (b.speed > T(Ranges::kSpeed)) b.speed = T(Ranges::kSpeed);  // the ceiling (ranges.hpp)
        }
        bool walked = false;
        if (b.speed != T(0)) {
            const T d = mul_carry(b.speed, dt, b.step_carry);  // no drift from rounding d
            if constexpr (Paper) {
                const Pose<T> p = engine::move(K, Pose<T>{b.centre, b.travel, b.facing}, d);
                b.accel_dir = wrap_pi(b.accel_dir + (p.facing - b.facing));
                b.centre = p.centre;
                b.travel = p.travel;
                b.facing = p.facing;
            } else {
                coast_step(b, d);
                walked = true;
            }
        }
        const T spin = b.desc->controlled ? b.spin + steer.turn : b.spin;
        if (spin != T(0)) b.facing = wrap_pi(b.facing + spin * dt);
        Coast<T>& c = b.coast;
        using N = typename Coast<T>::Numbers;
        if (b.centre.r > R) {  // the limit circle
            const T r = T(2) * R - b.centre.r;
            if (walked) {  // the next coast starts here, (2R - r, theta + pi) in the coast's numbers
                c.next_r = N::reflect(R, c.next_r), c.next_theta = N::opposite(c.next_theta), c.fresh = true;
                b.centre = {N::scalar(c.next_r), N::radians(c.next_theta)};
            } else {
                b.centre = {r > T(0) ? r : T(0), wrap_pi(b.centre.theta + geo::pi_v<T>)};
            }
        }
        c.left = b.centre, c.left_travel = b.travel;
    }
    // Step 2 along the body's coast (Coast). A new coast starts where the body is not where the
    // last step left it, after a wrap, when K has changed, and when the coast would grow longer
    // than kCoastLength (fx::coast_walk's domain); its first step is the plain walk of d.
    void coast_step(Body<T>& b, T d) const {
        using N = typename Coast<T>::Numbers;
        using Distance = typename Coast<T>::Distance;
        Coast<T>& c = b.coast;
        const bool ours = c.on && c.left.r == b.centre.r && c.left.theta == b.centre.theta && c.left_travel == b.travel;
        if (!ours) {
            c.next_r = N::length_of(b.centre.r);
            c.next_theta = N::angle_of(b.centre.theta), c.next_chi = N::angle_of(b.travel);
        }
        if (!ours || c.fresh || !(c.K == K) || c.walked + Distance(d) > Distance(kCoastLength)) {
            c.r0 = c.next_r, c.theta0 = c.next_theta, c.chi0 = c.next_chi;
            c.walked = Distance{}, c.turn = T(0), c.K = K, c.on = true, c.fresh = false;
        }
        c.walked = c.walked + Distance(d);
        typename Coast<T>::Length r{};
        typename Coast<T>::Angle theta{}, chi{};
        T turn{};
        coast_walk(c, r, theta, chi, turn);
        const T facing = geo::wrap_pi(b.facing + (turn - c.turn));
        b.accel_dir = geo::wrap_pi(b.accel_dir + (facing - b.facing));
        b.facing = facing;
        b.centre = {N::scalar(r), N::radians(theta)};
        b.travel = N::radians(chi);
        c.turn = turn, c.next_r = r, c.next_theta = theta, c.next_chi = chi;
    }
    // Where the coast is after c.walked: distance, bearing and heading in the coast's numbers,
    // and the heading's turn since the start.
    void coast_walk(const Coast<T>& c, typename Coast<T>::Length& r, typename Coast<T>::Angle& theta,
                    typename Coast<T>::Angle& chi, T& turn) const {
        if constexpr (std::is_same_v<T, fx::fixed>) {
            fx::CoastEnd e;
            if (fx::coast_walk(K, c.r0, c.chi0 - c.theta0, c.walked, e)) {
                r = e.r24, theta = c.theta0 + e.bearing, chi = c.chi0 + e.turn, turn = e.turn.to_radians();
                return;
            }
            // Outside its domain (a world built with R > sqrt 10, or K beyond +-1): geo::walk.
            using N = typename Coast<T>::Numbers;
            const Polar<T> start{N::scalar(c.r0), c.theta0.to_radians()};
            const geo::Walk<T> w = geo::walk(K, start, c.chi0.to_radians(), c.walked);
            r = N::length_of(w.end.r), theta = N::angle_of(w.end.theta), chi = N::angle_of(w.heading), turn = w.turn;
        } else {
            const geo::Walk<T> w = geo::walk(K, Polar<T>{c.r0, c.theta0}, c.chi0, T(c.walked));
            r = w.end.r, theta = w.end.theta, chi = w.heading, turn = w.turn;
        }
    }
    static constexpr double kCoastLength = 3;  // within fx::coast_walk's sqrt 10

    static T clamp_k(T k) { return k < T(-1) ? T(-1) : (k > T(1) ? T(1) : k); }
    Body<T> make_body(const SceneBody& sb) const {
        Body<T> b;
        b.centre = {T(sb.r), geo::wrap_pi(T(sb.theta_deg * kDegree))};
        b.facing = geo::wrap_pi(T(sb.facing_deg * kDegree));
        b.speed = T(sb.speed);
        b.travel = geo::wrap_pi(T(sb.direction_deg * kDegree));
        b.accel = T(sb.accel);
        b.accel_dir = geo::wrap_pi(T(sb.accel_direction_deg * kDegree));
        b.spin = T(sb.spin_deg * kDegree);
        for (const SceneBody::Vertex& v : sb.vertices) b.local.push_back({T(v.rho), T(v.phi_deg * kDegree)});
        return b;
    }
    void copy_from(const World& o) {
        K = o.K, R = o.R, time = o.time, frame = o.frame;
        bodies = o.bodies;
        initial_ = o.initial_;
        initial_K_ = o.initial_K_;
        sweep_dir_ = o.sweep_dir_;
        for (int i = 0; i < kActionCount; ++i) held_[i] = o.held_[i];
        for (std::size_t i = 0; i < bodies.size(); ++i) bodies[i].desc = initial_[i].desc = &scene_.bodies[i];
    }

    Scene scene_;
    std::vector<Body<T>> initial_;
    T initial_K_{};
    int sweep_dir_ = 1;
    bool held_[kActionCount] = {};
};

}  // namespace noneuclid::world
