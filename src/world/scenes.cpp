// The built-in scenes: the paper's figures, the kiosk's default, the Asteroids game, textured
// bodies, the Earth (world/earth.cpp), and a parametric stress scene.
#include <cmath>
#include <cstdio>

#include "world/scene.hpp"

#include <algorithm>
#include <memory>

#include "world/budget.hpp"
#include "world/earth.hpp"
#include "world/image.hpp"

namespace noneuclid::world {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The paper gives lengths in its figures' pixels. We read them at the figures' scale: the limit
// radius pi is 540 px (a 1080-px-high disk), so 90 px = 90 * pi / 540 = pi / 6 world units.
constexpr double kPaperPixel = kPi / 540;

SceneBody polygon(const char* name, int n, double radius, double phase_deg, Rgb color) {
    SceneBody b;
    b.name = name;
    b.color = color;
    for (int i = 0; i < n; ++i) b.vertices.push_back({radius, phase_deg + 360.0 * i / n});
    return b;
}
SceneBody ship() {
    SceneBody b;
    b.name = "ship";
    b.color = {255, 64, 64};
    b.vertices = {{0.12, 0}, {0.08, 140}, {0.08, 220}};
    b.controlled = true;
    b.tessellation = 4;
    return b;
}
SceneBody place(SceneBody b, double r, double theta, double facing, double speed, double dir, double spin) {
    b.r = r, b.theta_deg = theta, b.facing_deg = facing, b.speed = speed, b.direction_deg = dir, b.spin_deg = spin;
    return b;
}
const Rgb kGrid{70, 90, 120};

// A line of vertices along the local direction phi = 0 (and phi = 180 for `both` sides).
SceneBody line(const char* name, double length, double step, bool both, Rgb color) {
    SceneBody b;
    b.name = name;
    b.color = color;
    b.closed = false;
    b.grid = true;
    b.tessellation = 2;
    const int m = static_cast<int>(std::ceil(length / step - 1e-9));
    if (both)
        for (int j = m; j > 0; --j) b.vertices.push_back({std::min(j * step, length), 180});
    for (int j = 0; j <= m; ++j) b.vertices.push_back({std::min(j * step, length), 0});
    return b;
}

// The built-in scenes' grids (a few hundred vertices: well within the budget).
void axis_grid(Scene& s) {
    std::string unused;
    add_axis_grid(s, 0.5, s.limit_radius, 0.25, kGrid, unused);
}

void fig1(Scene& s) {
    s.curvature = -1;
    axis_grid(s);
    s.bodies.push_back(place(polygon("square", 4, 0.3, 45, {255, 200, 64}), 1.2, 20, 0, 0.25, 100, 20));
    s.bodies.push_back(place(polygon("triangle", 3, 0.3, 90, {64, 220, 120}), 1.6, 150, 30, 0.3, 250, -30));
    s.bodies.push_back(place(polygon("hexagon", 6, 0.25, 0, {120, 160, 255}), 0.8, 260, 0, 0.2, 10, 15));
    s.bodies.push_back(place(polygon("circle", 24, 0.2, 0, {230, 120, 230}), 0.3, 60, 0, 0.15, 200, 0));
    s.bodies.push_back(place(polygon("star", 5, 0.3, 90, {255, 255, 255}), 2.0, 300, 0, 0.2, 120, 45));
}
// Motion from the point at distance 1 east of O along the geodesic leaving it at `heading`
// (90: orthogonal to the radius, figure 14; 45, figure 15).
void geodesic_motion(Scene& s, double heading) {
    s.curvature = -1;
    axis_grid(s);
    SceneBody b = polygon("square", 4, 0.15, 45, {255, 200, 64});
    s.bodies.push_back(place(b, 1.0, 0, heading, 0.4, heading, 0));
}
void fig16(Scene& s) {
    s.curvature = -1;
    axis_grid(s);
    // The paper's square, spinning about its centre: its text says an equally spaced square,
    // its vertex list (90, pi/8), (90, 3pi/8), (90, 5pi/8), (90, 7pi/8) spans 135 degrees; the
    // text is followed: phi = pi/8 + k pi/2 (local rho in the paper's pixels).
    SceneBody b;
    b.name = "square";
    b.color = {255, 200, 64};
    for (double k : {1.0, 5.0, 9.0, 13.0}) b.vertices.push_back({90 * kPaperPixel, k * 22.5});
    b.tessellation = 16;
    s.bodies.push_back(place(b, 1.0, 0, 0, 0, 0, 45));
}
void fig17(Scene& s) {
    s.curvature = -1;
    s.sweep_rate = 0.4;  // -1 to +1 in 5 s, and back
    std::string unused;
    add_axis_grid(s, 1.0, s.limit_radius, 0.25, kGrid, unused);  // sparser: its time-lapse lays five over each other
    s.bodies.push_back(place(polygon("square", 4, 0.2, 45, {255, 200, 64}), 1.5, 180, 0, 0.3, 0, 0));
}
void kiosk(Scene& s) {
    s.curvature = 0;
    axis_grid(s);
    std::string unused;
    add_radial_grid(s, 12, s.limit_radius, 0.25, {50, 60, 80}, unused);
    s.bodies.push_back(place(ship(), 0.5, 30, 90, 0, 90, 0));
    s.bodies.push_back(place(polygon("square", 4, 0.25, 45, {255, 200, 64}), 1.5, 20, 0, 0.12, 110, 10));
    s.bodies.push_back(place(polygon("triangle", 3, 0.25, 90, {64, 220, 120}), 1.8, 140, 0, 0.1, 230, -15));
    s.bodies.push_back(place(polygon("hexagon", 6, 0.2, 0, {120, 160, 255}), 1.2, 250, 0, 0.08, 20, 12));
    s.bodies.push_back(place(polygon("circle", 24, 0.18, 0, {230, 120, 230}), 2.3, 310, 0, 0.1, 160, 0));
}
// The Asteroids game (world/game.hpp) over the axis grid, with its default settings: flat on
// the first level, hyperbolic on the second, spherical on the third, and round again.
void asteroids(Scene& s) {
    s.curvature = 0;
    std::string unused;
    add_axis_grid(s, 0.5, s.limit_radius, 0.25, {45, 58, 80}, unused);  // dimmer than the kiosk's: the game is in front
    s.bodies.push_back(place(ship(), 0, 0, 90, 0, 90, 0));
    s.game.on = true;
    add_game_slots(s, unused);  // the kiosk's ship and the default settings always fit
}
// The instruments (world/instruments.hpp): a triangle about O measured while the ship flies
// over the axis grid; the instrument button turns on the live one and fire drops its marks.
void measure(Scene& s) {
    s.curvature = 0;
    std::string unused;
    add_axis_grid(s, 0.5, s.limit_radius, 0.25, {45, 58, 80}, unused);
    s.bodies.push_back(place(ship(), 1.6, -90, 90, 0, 90, 0));
    MeasureDecl triangle;
    triangle.kind = geo::Instrument::triangle;
    triangle.marks = {{1.2, 90}, {1.2, 210}, {1.2, 330}};
    s.measures.push_back(triangle);
}
// The paper's figure 2: two geodesics leaving a common perpendicular (through O, 1 long) on the
// same side, 2.4 along each: they meet at K = +1 (at pi / 2), stay 1 apart at K = 0 and fly
// apart at K = -1; the parallels instrument reads how far apart they end.
void fig2(Scene& s) {
    s.curvature = 1;
    MeasureDecl p;
    p.kind = geo::Instrument::parallels;
    p.marks = {{0.5, 180}, {0.5, 0}};
    p.length = 2.4;
    s.measures.push_back(p);
}
// The paper's figure 4: the {7,3} tiling (regular heptagons, three at each vertex) about O, as
// bodies, every tile whose centre is within 3 of O; shown in the stereographic view at K = -1
// (the Poincare disc). Each tile's neighbour across an edge is its reflection there: a centre
// twice the inradius away toward the edge's midpoint, facing back across that edge.
void fig4(Scene& s) {
    s.curvature = -1;
    const double pi = 3.14159265358979323846, p = 7, q = 3;
    const double circum = std::acosh(1 / (std::tan(pi / p) * std::tan(pi / q)));
    const double in = std::acosh(std::cos(pi / q) / std::sin(pi / p));
    struct Tile {
        geo::Polar<double> c;
        double facing;
    };
    std::vector<Tile> tiles = {{{0, 0}, 0}};
    for (std::size_t i = 0; i < tiles.size() && tiles.size() < 400; ++i)
        for (int k = 0; k < 7; ++k) {
            const Tile t = tiles[i];
            const geo::Polar<double> c = geo::walk_end(-1.0, t.c, t.facing + (2 * k + 1) * pi / p, 2 * in);
            if (c.r > 3) continue;
            bool seen = false;
            for (const Tile& o : tiles) seen = seen || geo::distance(-1.0, o.c, c) < 1e-6;
            if (!seen) tiles.push_back({c, geo::bearing(-1.0, c, t.c) - pi / p});
        }
    for (const Tile& t : tiles) {
        SceneBody b = polygon("heptagon", 7, circum, 0, {120, 200, 255});
        b.tessellation = 12;
        s.bodies.push_back(place(b, t.c.r, t.c.theta * 180 / pi, t.facing * 180 / pi, 0, 0, 0));
    }
}
// Five textured bodies about 60 px across on the kiosk's 800x480 screen (0.4 from their
// centres: 61 px at K = 0), in the built-in images, and one filled: a hexagon, an irregular
// asteroid, a square, a five-pointed star, a thick "C" that is not star-shaped about its centre
// (its centre lies outside it), and a filled triangle; still, turning slowly, over the axis grid.
void textured(Scene& s) {
    s.curvature = 0;
    axis_grid(s);
    auto image = [](const char* name) {
        auto im = std::make_shared<Image>();
        builtin_image(name, *im);
        return im;
    };
    const std::shared_ptr<const Image> checker = image("builtin:checker"), rock = image("builtin:rock");
    auto textured_body = [&](SceneBody b, std::shared_ptr<const Image> im) {
        b.texture = std::move(im);
        b.tessellation = 8;
        return b;
    };
    s.bodies.push_back(place(textured_body(polygon("hexagon", 6, 0.4, 0, {255, 220, 160}), checker), 0.9, 30, 0, 0, 0, 8));
    SceneBody rocky;
    rocky.name = "asteroid";
    rocky.color = {200, 190, 170};
    const double rhos[] = {0.4, 0.33, 0.38, 0.3, 0.4, 0.36, 0.31, 0.39, 0.34, 0.37};
    for (int i = 0; i < 10; ++i) rocky.vertices.push_back({rhos[i], 36.0 * i});
    s.bodies.push_back(place(textured_body(rocky, rock), 1.6, 150, 20, 0, 0, -6));
    s.bodies.push_back(place(textured_body(polygon("square", 4, 0.4, 45, {160, 220, 255}), checker), 2.1, 250, 10, 0, 0, 5));
    SceneBody star;
    star.name = "star";
    star.color = {255, 255, 255};
    for (int i = 0; i < 10; ++i) star.vertices.push_back({i % 2 == 0 ? 0.4 : 0.18, 90 + 36.0 * i});
    s.bodies.push_back(place(textured_body(star, checker), 1.4, 320, 0, 0, 0, 10));
    SceneBody c;
    c.name = "crescent";
    c.color = {230, 160, 230};
    for (double phi : {40, 90, 140, 180, 220, 270, 320}) c.vertices.push_back({0.4, phi});
    for (double phi : {300, 240, 180, 120, 60}) c.vertices.push_back({0.2, phi});
    s.bodies.push_back(place(textured_body(c, rock), 2.4, 75, 200, 0, 0, -8));
    SceneBody tri = polygon("triangle", 3, 0.3, 90, {64, 220, 120});
    tri.filled = true, tri.fill = {30, 110, 60};
    s.bodies.push_back(place(tri, 0.8, 200, 0, 0, 0, 12));
}
void stress(Scene& s, const SceneParams& p) {
    s.curvature = -1;
    uint32_t x = 2463534242u;  // xorshift32: the same scene every time
    auto next = [&x] {
        x ^= x << 13, x ^= x >> 17, x ^= x << 5;
        return (x >> 8) * (1.0 / 16777216.0);
    };
    for (int i = 0; i < p.bodies; ++i) {
        char name[24];
        std::snprintf(name, sizeof name, "body%d", i);
        // The draws in a fixed order, one statement each: the order in which a call's arguments
        // are evaluated is the compiler's choice, and differs between x86-64 and aarch64. This
        // is the order x86-64's g++ took, so the scene is the one the figures were made with.
        const double red = next(), green = next(), phase = next(), size = next();
        SceneBody b = polygon(name, p.vertices, 0.1 + 0.2 * size, 360 * phase,
                              {static_cast<uint8_t>(80 + 175 * red), static_cast<uint8_t>(80 + 175 * green), 200});
        b.tessellation = p.tessellation;
        const double spin = next(), dir = next(), speed = next(), facing = next(), theta = next(), r = next();
        s.bodies.push_back(place(b, 2.9 * r, 360 * theta, 360 * facing, 0.1 + 0.3 * speed, 360 * dir, 60 * spin - 30));
    }
}

}  // namespace

