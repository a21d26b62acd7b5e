// The three-dimensional world's state and its step (docs/space.md): bodies (the Platonic solids
// of space/polyhedra.hpp, and the ship) with a position, a frame carried by parallel transport,
// a velocity (a speed along a carried direction of travel) and a spin, in a space of curvature K
// that the curvature actions turn while they move, as the 2D world does:
//  1. the ship: thrust adds thrust * dt along its forward to its velocity (as vectors at the
//     ship, the 2D rule), left and right turn its frame about its up (yaw), pitch up and down
//     about its right (up: forward toward up), roll left and right about its forward;
//  2. every body flies speed * dt along its travel (the travel and the frame carried, so a
//     spinning body still coasts along one geodesic), and
//  3. its spin turns its frame about its axis (in the frame's own coordinates): both from the
//     start of its coast, the stretch since its velocity, K or the limit sphere last changed it:
//     the walk of speed * (time on the coast) from where the coast began, its frame turned by
//     spin * (time) about the axis and then carried (the two commute: the spin is in the body's
//     own coordinates, the carrying in the world's). So a frame's roundings do not add up over
//     the frames, which in fixed point (Q16.16) would move a body pixels in seconds;
//  4. the limit sphere: a centre past R reappears at (2R - r, -u), its frame unchanged in the
//     carried coordinates. At K > 0 with R = pi / sqrt K that is exactly the geodesic going on
//     through the antipode (tested against the embedding).
// A kiosk has six buttons (thrust, left, right, curvature up and down, fire), and there is no
// shot here: fire is the shift. While it is held, left and right roll and the curvature buttons
// pitch (up: the nose rises), and K stays.
// Changing K leaves every body's (r, u) and frame as they are (the paper's rule); held curvature
// up and down change K by `curvature_rate` a second within [-1, 1]; the presets set K = -1, 0, 1;
// reset restores the start. At K > 0 the limit distance in force is min(R, pi / sqrt K). Nothing
// reads a clock or a random number: the same actions give the same world, bit for bit.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "space/polyhedra.hpp"
#include "world/action.hpp"

namespace noneuclid::space {

template <class T>
struct Body {
    int solid = 0;  // its shape: kSolids[solid]
    T size{};       // its circumradius
    Point<T> at;
    Frame<T> frame;
    V3<T> travel{T(1), T(0), T(0)};      // the direction of travel, a carried unit vector
    T speed{};                           // along travel, units a second
    V3<T> spin_axis{T(0), T(0), T(1)};   // in the frame's own coordinates (forward, left, up)
    T spin{};                            // radians a second, right-handed about the axis
    uint8_t color[3] = {220, 225, 235};
    bool ship = false;                   // the body the ship's actions steer (the first one)

    // Its coast (step 2): where the geodesic it is on began, and for how long it has been on it.
    struct Coast {
        Point<T> at;
        V3<T> travel{T(1), T(0), T(0)};
        Frame<T> frame;
        double time = 0;
        bool on = false;
    } coast;
};

// A world's start: its bodies and its constants.
template <class T>
struct Start {
    T K{}, R = T(3);                         // the curvature and the limit distance
    double curvature_rate = 0.5;             // K a second while a curvature action is held
    double thrust = 0.6, turn_rate = 1.8;    // the ship's: units a second squared, radians a second
    double max_speed = 1.5;
    std::vector<Body<T>> bodies;
};

template <class T>
class World {
public:
    using scalar = T;

    explicit World(const Start<T>& start) : start_(start) { reset(); }

    T K{}, R{};
    double time = 0;
    long frame = 0;
    std::vector<Body<T>> bodies;

    const Start<T>& start() const { return start_; }
    // The limit distance in force: R, or at K > 0 the antipode if nearer.
    T limit() const {
        using std::sqrt;
        if (!(K > T(0))) return R;
        const T antipode = geo::pi_v<T> / sqrt(K);
        return antipode < R ? antipode : R;
    }

    bool held(world::Action a) const { return held_[static_cast<int>(a)]; }
    void press(world::Action a) {
        using world::Action;
        held_[static_cast<int>(a)] = true;
        switch (a) {
            case Action::hyperbolic: K = T(-1); break;
            case Action::flat: K = T(0); break;
            case Action::spherical: K = T(1); break;
            case Action::preset: K = K < T(-0.5) ? T(0) : K < T(0.5) ? T(1) : T(-1); break;  // -1, 0, 1 in turn
            case Action::reset: reset(); break;
            default: break;
        }
    }
    void release(world::Action a) { held_[static_cast<int>(a)] = false; }

    void reset() {
        K = start_.K, R = start_.R, time = 0, frame = 0, bodies = start_.bodies, last_K_ = K;
        for (bool& h : held_) h = false;
    }

