#include "files/scene_file.hpp"

#include <algorithm>
#include <sstream>

#include "world/budget.hpp"
#include "world/earth.hpp"
#include "world/game.hpp"
#include "world/instruments.hpp"
#include "world/world.hpp"
#include "world/quote.hpp"
#include "world/ranges.hpp"
#include "files/scene_solids.hpp"
#include "files/text_file.hpp"
#include "files/toml_reader.hpp"

namespace noneuclid::files {
namespace {

using tomlr::Bad, tomlr::Reader, tomlr::tables, tomlr::type_name;

// Where a scene's textures come from: the built-in images by name, files through the reader,
// relative to the scene file's directory. A file is decoded once however many bodies name it
// and however its path is spelt (`identify` gives the file's identity), and the images decoded
// are counted against the world's budget, so that no scene can ask for more than it.
struct Images {
    const ImageReader& reader;
    const FileIdentity& identify;
    std::string dir;  // the scene file's directory, with its '/', or ""
    // Each image read, under its path as resolved and under its file's identity ("" if none).
    std::vector<std::pair<std::string, std::shared_ptr<const world::Image>>> by_path, by_file;
    long long bytes = 0;  // of the images read

    static std::shared_ptr<const world::Image> find(const auto& list, const std::string& key) {
        for (const auto& [k, image] : list)
            if (k == key) return image;
        return nullptr;
    }

