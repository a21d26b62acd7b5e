// A scene: the description a world starts from, in double precision and in the units people
// write (degrees, world units per second). Built-in scenes (scenes.cpp) and TOML scene files
// (scene_file.cpp) both produce one; World<T> (world.hpp) is built from it for any engine.
//
// Units. Lengths are world units: the geodesic distance of the space with curvature K, so at
// K = +1 the sphere's circumference is 2 pi. Angles are degrees here and radians inside the
// world. Directions (facing, velocity, acceleration) are angles in the frame carried from O to
// the body's centre (geometry.hpp); local vertex angles are measured from the facing.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace noneuclid::world {

struct Rgb {
    uint8_t r = 255, g = 255, b = 255;
    friend bool operator==(Rgb, Rgb) = default;
};

struct SceneBody {
    std::string name;
    double r = 0, theta_deg = 0;              // position
    double facing_deg = 0;
    double speed = 0, direction_deg = 0;      // velocity
    double accel = 0, accel_direction_deg = 0;  // constant acceleration (scene files may set it)
    double spin_deg = 0;                      // degrees per second
    Rgb color;
    bool closed = true;
    int tessellation = 8;
    struct Vertex {
        double rho = 0, phi_deg = 0;
    };
    std::vector<Vertex> vertices;
    bool controlled = false;  // the ship: thrust and turn act on it
    bool grid = false;        // part of a grid (drawn dimmer); otherwise an ordinary body
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
};

// Parameters of the parametric built-in scenes.
struct SceneParams {
    int bodies = 200;       // stress
    int vertices = 8;       // stress
    int tessellation = 8;   // stress
};

// The names of the built-in scenes, null-terminated.
const char* const* builtin_scene_names();
// Fills `out` with the named built-in scene; false if there is none by that name, or (with
// `why` set) if the stress scene's parameters ask for more than a world may hold (budget.hpp).
bool builtin_scene(const std::string& name, const SceneParams& params, Scene& out, std::string* why = nullptr);

// Grid families, as bodies (they bend with K like any body): the geodesics perpendicular to the
// x and y axes at multiples of `spacing`, and `radial` lines through O, each `length` long
// from its foot (on the axis or at O), with a vertex every `step`. False, adding nothing, with
// a sentence in `why` if the lines would take the world over its budget (budget.hpp).
bool add_axis_grid(Scene& scene, double spacing, double length, double step, Rgb color, std::string& why);
bool add_radial_grid(Scene& scene, int lines, double length, double step, Rgb color, std::string& why);

}  // namespace noneuclid::world
