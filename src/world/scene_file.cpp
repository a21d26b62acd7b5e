#include "world/scene_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <toml++/toml.h>

namespace noneuclid::world {
namespace {

// Thrown inside the parser, caught at the top, turned into a SceneError.
struct Bad {
    toml::source_region where;
    std::string message;
};

const char* type_name(const toml::node& n) {
    switch (n.type()) {
        case toml::node_type::string: return "a string";
        case toml::node_type::integer: return "an integer";
        case toml::node_type::floating_point: return "a number";
        case toml::node_type::boolean: return "a boolean";
        case toml::node_type::array: return "an array";
        case toml::node_type::table: return "a table";
        case toml::node_type::date: return "a date";
        case toml::node_type::time: return "a time";
        case toml::node_type::date_time: return "a date-time";
        default: return "nothing";
    }
}

std::string quote(std::string_view s) {
    std::string q;  // (built with append: GCC 12 warns falsely on "'" + std::string(s))
    q.reserve(s.size() + 2);
    q.append(1, '\'').append(s).append(1, '\'');
    return q;
}

class Reader {
public:
    Reader(const toml::table& t, std::string context) : t_(t), context_(std::move(context)) {}

    // Every key must be one we know: a typo is an error, not a silently ignored line.
    void only(std::initializer_list<const char*> known) const {
        for (auto&& [key, node] : t_) {
            bool ok = false;
            for (const char* k : known) ok = ok || key.str() == k;
            if (!ok) {
                std::string list;
                for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
                throw Bad{key.source(), context_ + "unknown key " + quote(key.str()) + " (expected one of: " + list + ")"};
            }
        }
    }

    double number(const char* key, double fallback, double lo, double hi, const char* what) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        return as_number(*n, key, lo, hi, what);
    }
    double as_number(const toml::node& n, const std::string& key, double lo, double hi, const char* what) const {
        double v;
        if (auto f = n.as_floating_point())
            v = f->get();
        else if (auto i = n.as_integer())
            v = static_cast<double>(i->get());
        else
            throw Bad{n.source(), context_ + "expected a number for " + quote(key) + " (" + what + "), found " + type_name(n)};
        if (!std::isfinite(v) || v < lo || v > hi) {
            std::ostringstream m;
            m << context_ << quote(key) << " must be from " << lo << " to " << hi << " (" << what << "), found " << v;
            throw Bad{n.source(), m.str()};
        }
        return v;
    }
    bool boolean(const char* key, bool fallback) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        if (auto b = n->as_boolean()) return b->get();
        throw Bad{n->source(), context_ + "expected true or false for " + quote(key) + ", found " + type_name(*n)};
    }
    std::string string(const char* key, const std::string& fallback) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        if (auto s = n->as_string()) return s->get();
        throw Bad{n->source(), context_ + "expected a string for " + quote(key) + ", found " + type_name(*n)};
    }
    long integer(const char* key, long fallback, long lo, long hi, const char* what) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        auto i = n->as_integer();
        if (!i) throw Bad{n->source(), context_ + "expected a whole number for " + quote(key) + " (" + what + "), found " + type_name(*n)};
        if (i->get() < lo || i->get() > hi) {
            std::ostringstream m;
            m << context_ << quote(key) << " must be from " << lo << " to " << hi << " (" << what << "), found " << i->get();
            throw Bad{n->source(), m.str()};
        }
        return static_cast<long>(i->get());
    }
    // [a, b]: two numbers.
    bool pair(const char* key, double& a, double& b, double alo, double ahi, const char* what) const {
        const toml::node* n = t_.get(key);
        if (!n) return false;
        const toml::array* arr = n->as_array();
        if (!arr || arr->size() != 2)
            throw Bad{n->source(), context_ + "expected " + quote(key) + " = [" + what + "], found " +
                                       (arr ? "an array of " + std::to_string(arr->size()) : std::string(type_name(*n)))};
        a = as_number(*arr->get(0), key, alo, ahi, what);
        b = as_number(*arr->get(1), key, -1e6, 1e6, what);
        return true;
    }
    Rgb color(const char* key, Rgb fallback) const {
        const toml::node* n = t_.get(key);
        if (!n) return fallback;
        auto s = n->as_string();
        const std::string v = s ? s->get() : "";
        auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
        if (!s || v.size() != 7 || v[0] != '#' || !std::all_of(v.begin() + 1, v.end(), hex))
            throw Bad{n->source(), context_ + "expected a colour \"#rrggbb\" for " + quote(key) + ", found " +
                                       (s ? "\"" + v + "\"" : std::string(type_name(*n)))};
        const unsigned long x = std::stoul(v.substr(1), nullptr, 16);
        return {static_cast<uint8_t>(x >> 16), static_cast<uint8_t>(x >> 8), static_cast<uint8_t>(x)};
    }
    const toml::table& table() const { return t_; }

private:
    const toml::table& t_;
    std::string context_;
};

// [[body]] and [[grid]] are arrays of tables.
const toml::array* tables(const toml::table& root, const char* key) {
    const toml::node* n = root.get(key);
    if (!n) return nullptr;
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables())
        throw Bad{n->source(), std::string("expected [[") + key + "]] tables, found " + type_name(*n)};
    return a;
}

