#include "world/ranges.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "world/quote.hpp"

namespace noneuclid::world {

namespace {
std::string number(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.4g", v);
    return s;
}
}  // namespace

bool body_moves(const SceneBody& b) {
    return b.speed > 0 || b.accel > 0 || b.controlled || b.role != BodyKind::body;  // a game's slots move
}

double body_reach(const SceneBody& b, double R) {
    double rho = 0;
    for (const SceneBody::Vertex& v : b.vertices)
        rho = std::max(rho, v.rho);
    return (body_moves(b) ? std::max(b.r, R) : b.r) + rho;
}

bool body_within_ranges(const SceneBody& b, double R, std::string& why, const char** key) {
    auto at = [&](const char* k) {
        if (key) *key = k;
    };
    const std::string name = "body " + quote(b.name) + ": ";
    if (b.r > R) {
        why = name + "its position r = " + number(b.r) + " is outside the limit circle (limit_radius = " + number(R)
              + "): place it at r <= " + number(R);
        at("position");
        return false;
    }
    if (b.speed > Ranges::kSpeed) {
        why = name + "its speed " + number(b.speed) + " is over the ceiling of " + number(Ranges::kSpeed)
              + " world units per second: give a speed of at most that";
        at("speed");
        return false;
    }
    if (!b.grid)
        for (const SceneBody::Vertex& v : b.vertices)
            if (v.rho > Ranges::kBodyRadius) {
                why = name + "a vertex at rho = " + number(v.rho) + " from its centre, over the "
                      + number(Ranges::kBodyRadius)
                      + " a body may span (80 degrees of the sphere at K = 1): make the body smaller";
                at("vertices");
                return false;
            }
    const double reach = body_reach(b, R);
    if (reach > Ranges::kReach) {
        const bool moves = body_moves(b);
        why = name + "its vertices could reach " + number(reach) + " from O ("
              + (moves ? "limit_radius" : "its distance r")
              + " plus its largest rho), past the engines' reach of 2 pi (6.283): make the body smaller or "
              + (moves ? "limit_radius" : "r") + " lower";
        at("vertices");
        return false;
    }
    return true;
}

bool bump_within_ranges(const SceneBump& b, int index, const Scene& scene, std::string& why) {
    const std::string name = std::string("bump ") + std::to_string(index + 1) + " (" + (b.mass ? "mass" : "hill") + "): ";
    if (index >= Ranges::kBumps) {
        why = name + "a scene may have at most " + std::to_string(Ranges::kBumps) + " bumps: remove some";
        return false;
    }
    const double reach = std::min(scene.limit_radius, Ranges::kBumpReach);
    if (!(b.r >= 0 && b.r <= reach)) {
        why = name + "its centre at r = " + number(b.r) + " is outside the world, which reaches " + number(reach) +
              " (the limit radius, or 120 degrees of the sphere at K = 1): move it nearer O";
        return false;
    }
    if (!(b.width >= Ranges::kBumpWidth[0] && b.width <= Ranges::kBumpWidth[1])) {
        why = name + "width = " + number(b.width) + " is outside " + number(Ranges::kBumpWidth[0]) + " to " +
              number(Ranges::kBumpWidth[1]) + ": give a width in that range";
        return false;
    }
    const double most = b.mass ? Ranges::kMass : Ranges::kHill;
    if (!(b.strength >= -most && b.strength <= most)) {
        why = name + "strength = " + number(b.strength) + " is outside -" + number(most) + " to " + number(most) +
              (b.mass ? " (a mass's cone closes up at 1)" : " (a hill stretches lengths e^strength times)") +
              ": give a strength in that range";
        return false;
    }
    return true;
}

bool uneven_scene_fits(const Scene& scene, std::string& why) {
    for (const MeasureDecl& m : scene.measures)
        if (m.kind != geo::Instrument::triangle) {
            why = "a scene with bumps measures triangles only (src/uneven): remove the [[measure]] " +
                  std::string(geo::instrument_name(m.kind)) + ", or the bumps";
            return false;
        }
    // The chart has no point at the sphere's antipode: the uneven world's limit circle stops
    // short of it (uneven/world.hpp), at 120 degrees of the sphere.
    const double cut = scene.curvature > 0 ? 2 * 3.14159265358979323846 / 3 / std::sqrt(scene.curvature) : 1e300;
    const double reach = std::min(scene.limit_radius, cut);
    for (const SceneBody& b : scene.bodies)
        if (b.r > reach) {
            why = "body " + quote(b.name) + ": at r = " + number(b.r) + " it lies past " + number(reach) +
                  ", where the uneven world's chart ends at K = " + number(scene.curvature) +
                  " (120 degrees of the sphere, short of the antipode, where the metric is singular): move it nearer O";
            return false;
        }
    return true;
}

double bump_gain_most(const Scene& scene) {
    double g = Ranges::kGain;
    for (const SceneBump& b : scene.bumps) {
        const double most = b.mass ? Ranges::kMass : Ranges::kHill;
        if (b.strength != 0) g = std::min(g, most / std::fabs(b.strength));
    }
    return g;
}

bool within_ranges(const Scene& scene, std::string& why) {
    for (const SceneBody& b : scene.bodies)
        if (!body_within_ranges(b, scene.limit_radius, why))
            return false;
    return true;
}

}  // namespace noneuclid::world
