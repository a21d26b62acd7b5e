// The law of gravity on a surface of constant curvature K in [-1, 1] (docs/gravity.md): the
// curvature's cotangent ctn_K, and each law's potential U(d) and attraction dU/dd between two
// bodies a distance d apart (the force -grad U points at the other body with that length), with a softening length eps. Written for every K including 0 in
// one formula (no 1/sqrt|K|, no branch on the sign of K), templated on the scalar
// (geometry/scalar.hpp): standard functions are called unqualified after `using std::...`.
//
// Why the cotangent is the default. Gravity's potential is the one that is harmonic away from
// the mass (Gauss's law), and the space it is harmonic in is the three-dimensional space of the
// same curvature, S³ or H³, on which our surface lies as a totally geodesic plane. A function of
// the distance d alone in that 3-space is harmonic when (S_K(d)^2 U')' = 0, so U' ∝ 1/S_K(d)^2
// and U ∝ -C_K(d)/S_K(d) = -ctn_K(d): Newton's inverse square with the curved sphere's area
// 4 pi S_K(d)^2 in place of 4 pi d^2 (Serret 1860, Schering 1870, Killing 1885; Kozlov and Harin,
// Celest. Mech. Dyn. Astr. 54, 1992; Diacu, "Relative equilibria of the curved N-body problem",
// 2012). It is the only central law on S² and H² besides the oscillator whose bounded orbits all
// close (Bertrand's theorem carries over), and it tends to Newton's -1/d as K -> 0.
// The surface's own two-dimensional Gauss law (a circle's length 2 pi S_K(d) in place of the
// sphere's area) gives a force ∝ 1/S_K(d) and a logarithmic potential: offered as `logarithmic`.
// `newton` (force 1/d^2 with the geodesic distance d) is Newton's formula copied onto the curved
// surface unchanged: not harmonic in anything, and its orbits precess, which is what it is for.
#pragma once

#include <cmath>

#include "geometry/model.hpp"

namespace noneuclid::gravity {

enum class Law {
    cotangent,    // U = -ctn_K(d): harmonic in the 3-space of curvature K (the default)
    newton,       // U = -1/d on the curved surface: precesses
    logarithmic,  // U = log(2 T_K(d/2)): harmonic on the surface itself (2D Gauss)
};

// ctn_K(d) = C_K(d) / S_K(d): sqrt K cot(sqrt K d) (K > 0), 1/d (K = 0), sqrt -K coth(sqrt -K d)
// (K < 0), one formula since S_K and C_K are (geometry/model.hpp). Infinite at d = 0.
template <class T>
T ctn_K(T K, T d) {
    return geo::C_K(K, d) / geo::S_K(K, d);
}

// A pair's law in the terms the embedding gives for free (gravity/system.hpp): c = C_K(d) =
// <p, q> and s = S_K(d), the length of the tangent vector q - c p at p. The potential is
// U = G m1 m2 `potential` and the force on the body at p is G m1 m2 `pull` (q - c p), a vector
// along the geodesic towards q of length G m1 m2 `pull` s = dU/dd. `pull` carries no 1/s, so a
// softened pair is finite even when the bodies meet.
template <class T>
struct PairLaw {
    T potential;
    T pull;
};

// Softening: a close pass would need an ever shorter step, so each law's singular 1/S_K(d)^2
// (or 1/d^2) is rounded off over a length eps, Plummer's way, and the potential is softened to
// match, so that the force is still exactly minus the potential's gradient and the integrator still conserves energy:
//   cotangent:   U = -C_K(d) / sqrt(S_K(d)^2 + eps^2),
//                dU/dd = (1 + K eps^2) S_K(d) / (S_K(d)^2 + eps^2)^(3/2)
//     (differentiate with S_K' = C_K, C_K' = -K S_K and C_K^2 + K S_K^2 = 1);
//   newton:      U = -1 / sqrt(d^2 + eps^2),        dU/dd = d / (d^2 + eps^2)^(3/2);
//   logarithmic: U = log(2 sqrt(S_K(d)^2 + eps^2)) - log(1 + C_K(d)),
//                dU/dd = S_K C_K / (S_K^2 + eps^2) + K S_K / (1 + C_K)
//     (at eps = 0, U = log(2 T_K(d/2)) and the force is 1/S_K(d): on the sphere it is infinite
//     at the antipode too, where the 2D law puts the mass's mirror image; softening does not
//     help there).
// All three are Newton's (or the plane's log) softened the usual way at K = 0. At eps = 0 the
// cotangent and newton laws are singular at d = 0 (the bodies must not meet). At the sphere's
// antipode (s = 0, c = -1) the cotangent's pull vanishes (q - c p = 0: the potential has a
// repulsive singularity there that eps rounds off), newton's direction is undefined
// (infinite `pull`).
template <class T>
PairLaw<T> pair_law(Law law, T K, T s, T c, T eps) {
    using std::log, std::sqrt;
    const T e2 = eps * eps;
    const T q = s * s + e2;
    switch (law) {
    case Law::newton: {
        const T d = geo::arc_K(K, s, c);
        const T dd = d * d;
        const T root = sqrt(dd + e2);
        // dU/dd / s = d / (s (d^2 + eps^2)^(3/2)), and d / s = 1 / Sf(K d^2) (no 0/0 at d = 0).
        using geo::Sf;
        return {T(-1) / root, T(1) / (Sf(K * dd) * root * (dd + e2))};
    }
    case Law::logarithmic:
        return {T(0.5) * log(T(4) * q) - log(T(1) + c), c / q + K / (T(1) + c)};
    case Law::cotangent:
    default: {
        const T root = sqrt(q);
        return {-c / root, (T(1) + K * e2) / (root * q)};
    }
    }
}

// The same potential and force as functions of the distance d (for plots, instruments and the
// tests): U(d) / (G m1 m2) and the attraction dU/dd / (G m1 m2).
template <class T>
T potential(Law law, T K, T d, T eps = T(0)) {
    return pair_law(law, K, geo::S_K(K, d), geo::C_K(K, d), eps).potential;
}
template <class T>
T force(Law law, T K, T d, T eps = T(0)) {
    const T s = geo::S_K(K, d);
    return pair_law(law, K, s, geo::C_K(K, d), eps).pull * s;
}

// The speed of a circular orbit of radius a around a fixed mass M (cotangent law, eps = 0):
//   v^2 = G M / (S_K(a) C_K(a)).
// A circle of radius a about O is not a geodesic. Its tangent turns, in all, by 2 pi minus K
// times the disc's area 2 pi (1 - C_K(a)) / K (Gauss-Bonnet), that is by 2 pi C_K(a), over its
// length 2 pi S_K(a): its geodesic curvature is kappa = C_K(a) / S_K(a) = ctn_K(a). Keeping a
// body on it at speed v needs an acceleration v^2 kappa towards O, and the pull is
// G M / S_K(a)^2: v^2 ctn_K(a) = G M / S_K(a)^2. On the sphere C_K(a) falls to 0 a quarter of
// the way round (the equator, a = pi / (2 sqrt K)),
// where the circle is a geodesic and needs no pull at all, and is negative beyond, where the
// circle bends away from O: an attraction towards O cannot hold a body on it, so no circle past
// the equator is an orbit. Returns v^2, or a negative number when there is none.
template <class T>
T circular_speed_squared(T K, T GM, T a) {
    const T c = geo::C_K(K, a);
    return c > T(0) ? GM / (geo::S_K(K, a) * c) : T(-1);
}

}  // namespace noneuclid::gravity
