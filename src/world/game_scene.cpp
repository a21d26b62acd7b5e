// The game's bodies in a scene: the ship check and the asteroid and bullet slots (world/game.hpp
// spawns into them).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "world/budget.hpp"
#include "world/game.hpp"
#include "world/quote.hpp"
#include "world/scene.hpp"

namespace noneuclid::world {

namespace {

constexpr double kTurnDeg = 360;

// Whether the ship's outline is star-shaped about its centre with its vertices counter-clockwise:
// each next vertex further round by more than 0 and less than half a turn, once round in all.
bool star_shaped(const SceneBody& b) {
    double total = 0;
    const std::size_t n = b.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double gap = std::fmod(std::fmod(b.vertices[(i + 1) % n].phi_deg - b.vertices[i].phi_deg, kTurnDeg) + kTurnDeg, kTurnDeg);
        if (gap <= 0 || gap >= 180) return false;
        total += gap;
    }
    return n >= 3 && std::fabs(total - kTurnDeg) < 1e-6;
}

}  // namespace

bool add_game_slots(Scene& scene, std::string& why) {
    const GameSettings& g = scene.game;
    const SceneBody* ship = nullptr;
    for (const SceneBody& b : scene.bodies)
        if (b.controlled) {
            ship = &b;
            break;
        }
    if (!ship) {
        why = "the game needs a ship: a [[body]] named \"ship\" or with controlled = true";
        return false;
    }
    double rho = 0;
    for (const SceneBody::Vertex& v : ship->vertices) rho = std::max(rho, v.rho);
    if (ship->vertices.size() > static_cast<std::size_t>(kGameMaxVertices) || !ship->closed || !star_shaped(*ship) ||
        rho > 0.5) {
        why = "body " + quote(ship->name) + ": the game's ship must be a closed outline of 3 to " +
              std::to_string(kGameMaxVertices) +
              " vertices within 0.5 of its centre, listed counter-clockwise (phi rising) with each next vertex less "
              "than 180 degrees further round: collisions are tested on such outlines";
        return false;
    }
    const long slots = 4L * g.asteroids_max + g.bullets;
    if (!budget_allows(scene, slots, std::max(g.vertices, 2), 3, why)) {
        why += " (fewer asteroids_max or bullets)";
        return false;
    }
    for (long i = 0; i < 4L * g.asteroids_max; ++i) {
        SceneBody a;
        a.name = "asteroid";
        a.role = BodyKind::asteroid;
        a.color = g.asteroid_color;
        a.filled = g.asteroid_filled, a.fill = g.asteroid_fill;
        a.texture = g.asteroid_texture, a.texture_scale = g.asteroid_texture_scale;
        a.texture_bilinear = g.asteroid_texture_bilinear;
        a.tessellation = 3;
        for (int k = 0; k < g.vertices; ++k) a.vertices.push_back({g.sizes[0], kTurnDeg * k / g.vertices});
        scene.bodies.push_back(a);
    }
    for (int i = 0; i < g.bullets; ++i) {
        SceneBody b;
        b.name = "bullet";
        b.role = BodyKind::bullet;
        b.color = g.bullet_color;
        b.closed = false;
        b.tessellation = 1;
        b.vertices = {{0.03, 0}, {0.03, 180}};  // a short streak along its flight
        scene.bodies.push_back(b);
    }
    return true;
}

}  // namespace noneuclid::world
