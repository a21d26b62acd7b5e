// The scene bodies of a gauge (world/instruments.hpp): every part, made once with the world.
#include "world/instruments.hpp"

#include <string>

namespace noneuclid::world {

namespace {

constexpr Rgb kLive = {255, 210, 90}, kDeclared = {120, 230, 255}, kArc = {255, 150, 80};

SceneBody part(const std::string& name, Rgb color, bool closed, int vertices) {
    SceneBody b;
    b.name = name;
    b.role = BodyKind::instrument;
    b.color = color;
    b.closed = closed;
    b.tessellation = 16;
    for (int k = 0; k < vertices; ++k) b.vertices.push_back({0.0, 0.0});
    return b;
}

}  // namespace

void add_gauge_bodies(Scene& scene, const MeasureDecl& d, bool live) {
    const Rgb c = live ? kLive : kDeclared;
    const std::string name = std::string(live ? "live " : "") + geo::instrument_name(d.kind);
    for (int i = 0; i < 3; ++i) {
        SceneBody m = part("mark", c, true, 0);
        for (int k = 0; k < 6; ++k) m.vertices.push_back({0.04, 60.0 * k});
        scene.bodies.push_back(m);
    }
    scene.bodies.push_back(part(name + " triangle", c, true, 3));
    for (int i = 0; i < 3; ++i) scene.bodies.push_back(part("angle", kArc, false, kArcPoints));
    scene.bodies.push_back(part(name + " circle", c, true, kCirclePoints));
    scene.bodies.push_back(part("radius", kArc, false, 2));
    scene.bodies.push_back(part("perpendicular", kArc, false, 2));
    for (int i = 0; i < 2; ++i) scene.bodies.push_back(part("parallel", c, false, 2));
    scene.bodies.push_back(part("apart", kArc, false, 2));
    const int p = std::clamp(d.sides, 3, kMeasureMaxSides), q = std::clamp(d.around, 3, kMeasureMaxAround);
    for (int j = 0; j < q; ++j) scene.bodies.push_back(part("polygon", c, true, p));
}

}  // namespace noneuclid::world
