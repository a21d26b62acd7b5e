// A body's coast: the straight stretch it is on, walked from where it began (docs/accuracy.md,
// "The long run"). While nothing but its own motion moves a body (the same direction of travel,
// the same K, no wrap at the limit circle), its centre after distance D is one walk of D from
// the coast's start, not the last of many short walks, so the steps' roundings do not add up.
// In fixed point the start is kept in finer numbers than Q16.16 (r in Q24, the angles as binary
// angles: a turn adds exactly, and the limit circle's theta + pi and 2R - r round nothing), the
// distance walked is the exact sum of the steps' speed * dt (dt the step's exact share of the
// world's clock, Tick), and the walk is fx::coast_walk's.
// The exact engine (geometry/engine.hpp) moves bodies this way. A body here is anything with
// centre, travel, facing, accel_dir, speed and a Coast<T> `coast` (world::Body).
#pragma once

#include <cstdint>
#include <type_traits>

#include "geometry/fx/coast.hpp"
#include "geometry/geometry.hpp"

namespace noneuclid::geo {

// The longest coast, in world units: within fx::coast_walk's domain (sqrt 10).
inline constexpr int kCoastLength = 3;

// One step's time, as the world's clock gives it (world::World::step): dt in the scalar, for
// what is rounded once a step. In fixed point dt = 1/60 s is 1092/65536 in Q16.16, 0.015%
// short, so the step also carries its exact share of the clock in Q32 seconds, q32: the
// differences of the clock read in Q32, which add up to the clock to within 2^-32 s however
// many steps there are. What moves at a rate (speed * dt along a coast, spin * dt) is taken
// from q32 with its remainder carried to the next step, so that it follows the clock.
template <class T>
struct Tick {
    T dt{};
};
template <>
struct Tick<fx::fixed> {
    fx::fixed dt{};
    int64_t q32 = 0;
};

// rate * dt, rounded once (an acceleration's a dt, K's change in a step): in fixed point from
// the step's exact time, not from its Q16.16 dt.
template <class T>
T times_dt(T rate, const Tick<T>& t) {
    if constexpr (std::is_same_v<T, fx::fixed>) {
        const int64_t q48 = int64_t{rate.raw()} * t.q32;  // |raw| < 2^31 and q32 <= 2^32 (dt <= 1 s)
        return fx::fixed::from_raw(fx::detail::saturate32((q48 + (int64_t{1} << 31)) >> 32));
    } else {
        return rate * t.dt;
    }
}

// Turns `angle` by rate * dt, wrapped into (-pi, pi]. In fixed point the turn is taken from
// the step's exact time and the angle is kept, between steps, to Q48 radians: `rest` carries
// what lies below its Q16.16 step, so that a slow spin turns at its rate (not at zero, nor at
// its rounding's), and a turn past pi wraps by 2 pi in Q48, not by Q16.16's rounded 2 pi. Floating
// point rounds too little to need it.
template <class T>
T turn_by(T angle, T rate, const Tick<T>& t, int64_t& rest) {
    if constexpr (std::is_same_v<T, fx::fixed>) {
        constexpr int64_t kPiQ48 = 884279719003555;       // pi * 2^48
        constexpr int64_t kTwoPiQ48 = 1768559438007110;   // 2 pi * 2^48
        // |rate raw| < 2^31 and q32 <= 2^32 (dt <= 1 s): the product is within 64 bits.
        int64_t q48 = ((int64_t{angle.raw()} << 32) + rest) % kTwoPiQ48 + int64_t{rate.raw()} * t.q32 % kTwoPiQ48;
        if (q48 > kPiQ48) q48 -= kTwoPiQ48;
        if (q48 > kPiQ48) q48 -= kTwoPiQ48;
        if (q48 <= -kPiQ48) q48 += kTwoPiQ48;
        if (q48 <= -kPiQ48) q48 += kTwoPiQ48;
        const int64_t whole = (q48 + (int64_t{1} << 31)) >> 32;  // Q16, rounded
        rest = q48 - (whole << 32);
        return fx::fixed::from_raw(static_cast<int32_t>(whole));
    } else {
        (void)rest;
        return wrap_pi(angle + rate * t.dt);
    }
}

// How a coast keeps its numbers: in floating point the scalar itself (float's distance walked
// in double, where its steps add exactly); in fixed point r in Q24, the angles as binary angles
// and the distance walked in Q48, where speed (Q16) * the step's exact time (Q32) is exact.
template <class T>
struct CoastNumbers {
    using length = T;
    using angle = T;
    using distance = std::conditional_t<std::is_same_v<T, float>, double, T>;
    static T length_of(T r) { return r; }
    static T scalar(T r) { return r; }
    static T reflect(T R, T r) { return T(2) * R - r > T(0) ? T(2) * R - r : T(0); }  // 2R - r, or 0
    static T angle_of(T radians) { return radians; }
    static T radians(T a) { return a; }
    static T opposite(T a) { return wrap_pi(a + pi_v<T>); }
    static distance step(T speed, const Tick<T>& t) { return distance(speed) * distance(t.dt); }
    static distance longest() { return distance(kCoastLength); }
    struct start {};  // what every walk of a coast shares: nothing here
    static start begin(T, T, T, T) { return {}; }
};
template <>
struct CoastNumbers<fx::fixed> {
    using length = int64_t;    // Q24
    using angle = fx::angle;
    using distance = int64_t;  // Q48: at most 3 units, 2^50
    static length length_of(fx::fixed r) { return int64_t{r.raw()} << 8; }
    static fx::fixed scalar(length r) { return fx::fixed::from_raw(fx::detail::saturate32((r + 128) >> 8)); }
    static length reflect(fx::fixed R, length r) {
        const length twice = int64_t{R.raw()} << 9;
        return twice - r > 0 ? twice - r : 0;
    }
    static angle angle_of(fx::fixed radians) { return angle::from_radians(radians); }
    static fx::fixed radians(angle a) { return a.to_radians(); }
    static angle opposite(angle a) { return a + angle::from_raw(angle::half_turn); }
    static distance step(fx::fixed speed, const Tick<fx::fixed>& t) { return int64_t{speed.raw()} * t.q32; }
    static distance longest() { return int64_t{kCoastLength} << 48; }
    using start = fx::CoastStart;
    static start begin(fx::fixed K, length r0, angle theta0, angle chi0) {
        return fx::coast_start(K, r0, chi0 - theta0);
    }
};

template <class T>
struct Coast {
    using Numbers = CoastNumbers<T>;
    using Length = typename Numbers::length;
    using Angle = typename Numbers::angle;
    using Distance = typename Numbers::distance;
    Length r0{};         // the start: distance from O, bearing, heading
    Angle theta0{}, chi0{};
    [[no_unique_address]] typename Numbers::start start{};  // what its walks share
    Distance walked{};   // the distance walked from the start
    T turn{};            // the heading's turn over `walked`, as the facing was turned by it
    T K{};               // the curvature it is walked in
    Length next_r{};     // where the next coast starts (the last step's end, wrapped if it
    Angle next_theta{}, next_chi{};  // was), in the coast's numbers
    Polar<T> left;  // the centre and direction of travel the last step left: a body
    T left_travel{};     // found elsewhere (a change of velocity, a reset) starts a new coast
    bool on = false;     // a coast has been walked
    bool fresh = false;  // the next step starts a new coast at next_* (after a wrap)
};

// Where coast c is after c.walked at K: distance, bearing and heading in the coast's numbers,
// and the heading's turn since the start.
template <class T>
void walk_coast(T K, const Coast<T>& c, typename Coast<T>::Length& r, typename Coast<T>::Angle& theta,
                typename Coast<T>::Angle& chi, T& turn) {
    if constexpr (std::is_same_v<T, fx::fixed>) {
        fx::CoastEnd e;
        if (fx::coast_walk(c.start, (c.walked + (int64_t{1} << 23)) >> 24, e)) {
            r = e.r24, theta = c.theta0 + e.bearing, chi = c.chi0 + e.turn, turn = e.turn.to_radians();
            return;
        }
        // Outside its domain (a step longer than sqrt 10, or K beyond +-1): walk.
        using N = typename Coast<T>::Numbers;
        const Polar<T> start{N::scalar(c.r0), c.theta0.to_radians()};
        const fx::fixed D = fx::fixed::from_raw(fx::detail::saturate32((c.walked + (int64_t{1} << 31)) >> 32));
        const Walk<T> w = walk(K, start, c.chi0.to_radians(), D);
        r = N::length_of(w.end.r), theta = N::angle_of(w.end.theta), chi = N::angle_of(w.heading), turn = w.turn;
    } else {
        const Walk<T> w = walk(K, Polar<T>{c.r0, c.theta0}, c.chi0, T(c.walked));
        r = w.end.r, theta = w.end.theta, chi = w.heading, turn = w.turn;
    }
}

// Step 2 of World::step_body along body b's coast: speed * dt further at K. A new coast starts
// where the body is not where the last step left it, after a wrap, when K has changed, and when
// the coast would grow longer than kCoastLength; its first step is the plain walk of the step.
template <class T, class Body>
void coast_step(T K, Body& b, const Tick<T>& dt) {
    using N = CoastNumbers<T>;
    Coast<T>& c = b.coast;
    const bool ours = c.on && c.left.r == b.centre.r && c.left.theta == b.centre.theta && c.left_travel == b.travel;
    if (!ours) {
        c.next_r = N::length_of(b.centre.r);
        c.next_theta = N::angle_of(b.centre.theta), c.next_chi = N::angle_of(b.travel);
    }
    const typename N::distance step = N::step(b.speed, dt);
    if (!ours || c.fresh || !(c.K == K) || c.walked + step > N::longest()) {
        c.r0 = c.next_r, c.theta0 = c.next_theta, c.chi0 = c.next_chi;
        c.start = N::begin(K, c.r0, c.theta0, c.chi0);
        c.walked = typename N::distance{}, c.turn = T(0), c.K = K, c.on = true, c.fresh = false;
    }
    c.walked = c.walked + step;
    typename N::length r{};
    typename N::angle theta{}, chi{};
    T turn{};
    walk_coast(K, c, r, theta, chi, turn);
    const T facing = wrap_pi(b.facing + (turn - c.turn));
    b.accel_dir = wrap_pi(b.accel_dir + (facing - b.facing));
    b.facing = facing;
    b.centre = {N::scalar(r), N::radians(theta)};
    b.travel = N::radians(chi);
    c.turn = turn, c.next_r = r, c.next_theta = theta, c.next_chi = chi;
}

// The limit circle's wrap of a centre that has just walked its coast: the next coast starts at
// (2R - r, theta + pi) in the coast's numbers; returns that centre.
template <class T>
Polar<T> coast_wrap(Coast<T>& c, T R) {
    using N = CoastNumbers<T>;
    c.next_r = N::reflect(R, c.next_r), c.next_theta = N::opposite(c.next_theta), c.fresh = true;
    return {N::scalar(c.next_r), N::radians(c.next_theta)};
}

}  // namespace noneuclid::geo
