// [[solid]] tables: a three-dimensional scene's bodies (scene_solids.hpp).
#include "files/scene_solids.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "world/quote.hpp"

namespace noneuclid::files {
namespace {

using tomlr::Bad, tomlr::Reader, tomlr::tables, tomlr::type_name;

constexpr const char* kShapes[] = {"tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron"};
constexpr int kMaxSolids = 64, kMaxVertices = 64, kMaxEdges = 128;
constexpr double kReach = 100;  // (world units: any position, size or vertex past this is a mistake)

// [x, y, z]: three numbers within +-limit.
void triple(const Reader& r, const toml::node& n, const std::string& key, double out[3], double limit, const char* what,
            const std::string& context) {
    const toml::array* a = n.as_array();
    if (!a || a->size() != 3)
        throw Bad{n.source(), context + "expected " + world::quote(key) + " = [x, y, z] (" + what + "), found " +
                                  (a ? "an array of " + std::to_string(a->size()) : std::string(type_name(n)))};
    for (int i = 0; i < 3; ++i) out[i] = r.as_number(*a->get(i), key, -limit, limit, what);
}

void read_solid(const toml::table& t, int index, world::Scene& s) {
    world::SceneSolid b;
    b.name = Reader(t, "").string("name", "solid" + std::to_string(index + 1));
    const bool plain = std::all_of(b.name.begin(), b.name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == ' ' || c == '-' || c == '_' || c == '.';
    });
    if (!plain || b.name.empty() || b.name.size() > 40)
        throw Bad{t.source(), "solid " + std::to_string(index + 1) +
                                  ": expected a 'name' of 1 to 40 letters, digits, spaces, '-', '_' or '.', found " + world::quote(b.name)};
    const std::string context = "solid " + world::quote(b.name) + ": ";
    const Reader r(t, context);
    r.only({"name", "shape", "size", "vertices", "edges", "position", "velocity", "spin", "spin_axis", "color"});
    b.shape = r.string("shape", "");
    const toml::node* v = t.get("vertices");
    const toml::node* e = t.get("edges");
    if (b.shape.empty() == !v)
        throw Bad{t.source(), context + "give either shape = \"tetrahedron\", \"cube\", \"octahedron\", \"dodecahedron\" or "
                                        "\"icosahedron\", or its own 'vertices' and 'edges', not both or neither"};
    if (!b.shape.empty()) {
        bool known = false;
        for (const char* k : kShapes) known = known || b.shape == k;
        if (!known)
            throw Bad{t.get("shape")->source(), context + "expected shape = \"tetrahedron\", \"cube\", \"octahedron\", "
                                                          "\"dodecahedron\" or \"icosahedron\", found " + world::quote(b.shape)};
        if (e) throw Bad{e->source(), context + "a named shape has its own edges: remove 'edges', or 'shape'"};
        b.size = r.number("size", b.size, 1e-3, 10, "its circumradius in world units");
    } else {
        if (t.get("size")) throw Bad{t.get("size")->source(), context + "'size' scales a named shape: its own vertices are in world units"};
        const toml::array* vs = v->as_array();
        if (!vs || vs->empty() || vs->size() > kMaxVertices)
            throw Bad{v->source(), context + "expected 'vertices' = [[x, y, z], ...] with 1 to " + std::to_string(kMaxVertices) +
                                       " vertices, found " + (vs ? std::to_string(vs->size()) : std::string(type_name(*v)))};
        for (const toml::node& p : *vs) {
            std::array<double, 3> x{};
            triple(r, p, "vertices", x.data(), 10, "a vertex in the solid's frame, world units", context);
            b.vertices.push_back(x);
        }
        const toml::array* es = e ? e->as_array() : nullptr;
        if (!es || es->empty() || es->size() > kMaxEdges)
            throw Bad{e ? e->source() : t.source(), context + "expected 'edges' = [[i, j], ...] with 1 to " +
                                                        std::to_string(kMaxEdges) + " pairs of vertex numbers from 0"};
        for (const toml::node& p : *es) {
            const toml::array* a = p.as_array();
            const long n = static_cast<long>(b.vertices.size());
            auto at = [&](std::size_t i) { return a && a->get(i) && a->get(i)->as_integer() ? a->get(i)->as_integer()->get() : -1; };
            if (!a || a->size() != 2 || at(0) < 0 || at(0) >= n || at(1) < 0 || at(1) >= n || at(0) == at(1))
                throw Bad{p.source(), context + "expected each edge as [i, j], two different vertex numbers from 0 to " +
                                          std::to_string(n - 1)};
            b.edges.push_back({static_cast<int>(at(0)), static_cast<int>(at(1))});
        }
    }
    if (const toml::node* n = t.get("position")) {
        triple(r, *n, "position", b.position, kReach, "its centre, world units", context);
        if (std::hypot(b.position[0], std::hypot(b.position[1], b.position[2])) > s.limit_radius)
            throw Bad{n->source(), context + "'position' must lie within limit_radius of O: move it nearer, or raise limit_radius"};
    }
    if (const toml::node* n = t.get("velocity")) triple(r, *n, "velocity", b.velocity, 10, "world units a second", context);
    if (const toml::node* n = t.get("spin_axis")) {
        triple(r, *n, "spin_axis", b.spin_axis, kReach, "an axis in its frame", context);
        if (std::hypot(b.spin_axis[0], std::hypot(b.spin_axis[1], b.spin_axis[2])) == 0)
            throw Bad{n->source(), context + "'spin_axis' must not be [0, 0, 0]: give the axis it turns about"};
    }
    b.spin_deg = r.number("spin", 0, -3600, 3600, "degrees a second");
    b.color = r.color("color", b.color);
    s.solids.push_back(std::move(b));
}

}  // namespace

void read_solids(const toml::table& root, world::Scene& s) {
    const toml::array* solids = tables(root, "solid");
    if (!solids) return;
    for (const char* plane : {"body", "bump", "game", "measure", "backdrop", "grid"})
        if (const toml::node* n = root.get(plane))
            throw Bad{n->source(), std::string("a scene with [[solid]] tables is three-dimensional, and '") + plane +
                                       "' belongs to the plane: remove it, or the [[solid]] tables"};
    if (solids->size() > kMaxSolids)
        throw Bad{solids->source(), "a scene may have at most " + std::to_string(kMaxSolids) + " [[solid]] tables"};
    int i = 0;
    for (const toml::node& t : *solids) read_solid(*t.as_table(), i++, s);
    s.space = true;
}

}  // namespace noneuclid::files