    // The image `key` names in the table read by r (its value as written), or a Bad at its place.
    std::shared_ptr<const world::Image> get(const Reader& r, const char* key, const std::string& context) {
        const std::string name = r.plain_string(key, "");
        const toml::node* node = r.table().get(key);
        const std::string shown = context + "texture " + world::quote(name) + ": ";
        if (name.empty()) throw Bad{node->source(), shown + "expected a PNG file's name or a built-in image"};
        const bool builtin = name.rfind(world::kBuiltinImagePrefix, 0) == 0;
        const std::string path = builtin || name[0] == '/' ? name : dir + name;
        if (auto image = find(by_path, path)) return image;
        const std::string file = builtin || !identify ? std::string() : identify(path);
        if (auto image = file.empty() ? nullptr : find(by_file, file)) {
            by_path.emplace_back(path, image);
            return image;
        }
        auto image = std::make_shared<world::Image>();
        std::string why;
        if (builtin) {
            if (!world::builtin_image(name, *image)) {
                std::string names;
                for (const char* const* n = world::builtin_image_names(); *n; ++n) names += std::string(names.empty() ? "" : ", ") + *n;
                throw Bad{node->source(), shown + "there is no such built-in image (" + names + ")"};
            }
        } else if (!reader) {
            throw Bad{node->source(), shown + "image files cannot be read here: name a built-in image (builtin:checker, builtin:rock)"};
        } else if (!reader(path, *image, why)) {
            throw Bad{node->source(), shown + why};
        }
        const long long more = world::image_bytes(*image);
        if (!world::images_allow(bytes, more, why)) throw Bad{node->source(), shown + why};
        bytes += more;
        by_path.emplace_back(path, image);
        if (!file.empty()) by_file.emplace_back(file, image);
        return image;
    }
};

// fill, texture, texture_scale, texture_filter (with `prefix`: the game's asteroid_fill, ...).
struct Surface {
    bool filled = false;
    world::Rgb fill;
    std::shared_ptr<const world::Image> texture;
    double scale = 1;
    bool bilinear = false;
};
Surface read_surface(const Reader& r, const std::string& prefix, const std::string& context, Images& images, Surface s) {
    const std::string fill = prefix + "fill", texture = prefix + "texture", scale = prefix + "texture_scale",
                      filter = prefix + "texture_filter";
    if (r.table().get(fill)) s.filled = true, s.fill = r.color(fill.c_str(), s.fill);
    if (r.table().get(texture)) s.texture = images.get(r, texture.c_str(), context);
    s.scale = r.number(scale.c_str(), s.scale, 0.05, 20, "the image's width in diameters of the body");
    if (const toml::node* f = r.table().get(filter)) {
        const std::string v = r.string(filter.c_str(), "");
        if (v != "nearest" && v != "bilinear")
            throw Bad{f->source(), context + "expected " + world::quote(filter) + " = \"nearest\" or \"bilinear\", found \"" +
                                       world::printable(v) + "\""};
        s.bilinear = v == "bilinear";
    }
    return s;
}

void read_body(const toml::table& t, int index, world::Scene& scene, Images& images) {
    world::SceneBody b;
    {
        const Reader pre(t, "");
        b.name = pre.string("name", "body" + std::to_string(index + 1));
    }
    const Reader r(t, "body " + world::quote(b.name) + ": ");
    r.only({"name", "position", "facing", "velocity", "acceleration", "spin", "color", "closed", "tessellation",
            "vertices", "controlled", "grid", "fill", "texture", "texture_scale", "texture_filter"});
    r.pair("position", b.r, b.theta_deg, 0, world::Ranges::kReach, "r, theta in degrees");
    b.facing_deg = r.number("facing", 0, -1e6, 1e6, "degrees");
    r.pair("velocity", b.speed, b.direction_deg, 0, world::Ranges::kSpeed, "speed in world units per second, direction in degrees");
    r.pair("acceleration", b.accel, b.accel_direction_deg, 0, 1e3, "world units per second^2, direction in degrees");
    b.spin_deg = r.number("spin", 0, -1e6, 1e6, "degrees per second");
    b.color = r.color("color", b.color);
    b.closed = r.boolean("closed", true);
    b.tessellation = static_cast<int>(r.integer("tessellation", 8, 1, 256, "segments per edge"));
    b.controlled = r.boolean("controlled", b.name == "ship");
    b.grid = r.boolean("grid", false);
    const toml::node* v = t.get("vertices");
    if (!v) throw Bad{t.source(), "body " + world::quote(b.name) + ": expected 'vertices' = [[rho, phi], ...], found none"};
    const toml::array* arr = v->as_array();
    if (!arr || arr->empty())
        throw Bad{v->source(), "body " + world::quote(b.name) + ": expected 'vertices' = [[rho, phi], ...] with at least one vertex, found " +
                                   (arr ? "an empty array" : std::string(type_name(*v)))};
    for (const toml::node& e : *arr) {
        const toml::array* p = e.as_array();
        if (!p || p->size() != 2)
            throw Bad{e.source(), "body " + world::quote(b.name) + ": expected each vertex as [rho, phi in degrees], found " +
                                      (p ? "an array of " + std::to_string(p->size()) : std::string(type_name(e)))};
        world::SceneBody::Vertex vx;
        vx.rho = r.as_number(*p->get(0), "vertices", 0, world::Ranges::kBodyRadius, "rho, distance from the centre");
        vx.phi_deg = r.as_number(*p->get(1), "vertices", -1e6, 1e6, "phi in degrees from the facing");
        b.vertices.push_back(vx);
    }
    const Surface surface = read_surface(r, "", "body " + world::quote(b.name) + ": ", images, {});
    b.filled = surface.filled, b.fill = surface.fill, b.texture = surface.texture;
    b.texture_scale = surface.scale, b.texture_bilinear = surface.bilinear;
    if ((b.filled || b.texture) && (!b.closed || b.vertices.size() < 3))
        throw Bad{t.source(), "body " + world::quote(b.name) + ": a fill or a texture needs a closed outline of 3 or more vertices"};
    std::string why;
    const char* key = nullptr;  // (the error at the key's line where the table has it)
    if (!world::body_within_ranges(b, scene.limit_radius, why, &key)) {
        const toml::node* n = key ? t.get(key) : nullptr;
        throw Bad{n ? n->source() : t.source(), why};
    }
    scene.bodies.push_back(std::move(b));
}

void read_grid(const toml::table& t, world::Scene& scene) {
    const Reader r(t, "grid: ");
    r.only({"kind", "spacing", "lines", "length", "step", "color"});
    const std::string kind = r.string("kind", "axes");
    const double length = r.number("length", scene.limit_radius, 0.01, world::Ranges::kReach, "world units");
    const double step = r.number("step", 0.25, 0.001, world::Ranges::kBodyRadius, "world units between vertices");
    const world::Rgb color = r.color("color", {70, 90, 120});
    std::string why;
    const std::size_t first = scene.bodies.size();
    if (kind == "axes") {
        if (!world::add_axis_grid(scene, r.number("spacing", 0.5, 0.01, 1e4, "world units"), length, step, color, why))
            throw Bad{t.source(), "grid: " + why};
    } else if (kind == "radial") {
        if (!world::add_radial_grid(scene, static_cast<int>(r.integer("lines", 12, 1, 360, "lines")), length, step, color, why))
            throw Bad{t.source(), "grid: " + why};
    } else {
        throw Bad{t.get("kind")->source(), "grid: expected kind = \"axes\" or \"radial\", found \"" + world::printable(kind) + "\""};
    }
    // A grid line does not move: its farthest point is its distance from O plus its length.
    double reach = 0, farthest = 0;
    for (std::size_t i = first; i < scene.bodies.size(); ++i) {
        reach = std::max(reach, body_reach(scene.bodies[i], scene.limit_radius));
        farthest = std::max(farthest, scene.bodies[i].r);
    }
    if (reach > world::Ranges::kReach) {
        std::ostringstream m;
        m << "grid: its lines could reach " << reach << " from O (the farthest line is " << farthest
          << " from O, plus the length " << length << "), past the engines' reach of 2 pi (6.283): a length of at most "
          << world::Ranges::kReach - farthest << ", or a lower limit_radius";
        throw Bad{t.source(), m.str()};
    }
}

// [key] = [a, b, ...]: exactly `n` numbers in [lo, hi] (n = 0: any number of them).
std::vector<double> numbers(const Reader& r, const char* key, std::size_t n, double lo, double hi, const char* what) {
    const toml::node* node = r.table().get(key);
    const toml::array* a = node ? node->as_array() : nullptr;
    if (node && (!a || (n > 0 && a->size() != n)))
        throw Bad{node->source(), "game: expected " + world::quote(key) + " = [" + what + "], found " +
                                      (a ? "an array of " + std::to_string(a->size()) : std::string(type_name(*node)))};
    std::vector<double> out;
    if (a)
        for (const toml::node& e : *a) out.push_back(r.as_number(e, key, lo, hi, what));
    return out;
}

// [game]: the Asteroids game's settings (docs/game.md), over the defaults.
void read_game(const toml::table& t, world::GameSettings& g, Images& images) {
    const Reader r(t, "game: ");
    r.only({"seed", "lives", "asteroids", "asteroids_step", "asteroids_max", "sizes", "points", "asteroid_speed",
            "asteroid_spin", "asteroid_vertices", "split_speed", "bullet_speed", "bullet_range", "bullet_cooldown",
            "bullets", "ship_speed", "invulnerable", "respawn_delay", "level_pause", "game_over", "levels",
            "asteroid_color", "bullet_color", "asteroid_fill", "asteroid_texture", "asteroid_texture_scale",
            "asteroid_texture_filter"});
    g.on = true;
    g.seed = static_cast<uint32_t>(r.integer("seed", static_cast<long>(g.seed), 0, 2147483647L, "the random numbers' seed"));
    g.lives = static_cast<int>(r.integer("lives", g.lives, 1, 99, "ships"));
    g.asteroids = static_cast<int>(r.integer("asteroids", g.asteroids, 1, 64, "large asteroids on the first level"));
    g.asteroids_step = static_cast<int>(r.integer("asteroids_step", g.asteroids_step, 0, 64, "more on each level"));
    g.asteroids_max = static_cast<int>(r.integer("asteroids_max", std::max(g.asteroids_max, g.asteroids), g.asteroids,
                                                 64, "large asteroids at a level's start, at most; at least 'asteroids'"));
    const std::vector<double> sizes = numbers(r, "sizes", 3, 0.02, 0.5, "large, medium, small: radii from 0.02 to 0.5");
    if (!sizes.empty()) {
        if (!(sizes[0] >= sizes[1] && sizes[1] >= sizes[2]))
            throw Bad{t.get("sizes")->source(), "game: expected 'sizes' from the largest to the smallest"};
        for (int i = 0; i < 3; ++i) g.sizes[i] = sizes[static_cast<std::size_t>(i)];
    }
    const std::vector<double> points = numbers(r, "points", 3, 0, 1e6, "large, medium, small: whole points");
    for (std::size_t i = 0; i < points.size(); ++i) g.points[i] = static_cast<int>(points[i]);
    r.pair("asteroid_speed", g.speed_min, g.speed_max, 0, 3, "slowest, fastest in world units per second");
    if (g.speed_max < g.speed_min || g.speed_max > 3)
        throw Bad{t.get("asteroid_speed")->source(), "game: expected 'asteroid_speed' = [slowest, fastest], from 0 to 3"};
    g.spin_deg = r.number("asteroid_spin", g.spin_deg, 0, 720, "degrees per second, either way");
    g.vertices = static_cast<int>(r.integer("asteroid_vertices", g.vertices, 5, world::kGameMaxVertices, "vertices"));
    g.split_speed = r.number("split_speed", g.split_speed, 0, 3, "world units per second");
    g.bullet_speed = r.number("bullet_speed", g.bullet_speed, 0.1, 10, "world units per second");
    g.bullet_range = r.number("bullet_range", g.bullet_range, 0.1, 6, "world units: under a sphere's circumference");
    g.bullet_cooldown = r.number("bullet_cooldown", g.bullet_cooldown, 0, 10, "seconds");
    g.bullets = static_cast<int>(r.integer("bullets", g.bullets, 1, 64, "bullets in flight at once"));
    g.ship_speed = r.number("ship_speed", g.ship_speed, 0.05, world::Ranges::kSpeed, "world units per second");
    g.invulnerable = r.number("invulnerable", g.invulnerable, 0, 60, "seconds");
    g.respawn_delay = r.number("respawn_delay", g.respawn_delay, 0, 60, "seconds");
    g.level_pause = r.number("level_pause", g.level_pause, 0, 60, "seconds");
    g.game_over_seconds = r.number("game_over", g.game_over_seconds, 0, 600, "seconds");
    if (t.get("levels")) g.levels = numbers(r, "levels", 0, -1, 1, "K at each level's start, in turn");
    g.asteroid_color = r.color("asteroid_color", g.asteroid_color);
    g.bullet_color = r.color("bullet_color", g.bullet_color);
    Surface s{g.asteroid_filled, g.asteroid_fill, g.asteroid_texture, g.asteroid_texture_scale, g.asteroid_texture_bilinear};
    s = read_surface(r, "asteroid_", "game: ", images, s);
    g.asteroid_filled = s.filled, g.asteroid_fill = s.fill, g.asteroid_texture = s.texture;
    g.asteroid_texture_scale = s.scale, g.asteroid_texture_bilinear = s.bilinear;
}

// [[measure]]: an instrument shown from the start (world/instruments.hpp, docs/measure.md),
// checked at the scene's curvature: a construction it cannot measure is refused here.
void read_measure(const toml::table& t, int index, world::Scene& scene) {
    const std::string context = "measure " + std::to_string(index + 1) + ": ";
    const Reader r(t, context);
    r.only({"instrument", "points", "radius", "length", "distance", "sides", "around", "side"});
    world::MeasureDecl d;
    const std::string kind = r.string("instrument", "");
    if (!geo::parse_instrument(kind.c_str(), d.kind))
        throw Bad{t.source(), context + "expected instrument = \"triangle\", \"circle\", \"parallels\" or \"polygon\", found " +
                                  (kind.empty() ? std::string("none") : "\"" + world::printable(kind) + "\"")};
    const std::size_t most[] = {3, 2, 2, 1}, least[] = {3, 1, 2, 1};
    const std::size_t k = static_cast<std::size_t>(d.kind);
    if (const toml::node* p = t.get("points")) {
        const toml::array* a = p->as_array();
        if (!a || a->size() < least[k] || a->size() > most[k])
            throw Bad{p->source(), context + "expected points = [[r, theta], ...] with " +
                                       (least[k] == most[k] ? std::to_string(most[k]) : std::to_string(least[k]) + " to " + std::to_string(most[k])) +
                                       " points for a " + kind};
        for (const toml::node& e : *a) {
            const toml::array* q = e.as_array();
            if (!q || q->size() != 2) throw Bad{e.source(), context + "expected each point as [r, theta in degrees]"};
            d.marks.push_back({r.as_number(*q->get(0), "points", 0, scene.limit_radius, "r, within the limit radius"),
                               r.as_number(*q->get(1), "points", -1e6, 1e6, "theta in degrees")});
        }
    }
    d.radius = r.number("radius", d.radius, 1e-6, world::Ranges::kReach, "world units");
    d.length = r.number("length", d.length, 0, world::Ranges::kReach, "world units along each geodesic");
    d.distance = r.number("distance", d.distance, 1e-6, world::Ranges::kReach, "world units between the parallels");
    d.sides = static_cast<int>(r.integer("sides", d.sides, 3, world::kMeasureMaxSides, "sides of each polygon"));
    d.around = static_cast<int>(r.integer("around", d.around, 3, world::kMeasureMaxAround, "polygons around the vertex"));
    d.side = r.number("side", d.side, 1e-6, world::Ranges::kReach, "world units");
    // Measured once at the scene's K, in double, as the world will: its sentence if it cannot be.
    world::Scene probe;
    probe.curvature = scene.curvature, probe.limit_radius = scene.limit_radius;
    probe.measures = {d};
    const world::World<double> w(probe);
    const world::GaugeReading& reading = w.gauges().front().reading();
    geo::MeasureError e = reading.error;
    if (d.kind == geo::Instrument::polygon) {
        geo::PolygonReading unused;
        e = geo::measure_polygon(scene.curvature, d.sides, d.around, d.side, unused);
    }
    if (e != geo::MeasureError::none) throw Bad{t.source(), context + kind + ": " + geo::measure_error_sentence(e)};
    if (scene.measures.size() >= 8) throw Bad{t.source(), context + "a scene may declare at most 8 instruments"};
    scene.measures.push_back(d);
}

// [[bump]]: a hill or a mass of an uneven world (world/scene.hpp's SceneBump, docs/uneven.md).
void read_bump(const toml::table& t, int index, world::Scene& scene) {
    const std::string context = "bump " + std::to_string(index + 1) + ": ";
    const Reader r(t, context);
    r.only({"kind", "centre", "width", "strength"});
    world::SceneBump b;
    const std::string kind = r.string("kind", "");
    if (kind != "hill" && kind != "mass")
        throw Bad{t.source(), context + "expected kind = \"hill\" or \"mass\", found " +
                                  (kind.empty() ? std::string("none") : "\"" + world::printable(kind) + "\"")};
    b.mass = kind == "mass";
    r.pair("centre", b.r, b.theta_deg, 0, 1e6, "r, theta in degrees");
    b.width = r.number("width", b.width, -1e6, 1e6, "chart units");
    b.strength = r.number("strength", b.strength, -1e6, 1e6, b.mass ? "alpha" : "a");
    std::string why;
    if (!world::bump_within_ranges(b, index, scene, why)) throw Bad{t.source(), why};
    scene.bumps.push_back(b);
}

// backdrop = "earth" (with centre = [lat, lon], default Greenwich): the Earth's graticule and
// coastlines about that place (world/earth.hpp, the whole globe) in place of a [[grid]]: grid
// bodies, so that the game's collisions and the controls pass them by.
void read_backdrop(const Reader& r, const toml::table& root, world::Scene& s) {
    const toml::node* backdrop = root.get("backdrop");
    const toml::node* centre = root.get("centre");
    if (!backdrop) {
        if (centre) throw Bad{centre->source(), "'centre' places the Earth's backdrop: add backdrop = \"earth\", or remove it"};
        return;
    }
    const std::string kind = r.string("backdrop", "");
    if (kind != "earth")
        throw Bad{backdrop->source(), "expected backdrop = \"earth\" (the only backdrop), found \"" + world::printable(kind) + "\""};
    if (const toml::node* grid = root.get("grid"))
        throw Bad{grid->source(), "backdrop = \"earth\" is the scene's grid: remove the [[grid]] tables, or the backdrop"};
    double lat = 51.5, lon = 0;
    if (r.pair("centre", lat, lon, -90, 90, "latitude, longitude in degrees") && !(lon >= -180 && lon <= 180))
        throw Bad{centre->source(), "'centre' must be [latitude, longitude] with the longitude from -180 to 180 degrees"};
    world::Scene earth;
    world::earth_scene(earth, lat, lon);
    for (world::SceneBody& b : earth.bodies) s.bodies.push_back(std::move(b));
}

void read_scene(const toml::table& root, world::Scene& s, Images& images) {
    const Reader r(root, "");
    r.only({"curvature", "limit_radius", "presets", "thrust", "turn_rate", "curvature_rate", "sweep_rate", "body", "grid",
            "game", "measure", "backdrop", "centre", "bump", "strength_rate", "solid"});
    s.curvature = r.number("curvature", 0, -1, 1, "K");
    s.limit_radius = r.number("limit_radius", s.limit_radius, 1e-3, world::Ranges::kLimitRadius, "R in world units");
    s.thrust = r.number("thrust", s.thrust, 0, 1e3, "world units per second^2");
    s.turn_rate_deg = r.number("turn_rate", s.turn_rate_deg, 0, 1e5, "degrees per second");
    s.curvature_rate = r.number("curvature_rate", s.curvature_rate, 0, 100, "per second");
    s.sweep_rate = r.number("sweep_rate", 0, 0, 100, "per second");
    s.strength_rate = r.number("strength_rate", s.strength_rate, 0, 100, "gain per second");
    if (const toml::node* p = root.get("presets")) {
        const toml::array* a = p->as_array();
        if (!a || a->empty()) throw Bad{p->source(), std::string("expected presets = [K, ...], found ") + type_name(*p)};
        s.presets.clear();
        for (const toml::node& e : *a) s.presets.push_back(r.as_number(e, "presets", -1, 1, "K"));
    }
    read_solids(root, s);  // (first: a three-dimensional scene refuses the plane's tables)
    read_backdrop(r, root, s);
    if (const toml::array* grids = tables(root, "grid"))
        for (const toml::node& g : *grids) read_grid(*g.as_table(), s);
    if (const toml::array* bodies = tables(root, "body")) {
        int i = 0;
        for (const toml::node& b : *bodies) read_body(*b.as_table(), i++, s, images);
    }
    if (const toml::array* measures = tables(root, "measure")) {
        int i = 0;
        for (const toml::node& m : *measures) read_measure(*m.as_table(), i++, s);
    }
    if (const toml::node* game = root.get("game")) {
        const toml::table* t = game->as_table();
        if (!t) throw Bad{game->source(), std::string("expected a [game] table, found ") + type_name(*game)};
        read_game(*t, s.game, images);
        std::string why;
        if (!world::add_game_slots(s, why)) throw Bad{t->source(), "game: " + why};
    }
    if (const toml::array* bumps = tables(root, "bump")) {
        int i = 0;
        for (const toml::node& b : *bumps) read_bump(*b.as_table(), i++, s);
        std::string why;
        if (!world::uneven_scene_fits(s, why)) throw Bad{bumps->source(), why};
    }
}

}  // namespace

std::string SceneError::to_string() const {
    std::ostringstream o;
    o << world::printable(file, world::kPathLimit);
    if (line > 0) o << ':' << line << ':' << column;
    o << ": " << message;
    return o.str();
}

bool parse_scene(const std::string& text, const std::string& name, world::Scene& out, SceneError& error,
                 const ImageReader& reader, const FileIdentity& identify) {
    out = world::Scene{};
    out.name = name;
    Images images{reader, identify, name.substr(0, name.rfind('/') + 1), {}, {}, 0};
    return tomlr::parse_toml(text, name, error, [&](const toml::table& root) { read_scene(root, out, images); });
}

bool load_scene_file(const std::string& path, world::Scene& out, SceneError& error, const ImageReader& images,
                     const FileIdentity& identify) {
    std::string text, why;
    if (!read_text_file(path, kSceneFileLimit, "a scene file", text, why)) {
        error = {path, 0, 0, "the scene file: " + why + ": check the path, or name a built-in scene (see --help)"};
        return false;
    }
    return parse_scene(text, path, out, error, images, identify);
}

}  // namespace noneuclid::files