    void step(double dt) {
        using world::Action;
        const double dk = shifted() ? 0 : (held(Action::curvature_up) ? 1 : 0) - (held(Action::curvature_down) ? 1 : 0);
        if (dk != 0) {
            const double k = static_cast<double>(K) + dk * start_.curvature_rate * dt;
            K = T(k < -1 ? -1 : (k > 1 ? 1 : k));
        }
        const bool turned_K = K != last_K_;
        last_K_ = K;
        for (Body<T>& b : bodies) {
            if ((b.ship && steer(b, dt)) || turned_K) b.coast.on = false;
            if (b.speed != T(0) || b.spin != T(0)) move(b, dt);
            if (settle(b)) b.coast.on = false;
        }
        time += dt, ++frame;
    }

private:
    // Whether the ship's velocity or frame changed.
    bool steer(Body<T>& b, double dt) {
        using world::Action;
        const bool thrust = held(Action::thrust);
        if (thrust) {  // velocity += thrust dt along forward, at most max_speed
            const V3<T> v = b.speed * b.travel + T(start_.thrust * dt) * b.frame.forward;
            const T speed = norm(v);
            b.travel = unit(v, b.frame.forward);
            b.speed = speed < T(start_.max_speed) ? speed : T(start_.max_speed);
        }
        const bool shift = shifted();
        const auto rate = [&](bool more, bool less) { return ((more ? 1 : 0) - (less ? 1 : 0)) * start_.turn_rate * dt; };
        const auto with_shift = [&](Action a) { return shift && held(a); };
        const double yaw = shift ? 0 : rate(held(Action::left), held(Action::right)),
                     pitch = rate(held(Action::pitch_up) || with_shift(Action::curvature_up),
                                  held(Action::pitch_down) || with_shift(Action::curvature_down)),
                     roll = rate(held(Action::roll_right) || with_shift(Action::right),
                                 held(Action::roll_left) || with_shift(Action::left));
        Frame<T>& f = b.frame;
        if (yaw != 0) f.forward = turned(f.forward, f.up, T(yaw)), f.right = turned(f.right, f.up, T(yaw));
        if (pitch != 0) f.forward = turned(f.forward, f.right, T(pitch)), f.up = turned(f.up, f.right, T(pitch));
        if (roll != 0) f.up = turned(f.up, f.forward, T(roll)), f.right = turned(f.right, f.forward, T(roll));
        const bool turn = yaw != 0 || pitch != 0 || roll != 0;
        if (turn) f = orthonormal(f);
        return thrust || turn;
    }
    bool shifted() const { return held(world::Action::fire); }
    // The frame f turned by `angle` about the body's spin axis (in f's own coordinates).
    static Frame<T> spun(const Body<T>& b, const Frame<T>& f, T angle) {
        const V3<T> axis = unit(b.spin_axis.x * f.forward + b.spin_axis.z * f.up - b.spin_axis.y * f.right);
        return orthonormal(Frame<T>{turned(f.forward, axis, angle), turned(f.up, axis, angle), turned(f.right, axis, angle)});
    }
    // Steps 2 and 3, from the coast's start (a new coast where the last one ended).
    void move(Body<T>& b, double dt) {
        typename Body<T>::Coast& c = b.coast;
        if (!c.on) c = {b.at, b.travel, b.frame, 0, true};
        c.time += dt;
        // (The turn taken modulo a full one: a body spinning in place keeps one coast for months.)
        const double turn = std::fmod(static_cast<double>(b.spin) * c.time, 2 * 3.14159265358979323846);
        const Frame<T> f = b.spin != T(0) ? spun(b, c.frame, T(turn)) : c.frame;
        if (b.speed == T(0)) {
            b.frame = f;
            return;
        }
        const Walk<T> w = walk(K, c.at, c.travel, T(static_cast<double>(b.speed) * c.time));
        b.at = w.end;
        b.travel = unit(w.heading, c.travel);
        b.frame = orthonormal(Frame<T>{carry(w, f.forward), carry(w, f.up), carry(w, f.right)});
    }
    // (Repeated, for a body that K's turn left more than once round: at K > 0 the limit can
    // shrink to pi / sqrt K under a body far out; each pass brings it 2R nearer.) Whether it moved.
    bool settle(Body<T>& b) const {
        const T R = limit();
        bool moved = false;
        while (b.at.r > R) {
            b.at = {T(2) * R - b.at.r, T(-1) * b.at.u};
            if (b.at.r < T(0)) b.at = {T(-1) * b.at.r, T(-1) * b.at.u};
            moved = true;
        }
        return moved;
    }

    Start<T> start_;
    T last_K_{};
    bool held_[world::kActionCount] = {};
};

}  // namespace noneuclid::space
