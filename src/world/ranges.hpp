// The engines' ranges: what a scene may hold so that every engine (fixed, double, float, paper)
// gives a finite picture at every K in [-1, 1], and the fixed engine stays within its stated
// tolerance of double (docs/reliability.md, "Ranges"). K can change while the world runs (the
// curvature buttons, presets, the sweep), so a scene is checked against the whole range of K,
// not only its own.
#pragma once

#include <string>

#include "world/scene.hpp"

namespace noneuclid::world {

struct Ranges {
    // The largest limit radius R: pi, the paper's, where at K = 1 the disc is the whole sphere.
    // Inside it the fixed engine draws within half a pixel of double at 1920x1080
    // (tests/render/test_ranges.cpp, bodies within kBodyRadius); past it the antipode (K > 0) and the Q16.16 hyperbolic
    // functions (K < 0) leave that tolerance.
    static constexpr double kLimitRadius = 3.14159265358979323846;
    // Every point of a world lies within this distance of O: 2 pi. Past it at K = -1 the fixed
    // engine's Q16.16 hyperbolic functions lose their precision (docs/accuracy.md), and the
    // double engine's cosine rule its digits, long before either overflows.
    static constexpr double kReach = 6.283185307179586;
    // The largest distance of a body's vertex from its centre (grid lines aside, whose edges are
    // their step): 1.4, 80 degrees of the sphere at K = 1, so that no edge joins two points near
    // opposite each other (where the great circle it takes is decided by rounding), and at
    // K = -1 no edge is long enough for the fixed engine to leave the tolerance above.
    static constexpr double kBodyRadius = 1.4;
    // The fastest a body moves, world units per second: acceleration and thrust stop there.
    // A step (1/60 s) is then at most a third of a unit.
    static constexpr double kSpeed = 20;
    // An uneven world's bumps (src/uneven, docs/uneven.md): at most kBumps; each width from
    // kBumpWidth[0] to [1] chart units (narrower, the integrator's step would need to shrink
    // with it); a hill's strength within +-kHill (e^1.5: lengths 4.5 times stretched at its top)
    // and a mass's within +-kMass (a cone of 2 pi alpha; at 1 its apex would be a cylinder's
    // end). Centres within kBumpReach of O: the chart the uneven world runs in reaches 120
    // degrees of the sphere at K = 1.
    static constexpr int kBumps = 8;
    static constexpr double kBumpWidth[2] = {0.1, 3.0};
    static constexpr double kHill = 1.5, kMass = 0.9;
    static constexpr double kBumpReach = 2 * 3.14159265358979323846 / 3;
    // The gain of the strength keys: at most this (or where a bump reaches its range first).
    static constexpr double kGain = 2;
};

// Whether the body ever moves (a velocity, an acceleration, the ship's thrust, or a game's
// asteroid or bullet).
bool body_moves(const SceneBody& b);

// How far from O the body's farthest vertex can get: its centre, or for a body that moves
// anywhere up to the limit radius R, plus its largest vertex distance rho.
double body_reach(const SceneBody& b, double R);

// Whether one body is within the ranges: its centre inside the limit circle, its vertices
// within kBodyRadius of it (a grid line's excepted), its reach within kReach, its speed within
// kSpeed; false with a sentence in `why` (no full stop) that ends with what to change.
// (key, if given: the scene file's key of the value out of range, for the place an error names.)
bool body_within_ranges(const SceneBody& b, double R, std::string& why, const char** key = nullptr);

// Whether bump `index` (from 0) of an uneven world is within the ranges above, the scene's
// limit radius and the count; false with a sentence in `why` (no full stop) that ends with what
// to change. And whether an uneven scene's bodies sit where the chart has a point and it asks
// for nothing the uneven world has not (an instrument but a triangle).
bool bump_within_ranges(const SceneBump& b, int index, const Scene& scene, std::string& why);
bool uneven_scene_fits(const Scene& scene, std::string& why);
// The most the strength keys' gain may reach: kGain, or where a bump would leave its range.
double bump_gain_most(const Scene& scene);

// The same for every body of the scene, the sentence naming the first body out of range.
bool within_ranges(const Scene& scene, std::string& why);

}  // namespace noneuclid::world