namespace {
// The vertices line() makes for a line of `length` with a vertex every `step`, in double (a
// grid's values can ask for far more than an int holds).
double line_vertices(double length, double step, bool both) {
    const double m = std::ceil(length / step - 1e-9);
    return both ? 2 * m + 1 : m + 1;
}
// Whether `lines` grid lines of `vertices` vertices fit the budget (both counted in double
// first: they may be beyond any integer type's range).
bool grid_fits(const Scene& scene, double lines, double vertices, std::string& why) {
    // (min: far beyond the budget, the exact count does not matter, and the long must not overflow)
    if (budget_allows(scene, static_cast<long>(std::min(lines, 1e12)), static_cast<long>(std::min(vertices, 1e12)), 2, why))
        return true;
    why += " (a larger spacing or step, a shorter length, fewer lines)";
    return false;
}
}  // namespace

bool add_axis_grid(Scene& scene, double spacing, double length, double step, Rgb color, std::string& why) {
    const double half = std::floor(scene.limit_radius / spacing + 1e-9);
    if (!grid_fits(scene, 2 * (2 * half + 1), line_vertices(length, step, true), why)) return false;
    const int n = static_cast<int>(half);
    for (int k = -n; k <= n; ++k) {
        const double d = std::fabs(k * spacing);
        char name[32];
        // Perpendicular to the x axis at x = k s: foot on the axis, running north-south.
        std::snprintf(name, sizeof name, "grid x=%g", k * spacing);
        SceneBody a = line(name, length, step, true, color);
        a.r = d, a.theta_deg = k < 0 ? 180 : 0, a.facing_deg = 90;
        scene.bodies.push_back(a);
        // Perpendicular to the y axis at y = k s, running east-west.
        std::snprintf(name, sizeof name, "grid y=%g", k * spacing);
        SceneBody b = line(name, length, step, true, color);
        b.r = d, b.theta_deg = k < 0 ? 270 : 90, b.facing_deg = 0;
        scene.bodies.push_back(b);
    }
    return true;
}