void read_body(const toml::table& t, int index, Scene& scene) {
    SceneBody b;
    {
        const Reader pre(t, "");
        b.name = pre.string("name", "body" + std::to_string(index + 1));
    }
    const Reader r(t, "body " + quote(b.name) + ": ");
    r.only({"name", "position", "facing", "velocity", "acceleration", "spin", "color", "closed", "tessellation",
            "vertices", "controlled", "grid"});
    r.pair("position", b.r, b.theta_deg, 0, 1e4, "r, theta in degrees");
    b.facing_deg = r.number("facing", 0, -1e6, 1e6, "degrees");
    r.pair("velocity", b.speed, b.direction_deg, 0, 1e3, "speed in world units per second, direction in degrees");
    r.pair("acceleration", b.accel, b.accel_direction_deg, 0, 1e3, "world units per second^2, direction in degrees");
    b.spin_deg = r.number("spin", 0, -1e6, 1e6, "degrees per second");
    b.color = r.color("color", b.color);
    b.closed = r.boolean("closed", true);
    b.tessellation = static_cast<int>(r.integer("tessellation", 8, 1, 256, "segments per edge"));
    b.controlled = r.boolean("controlled", b.name == "ship");
    b.grid = r.boolean("grid", false);
    const toml::node* v = t.get("vertices");
    if (!v) throw Bad{t.source(), "body " + quote(b.name) + ": expected 'vertices' = [[rho, phi], ...], found none"};
    const toml::array* arr = v->as_array();
    if (!arr || arr->empty())
        throw Bad{v->source(), "body " + quote(b.name) + ": expected 'vertices' = [[rho, phi], ...] with at least one vertex, found " +
                                   (arr ? "an empty array" : std::string(type_name(*v)))};
    for (const toml::node& e : *arr) {
        const toml::array* p = e.as_array();
        if (!p || p->size() != 2)
            throw Bad{e.source(), "body " + quote(b.name) + ": expected each vertex as [rho, phi in degrees], found " +
                                      (p ? "an array of " + std::to_string(p->size()) : std::string(type_name(e)))};
        SceneBody::Vertex vx;
        vx.rho = r.as_number(*p->get(0), "vertices", 0, 1e4, "rho, distance from the centre");
        vx.phi_deg = r.as_number(*p->get(1), "vertices", -1e6, 1e6, "phi in degrees from the facing");
        b.vertices.push_back(vx);
    }
    scene.bodies.push_back(std::move(b));
}

void read_grid(const toml::table& t, Scene& scene) {
    const Reader r(t, "grid: ");
    r.only({"kind", "spacing", "lines", "length", "step", "color"});
    const std::string kind = r.string("kind", "axes");
    const double length = r.number("length", scene.limit_radius, 0.01, 1e4, "world units");
    const double step = r.number("step", 0.25, 0.001, 1e4, "world units between vertices");
    const Rgb color = r.color("color", {70, 90, 120});
    if (kind == "axes") {
        add_axis_grid(scene, r.number("spacing", 0.5, 0.01, 1e4, "world units"), length, step, color);
    } else if (kind == "radial") {
        add_radial_grid(scene, static_cast<int>(r.integer("lines", 12, 1, 360, "lines")), length, step, color);
    } else {
        throw Bad{t.get("kind")->source(), "grid: expected kind = \"axes\" or \"radial\", found \"" + kind + "\""};
    }
}

void read_scene(const toml::table& root, Scene& s) {
    const Reader r(root, "");
    r.only({"curvature", "limit_radius", "presets", "thrust", "turn_rate", "curvature_rate", "sweep_rate", "body", "grid"});
    s.curvature = r.number("curvature", 0, -1, 1, "K");
    s.limit_radius = r.number("limit_radius", s.limit_radius, 1e-3, 1e4, "R in world units");
    s.thrust = r.number("thrust", s.thrust, 0, 1e3, "world units per second^2");
    s.turn_rate_deg = r.number("turn_rate", s.turn_rate_deg, 0, 1e5, "degrees per second");
    s.curvature_rate = r.number("curvature_rate", s.curvature_rate, 0, 100, "per second");
    s.sweep_rate = r.number("sweep_rate", 0, 0, 100, "per second");
    if (const toml::node* p = root.get("presets")) {
        const toml::array* a = p->as_array();
        if (!a || a->empty()) throw Bad{p->source(), std::string("expected presets = [K, ...], found ") + type_name(*p)};
        s.presets.clear();
        for (const toml::node& e : *a) s.presets.push_back(r.as_number(e, "presets", -1, 1, "K"));
    }
    if (const toml::array* grids = tables(root, "grid"))
        for (const toml::node& g : *grids) read_grid(*g.as_table(), s);
    if (const toml::array* bodies = tables(root, "body")) {
        int i = 0;
        for (const toml::node& b : *bodies) read_body(*b.as_table(), i++, s);
    }
}

}  // namespace

std::string SceneError::to_string() const {
    std::ostringstream o;
    o << file;
    if (line > 0) o << ':' << line << ':' << column;
    o << ": " << message;
    return o.str();
}

bool parse_scene(const std::string& text, const std::string& name, Scene& out, SceneError& error) {
    out = Scene{};
    out.name = name;
    try {
        const toml::table root = toml::parse(text, name);
        read_scene(root, out);
        return true;
    } catch (const toml::parse_error& e) {
        error = {name, static_cast<long>(e.source().begin.line), static_cast<long>(e.source().begin.column),
                 "not valid TOML: " + std::string(e.description())};
    } catch (const Bad& b) {
        error = {name, static_cast<long>(b.where.begin.line), static_cast<long>(b.where.begin.column), b.message};
    }
    return false;
}

bool load_scene_file(const std::string& path, Scene& out, SceneError& error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = {path, 0, 0, "cannot read the scene file: check the path, or name a built-in scene (see --help)"};
        return false;
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parse_scene(text.str(), path, out, error);
}

}  // namespace noneuclid::world
