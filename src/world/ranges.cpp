#include "world/ranges.hpp"

#include <algorithm>
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

bool body_within_ranges(const SceneBody& b, double R, std::string& why) {
    const std::string name = "body " + quote(b.name) + ": ";
    if (b.r > R) {
        why = name + "its position r = " + number(b.r) + " is outside the limit circle (limit_radius = " + number(R)
              + "): place it at r <= " + number(R);
        return false;
    }
    if (b.speed > Ranges::kSpeed) {
        why = name + "its speed " + number(b.speed) + " is over the ceiling of " + number(Ranges::kSpeed)
              + " world units per second: give a speed of at most that";
        return false;
    }
    if (!b.grid)
        for (const SceneBody::Vertex& v : b.vertices)
            if (v.rho > Ranges::kBodyRadius) {
                why = name + "a vertex at rho = " + number(v.rho) + " from its centre, over the "
                      + number(Ranges::kBodyRadius)
                      + " a body may span (80 degrees of the sphere at K = 1): make the body smaller";
                return false;
            }
    const double reach = body_reach(b, R);
    if (reach > Ranges::kReach) {
        const bool moves = body_moves(b);
        why = name + "its vertices could reach " + number(reach) + " from O ("
              + (moves ? "limit_radius" : "its distance r")
              + " plus its largest rho), past the engines' reach of 2 pi (6.283): make the body smaller or "
              + (moves ? "limit_radius" : "r") + " lower";
        return false;
    }
    return true;
}

bool within_ranges(const Scene& scene, std::string& why) {
    for (const SceneBody& b : scene.bodies)
        if (!body_within_ranges(b, scene.limit_radius, why))
            return false;
    return true;
}

}  // namespace noneuclid::world