bool add_radial_grid(Scene& scene, int lines, double length, double step, Rgb color, std::string& why) {
    if (!grid_fits(scene, lines, line_vertices(length, step, false), why)) return false;
    for (int i = 0; i < lines; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "radial %g", 360.0 * i / lines);
        SceneBody b = line(name, length, step, false, color);
        b.facing_deg = 360.0 * i / lines;
        scene.bodies.push_back(b);
    }
    return true;
}

namespace {

// The built-in scenes: name, what it shows (`noneuclid scenes`, --help), and how it is made.
// Uneven worlds (src/uneven, docs/uneven.md). lens: a mass between the ship at O and a field of
// bodies behind it, which the inhabitant's view shows twice; hills: two hills and a dip that the
// grid's geodesics bend through.
void lens(Scene& s) {
    s.curvature = 0;
    axis_grid(s);
    s.bumps.push_back({true, 1.2, 0, 0.15, 0.35});
    s.bodies.push_back(place(ship(), 0, 0, 0, 0, 0, 0));
    const Rgb colors[] = {{255, 200, 64}, {64, 220, 120}, {120, 160, 255}, {230, 120, 230}, {255, 255, 255}};
    const char* names[] = {"square 1", "square 2", "square 3", "square 4", "square 5"};
    for (int i = 0; i < 5; ++i)
        s.bodies.push_back(place(polygon(names[i], 4, 0.12, 45, colors[i]), 2.5, -22 + 11 * i, 0, 0.03, 90, 10));
}
void hills(Scene& s) {
    s.curvature = 0;
    axis_grid(s);
    s.bumps.push_back({false, 1.1, 45, 0.45, 0.8});
    s.bumps.push_back({false, 1.4, 200, 0.5, -0.6});
    s.bumps.push_back({false, 1.6, 300, 0.35, 0.6});
    s.bodies.push_back(place(ship(), 0.3, 30, 90, 0, 90, 0));
    s.bodies.push_back(place(polygon("square", 4, 0.2, 45, {255, 200, 64}), 1.5, 20, 0, 0.15, 110, 10));
    s.bodies.push_back(place(polygon("triangle", 3, 0.2, 90, {64, 220, 120}), 1.8, 140, 0, 0.12, 230, -15));
}

// The game around a mass: its asteroids and bullets curve round it (the asteroids' levels and K
// as the asteroids scene's).
void gravity(Scene& s) {
    asteroids(s);
    s.bumps.push_back({true, 1.5, 20, 0.25, 0.3});
}

struct SceneRow {
    const char* name;
    const char* about;
    void (*make)(Scene&, const SceneParams&);
};
// The three-dimensional world (src/space/scene_world.hpp makes its polyhedra, the ship and the
// grid), or a honeycomb of cubes there at the K where it closes.
void space(Scene& s, int honeycomb_cells = 0) {
    s.space = true, s.honeycomb_cells = honeycomb_cells;
    s.curvature = honeycomb_cells == 3 ? 1 : honeycomb_cells == 5 ? -1 : 0, s.limit_radius = 3;
}

const SceneRow kScenes[] = {
    {"kiosk", "the kiosk's: a ship, four drifting bodies and the grid", [](Scene& s, const SceneParams&) { kiosk(s); }},
    {"asteroids", "the game: Asteroids in curved space, K turning each level", [](Scene& s, const SceneParams&) { asteroids(s); }},
    {"textured", "textured and filled bodies that bend with K", [](Scene& s, const SceneParams&) { textured(s); }},
    {"measure", "instruments: a triangle's angles and area while K changes; the instrument button measures more",
     [](Scene& s, const SceneParams&) { measure(s); }},
    {"fig1", "the paper's figure 1: a body and its geodesic edges", [](Scene& s, const SceneParams&) { fig1(s); }},
    {"fig2", "the paper's figure 2: lines that start parallel (meet at K > 0, fly apart at K < 0)",
     [](Scene& s, const SceneParams&) { fig2(s); }},
    {"fig4", "the paper's figure 4: a {7,3} tiling of heptagons (the Poincare disc: --projection stereographic)",
     [](Scene& s, const SceneParams&) { fig4(s); }},
    {"fig14", "the paper's figure 14: a body moving along a geodesic at 90 degrees", [](Scene& s, const SceneParams&) { geodesic_motion(s, 90); }},
    {"fig15", "the paper's figure 15: a body moving along a geodesic at 45 degrees", [](Scene& s, const SceneParams&) { geodesic_motion(s, 45); }},
    {"fig16", "the paper's figure 16: the square at ninety pixels", [](Scene& s, const SceneParams&) { fig16(s); }},
    {"fig17", "the paper's figure 17: the grid while K sweeps from -1 to +1", [](Scene& s, const SceneParams&) { fig17(s); }},
    {"earth", "the Earth's coastlines and graticule about a place (--centre LAT,LON), at any K, zoomed by K (--view KM), with Tissot's circles (--tissot), and the ship", [](Scene& s, const SceneParams& p) {
         earth_zoom_scene(s, p.centre_lat, p.centre_lon, p.view_km, p.tissot);
         s.bodies.push_back(place(ship(), 0, 0, 90, 0, 90, 0));  // to fly over it (figure 3 leaves it out)
     }},
    {"lens", "uneven: a mass between the ship and five squares, seen twice from O (P: the chart or the inhabitant's view; < > its strength)",
     [](Scene& s, const SceneParams&) { lens(s); }},
    {"hills", "uneven: hills and a dip that the grid's geodesics bend through (P: the chart or the inhabitant's view; < > their strength)",
     [](Scene& s, const SceneParams&) { hills(s); }},
    {"gravity", "uneven: the game around a mass that bends the asteroids' and the bullets' paths",
     [](Scene& s, const SceneParams&) { gravity(s); }},
    {"space", "three dimensions: a dozen polyhedra drifting and spinning in a curved space (P: the inhabitant's view or the map)",
     [](Scene& s, const SceneParams&) { space(s); }},
    {"8-cell", "three dimensions: the 8-cell, eight cubes that fill S3 at K = +1, three round each edge; turn K and they part",
     [](Scene& s, const SceneParams&) { space(s, 3); }},
    {"order-5-cubic", "three dimensions: the order-5 cubic honeycomb {4,3,5}, five cubes round each edge, closing at K = -1; turn K and they part",
     [](Scene& s, const SceneParams&) { space(s, 5); }},
    {"stress", "many bodies of many vertices (--bodies, --vertices, --tessellation)", [](Scene& s, const SceneParams& p) { stress(s, p); }},
};

const SceneRow* find_scene(const std::string& name) {
    for (const SceneRow& r : kScenes)
        if (name == r.name) return &r;
    return nullptr;
}

}  // namespace

std::vector<SceneInfo> builtin_scenes() {
    std::vector<SceneInfo> out;
    for (const SceneRow& r : kScenes) out.push_back({r.name, r.about});
    return out;
}

std::vector<std::string> builtin_scene_names() {
    std::vector<std::string> out;
    for (const SceneRow& r : kScenes) out.emplace_back(r.name);
    return out;
}

bool builtin_scene(const std::string& name, const SceneParams& params, Scene& out, std::string* why) {
    const SceneRow* row = find_scene(name);
    if (!row) return false;
    out = Scene{};
    out.name = name;
    std::string over;
    if (name == "stress" && !budget_allows(out, params.bodies, params.vertices, params.tessellation, over)) {
        if (why) *why = "the stress scene: " + over;
        return false;
    }
    row->make(out, params);
    return true;
}

}  // namespace noneuclid::world
