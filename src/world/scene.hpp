// A scene: the description a world starts from, in double precision and in the units people
// write (degrees, world units per second). Built-in scenes (scenes.cpp) and TOML scene files
// (scene_file.cpp) both produce one; World<T> (world.hpp) is built from it for any engine.
//
// Units. Lengths are world units: the geodesic distance of the space with curvature K, so at
// K = +1 the sphere's circumference is 2 pi. Angles are degrees here and radians inside the
// world. Directions (facing, velocity, acceleration) are angles in the frame carried from O to
// the body's centre (geometry.hpp); local vertex angles are measured from the facing.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geometry/detail.hpp"
#include "geometry/measure.hpp"

#include "world/image.hpp"

namespace noneuclid::world {

struct Rgb {
    uint8_t r = 255, g = 255, b = 255;
    friend bool operator==(Rgb, Rgb) = default;
};

// What a body is, as `dump` names it: the ship (the controlled body), a game's asteroid or
// bullet, a grid line, or any other body.
enum class BodyKind : uint8_t { body, ship, asteroid, bullet, grid, instrument };
inline const char* kind_name(BodyKind k) {
    static const char* const names[] = {"body", "ship", "asteroid", "bullet", "grid", "instrument"};
    return names[static_cast<int>(k)];
}

struct SceneBody {
    std::string name;
    double r = 0, theta_deg = 0;              // position
    double facing_deg = 0;
    double speed = 0, direction_deg = 0;      // velocity
    double accel = 0, accel_direction_deg = 0;  // constant acceleration (scene files may set it)
    double spin_deg = 0;                      // degrees per second
    Rgb color;
    // Filled (render/fill.hpp; a closed body of 3 or more vertices): with `fill`, or with the
    // texture, mapped on the body's local equidistant coordinates; the outline is drawn over it.
    bool filled = false;
    Rgb fill;
    std::shared_ptr<const Image> texture;  // null: no texture
    double texture_scale = 1;              // the image's width in diameters of the body
    bool texture_bilinear = false;         // texels blended (else the nearest)
    bool closed = true;
    int tessellation = 8;
    struct Vertex {
        double rho = 0, phi_deg = 0;
    };
    std::vector<Vertex> vertices;
    // A line drawn simplified for each view (geometry/detail.hpp: the earth scene's lines);
    // none or empty: every vertex drawn. (Shared: a scene's copies share its trees, and a body
    // without one pays a pointer.)
    std::shared_ptr<const geo::DetailTree> detail;
    bool controlled = false;  // the ship: thrust and turn act on it
    bool grid = false;        // part of a grid (drawn dimmer); otherwise an ordinary body
    BodyKind role = BodyKind::body;  // asteroid or bullet: a game's slot (world/game.hpp)
    BodyKind kind() const { return controlled ? BodyKind::ship : grid ? BodyKind::grid : role; }
};

// The Asteroids game (world/game.hpp), when a scene has one: its rules and what it spawns.
// Lengths in world units, times in seconds; docs/game.md documents each with its default.
struct GameSettings {
    bool on = false;
    uint32_t seed = 1;               // the game's random numbers: the same seed, the same game
    int lives = 3;
    int asteroids = 4;               // large asteroids on the first level
    int asteroids_step = 1;          // this many more on each level after it
    int asteroids_max = 8;           // at most this many at a level's start (4 slots each)
    double sizes[3] = {0.36, 0.2, 0.11};  // large, medium, small: the mean radius
    int points[3] = {20, 50, 100};        // the score for hitting each size
    double speed_min = 0.08, speed_max = 0.3;  // a new asteroid's drift
    double spin_deg = 40;            // at most this fast, either way, degrees a second
    int vertices = 10;               // of each asteroid
    double split_speed = 0.12;       // how fast the two pieces of a hit asteroid fly apart
    double bullet_speed = 1.6;       // from the ship, plus the ship's own velocity
    double bullet_range = 2.6;       // the distance a bullet flies before it is spent
    double bullet_cooldown = 0.2;    // the least time between two shots
    int bullets = 12;                // bullets in flight at once, at most
    double ship_speed = 1.2;         // the ship's top speed
    double invulnerable = 2.5;       // after a respawn (the ship blinks)
    double respawn_delay = 1.5;      // from a crash to the respawn
    double level_pause = 1.5;        // from a cleared level to the next one's asteroids
    double game_over_seconds = 5;    // the game-over screen, before the "press fire" one
    std::vector<double> levels = {0, -1, 1};  // K at each level's start, in turn (empty: unchanged)
    Rgb asteroid_color{200, 190, 170}, bullet_color{255, 255, 160};
    // The asteroids filled with a colour, or textured (SceneBody's fill and texture).
    bool asteroid_filled = false;
    Rgb asteroid_fill{90, 84, 76};
    std::shared_ptr<const Image> asteroid_texture;
    double asteroid_texture_scale = 1;
    bool asteroid_texture_bilinear = false;
};

// An instrument a scene declares (a scene file's [[measure]]; docs/measure.md): its kind, its
// marks (r, theta in degrees; none: the defaults below about O) and its construction.
struct MeasureDecl {
    geo::Instrument kind = geo::Instrument::triangle;
    struct Mark {
        double r = 0, theta_deg = 0;
    };
    std::vector<Mark> marks;  // triangle 3; circle its centre (and a point on it); parallels 2; polygon its vertex
    double radius = 1;        // circle, without a second mark
    double length = 1.5;      // parallels: the arclength along each
    double distance = 0.5;    // parallels, without marks: the common perpendicular's length
    int sides = 3, around = 7;
    double side = 1.2;        // polygon
};
inline constexpr int kMeasureMaxSides = 12, kMeasureMaxAround = 12;

// A bump of an uneven world (a scene file's [[bump]]; src/uneven, docs/uneven.md): a hill
// (a Gaussian bump of the metric's log, strength a) or a mass (a smoothed cone, strength alpha:
// 2 pi alpha of curvature in all), centred where a body at (r, theta) would be, `width` wide in
// chart units. A scene with any bump is an uneven world.
struct SceneBump {
    bool mass = false;
    double r = 0, theta_deg = 0;
    double width = 0.5;
    double strength = 0;
};

// Zoom by curvature (the earth scene, world/earth.hpp; docs/earth.md): the curvature keys
// scale the picture instead of bending it. The zoom is a curvature z, the sphere the Earth is
// at that scale: a level's bodies were placed for the sphere of its own curvature, a place at
// its angle / sqrt(level), and the world shows them at z by scaling every vertex's rho by
// sqrt(level / z). Each level is built twice: with its edges halved so that they follow the
// Earth's lines at any K (`bent`), and without (the Earth's lines are the geodesics themselves
// while K = z). The world draws one: the level of the least curvature at or above z, the plain
// one while K = z, the bent one after K was set apart from it (keys 1, 2, 3, a preset).
struct ZoomLevel {
    double curvature = 1;   // the sphere its bodies were placed for
    bool bent = false;      // halved for every K (else drawn only while K = z)
    int first = 0, count = 0;  // its bodies: scene.bodies[first, first + count)
};
struct Zoom {
    std::vector<ZoomLevel> levels;  // none: the curvature keys change K, keeping every (r, theta)
    double start = 1;               // z at the start (and after reset)
    double least = 0, most = 1;     // z's range
    // Held curvature up (down): z divided (multiplied) by kStep every step, a multiplication
    // alone so that every machine gives the same z bit for bit: 6.7 times a second at 60 steps.
    static constexpr double kStep = 31.0 / 32;
    bool on() const { return !levels.empty(); }
};
// What every world reports of its zoom: z, and whether it is at either end of its range (on
// false: the world has no zoom, or the scene none).
struct ZoomReading {
    bool on = false;
    double z = 1;
    bool least = false, most = false;
};

// A three-dimensional scene's solid ([[solid]] in a scene file; src/space makes it a body): one of
// the Platonic solids by name, or its own vertices (in its frame, x forward, y left, z up, world
// units: each walked out from the centre along its direction by its length) and edges.
struct SceneSolid {
    std::string name;
    std::string shape;                         // "tetrahedron" ... "icosahedron", or "" for its own
    double size = 0.2;                         // a named shape's circumradius
    std::vector<std::array<double, 3>> vertices;
    std::vector<std::array<int, 2>> edges;
    double position[3] = {1, 0, 0};            // its centre: r u, in the map's coordinates
    double velocity[3] = {0, 0, 0};            // its speed times its direction of travel, carried
    double spin_deg = 0, spin_axis[3] = {0, 0, 1};  // degrees a second about an axis of its frame
    Rgb color{220, 225, 235};
};

struct Scene {
    std::string name;
    double curvature = 0;
    double limit_radius = 3.14159265358979323846;  // R; default pi: at K = 1 the whole sphere
    std::vector<double> presets = {-1, 0, 1};      // "next preset" cycles through these
    double thrust = 0.5;            // the ship's acceleration while thrusting, units / s^2
    double turn_rate_deg = 120;     // the ship's turn rate while a turn button is held, deg / s
    double curvature_rate = 0.5;    // curvature up/down while held, per second
    double sweep_rate = 0;          // K changes by this per second on its own (fig17), bouncing at +-1
    std::vector<SceneBody> bodies;
    Zoom zoom;                     // zoom.on(): the curvature keys zoom (the earth scene)
    GameSettings game;             // game.on: the Asteroids game runs in this scene
    std::vector<MeasureDecl> measures;  // instruments shown from the start (the live one is extra)
    std::vector<SceneBump> bumps;  // any: the world is uneven (src/uneven)
    bool space = false;            // a three-dimensional world (src/space; its bodies made there)
    std::vector<SceneSolid> solids;  // its solids (none: the space scene's dozen)
    int honeycomb_cells = 0;       // and in it a honeycomb of cubes, this many round an edge
                                   // (3: the 8-cell, 5: {4,3,5}); 0: none, the polyhedra
    double strength_rate = 0.5;    // the bumps' strength keys: their gain changes this much a second
};

// Parameters of the parametric built-in scenes.
struct SceneParams {
    int bodies = 200;       // stress
    int vertices = 8;       // stress
    int tessellation = 8;   // stress
    double centre_lat = 51.5, centre_lon = 0;  // earth: the place at O, degrees (default Greenwich; world/earth.hpp)
    double view_km = 0;  // earth: the view's radius, km (0: the whole globe at K = 1)
    bool tissot = false;  // earth: Tissot's indicatrices, circles of 500 km on a 30-degree grid
};

// The built-in scenes (world/scenes.cpp's table): each one's name and what it shows, in one
// line; and their names alone.
struct SceneInfo {
    const char* name;
    const char* about;
};
std::vector<SceneInfo> builtin_scenes();
std::vector<std::string> builtin_scene_names();
// Fills `out` with the named built-in scene; false if there is none by that name, or (with
// `why` set) if the stress scene's parameters ask for more than a world may hold (budget.hpp).
bool builtin_scene(const std::string& name, const SceneParams& params, Scene& out, std::string* why = nullptr);

// Grid families, as bodies (they bend with K like any body): the geodesics perpendicular to the
// x and y axes at multiples of `spacing`, and `radial` lines through O, each `length` long
// from its foot (on the axis or at O), with a vertex every `step`. False, adding nothing, with
// a sentence in `why` if the lines would take the world over its budget (budget.hpp).
bool add_axis_grid(Scene& scene, double spacing, double length, double step, Rgb color, std::string& why);
bool add_radial_grid(Scene& scene, int lines, double length, double step, Rgb color, std::string& why);

// The game's bodies, for a scene whose game is on (world/game_scene.cpp): its asteroid slots
// (4 for each of asteroids_max: a large one's pieces) and bullet slots, appended. False, adding
// nothing, with a sentence in `why` (no full stop) if the settings do not fit the scene: no
// ship, or a ship the collision tests cannot take (over kGameMaxVertices vertices, not
// star-shaped about its centre, or larger than 0.5).
bool add_game_slots(Scene& scene, std::string& why);

}  // namespace noneuclid::world
