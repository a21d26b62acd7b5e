// A custom body moving on the sphere (docs/library.md): a scene made in code at K = +1 with one
// triangle that starts 1 unit from O on the x axis and travels at 0.5 units a second at right
// angles to the axis, along a great circle: round the sphere, at most pi - 1 from O. Prints the
// world time and the centre, once a second of world time; tests/library compares each line
// with the great circle's closed form.
//
//   example_sphere fixed|double SECONDS        prints "t r theta" (theta in degrees)
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "fixed/fixed.hpp"
#include "world/world.hpp"

template <class W>
void fly(const noneuclid::world::Scene& scene, long seconds) {
    W world(scene);
    for (long s = 0; s <= seconds; ++s) {
        const auto& c = world.bodies[0].centre;
        std::printf("%.9f %.12f %.12f\n", world.time, static_cast<double>(c.r),
                    static_cast<double>(c.theta) * (180 / 3.14159265358979323846));
        for (int f = 0; f < 60; ++f) world.step(1.0 / 60);
    }
}

int main(int argc, char** argv) {
    using namespace noneuclid::world;
    Scene scene;
    scene.curvature = 1;  // the unit sphere; the limit radius is pi, the antipode
    SceneBody probe;
    probe.name = "probe";
    probe.r = 1, probe.theta_deg = 0;              // where it starts
    probe.speed = 0.5, probe.direction_deg = 90;  // its velocity, in the frame carried from O
    probe.facing_deg = 90;
    probe.vertices = {{0.05, 0}, {0.05, 120}, {0.05, 240}};  // a small triangle about its centre
    scene.bodies.push_back(probe);
    const long seconds = argc == 3 ? std::atol(argv[2]) : -1;
    if (seconds < 0 || (std::strcmp(argv[1], "fixed") != 0 && std::strcmp(argv[1], "double") != 0)) {
        std::fprintf(stderr, "usage: example_sphere fixed|double SECONDS\n");
        return 2;
    }
    if (std::strcmp(argv[1], "fixed") == 0) fly<World<noneuclid::fx::fixed>>(scene, seconds);
    else fly<World<double>>(scene, seconds);
    return 0;
}
