// `noneuclid dump`: a world's state as one line of JSON per frame (JSON Lines).
//
//   {"frame":0,"t":0,"K":-1,"bodies":[{"name":"ship","kind":"ship","center":[r,theta],"facing":psi,
//    "travel":[speed,chi],"vertices":[[r,theta],...],"edges":[[[r,theta],...],...],
//    "screen":[[[x,y],...],...]}]}
//
// kind is ship, asteroid, bullet, grid or body; a game's unused slots are left out, and its
// asteroids and bullets are named by their number ("asteroid 12": the twelfth spawned). A scene
// with a game gives each asteroid its "size" (0 large, 1 medium, 2 small) after its kind, and
// adds after "K": "phase" (ready, playing or over), "score", "lives", "level" and
// "events", what happened in the step that led to this frame:
//   {"start":true}  {"hit":["bullet 3","asteroid 12"]}  {"crash":"asteroid 7"}  {"level":2}
//   {"over":1230} (the final score)
// A world with an instrument on adds after "bodies" "measure": each instrument's readings
// (files/measure_json.hpp), the scene's first, the live one last.
// Angles in degrees in (-180, 180]; lengths in world units. Each edge lists its points from one
// vertex to the next, both ends included (tessellation + 1 points); "screen" holds the same
// points in pixels with the same nesting, for a canvas of the given size: the disc the
// projection shows (geo::shown_radius: R, or less on the sphere) fills the smaller side,
// centred, through the given projection; a point the projection cannot show is null.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "geometry/geometry.hpp"
#include "files/measure_json.hpp"
#include "world/world.hpp"

namespace noneuclid::files {

struct DumpOptions {
    int width = 800, height = 480;
    geo::Projection projection = geo::Projection::azimuthal_equidistant;
};

namespace detail {
inline void num(std::string& out, double v) {
    char buf[32];
    if (!std::isfinite(v)) {
        out += "null";  // JSON has no NaN; the paper engine can produce one
        return;
    }
    std::snprintf(buf, sizeof buf, "%.9g", v == 0 ? 0.0 : v);
    out += buf;
}
// In (-180, 180] as printed: an angle that num() would round to -180 (within half its last
// digit, 5e-7) is given as the same angle near +180.
inline double degrees(double rad) {
    double d = std::remainder(rad, 2 * 3.14159265358979323846) * (180 / 3.14159265358979323846);
    return d <= -180 + 5e-7 ? d + 360 : d;
}
inline void polar(std::string& out, double r, double theta) {
    out += '[';
    num(out, r);
    out += ',';
    num(out, degrees(theta));
    out += ']';
}
// "asteroid 12", "bullet 3": a game's body by its number.
inline void serial_name(std::string& out, world::BodyKind kind, uint32_t serial) {
    out += world::kind_name(kind);
    out += ' ';
    out += std::to_string(serial);
}
template <class G>
void game_fields(const G& g, std::string& out) {
    if (!g.on()) return;
    static const char* const phases[] = {"ready", "playing", "over"};
    out += ",\"phase\":\"";
    out += phases[static_cast<int>(g.phase)];
    out += "\",\"score\":" + std::to_string(g.score) + ",\"lives\":" + std::to_string(g.lives) +
           ",\"level\":" + std::to_string(g.level) + ",\"events\":[";
    for (int i = 0; i < g.event_count(); ++i) {
        const world::GameEvent& e = g.events()[i];
        if (i) out += ',';
        switch (e.kind) {
            case world::GameEvent::start: out += "{\"start\":true}"; break;
            case world::GameEvent::hit:
                out += "{\"hit\":[\"";
                serial_name(out, world::BodyKind::bullet, e.bullet);
                out += "\",\"";
                serial_name(out, world::BodyKind::asteroid, e.asteroid);
                out += "\"]}";
                break;
            case world::GameEvent::crash:
                out += "{\"crash\":\"";
                serial_name(out, world::BodyKind::asteroid, e.asteroid);
                out += "\"}";
                break;
            case world::GameEvent::level: out += "{\"level\":" + std::to_string(e.value) + "}"; break;
            case world::GameEvent::over: out += "{\"over\":" + std::to_string(e.value) + "}"; break;
        }
    }
    out += ']';
}
// A body's opening fields: {"name":...,"kind":...(,"size":N for a game's asteroid).
template <class B>
void body_head(std::string& out, const B& b, int size) {
    out += "{\"name\":\"";
    if (b.serial != 0) {
        serial_name(out, b.desc->kind(), b.serial);
    } else {
        for (char c : b.desc->name) {
            if (c == '"' || c == '\\') out += '\\';
            if (static_cast<unsigned char>(c) >= 0x20) out += c;
        }
    }
    out += "\",\"kind\":\"";
    out += world::kind_name(b.desc->kind());
    out += '"';
    if (size >= 0) out += ",\"size\":" + std::to_string(size);
}
// The line's end: "measure", the readings of every instrument that is on, then the close.
template <class Gauges>
void measure_tail(std::string& out, const Gauges& gauges) {
    bool listed = false;
    for (const auto& g : gauges) {
        if (!g.on()) continue;
        out += listed ? "," : ",\"measure\":[";
        listed = true;
        append_gauge_json(out, g.reading());
    }
    out += listed ? "]}\n" : "}\n";
}
}  // namespace detail

// Appends one frame's line (with its newline) to `out`.
template <class W>
void dump_frame(const W& world, const DumpOptions& o, std::string& out) {
    using T = typename W::scalar;
    using detail::num;
    const double K = static_cast<double>(world.K), R = static_cast<double>(world.R);
    const double scale = 0.5 * std::min(o.width, o.height) / geo::rim_rho(K, R, o.projection);
    const double cx = 0.5 * o.width, cy = 0.5 * o.height;
    out += "{\"frame\":";
    out += std::to_string(world.frame);
    out += ",\"t\":";
    num(out, world.time);
    out += ",\"K\":";
    num(out, K);
    detail::game_fields(world.game(), out);
    out += ",\"bodies\":[";
    std::vector<geo::Polar<T>> v;
    std::vector<std::vector<geo::Polar<T>>> edges;
    bool first = true;
    for (std::size_t bi = 0; bi < world.bodies.size(); ++bi) {
        const world::Body<T>& b = world.bodies[bi];
        if (!b.active) continue;
        v.resize(b.local.size());
        world.vertices(b, v.data());
        const std::size_t n = v.size();
        const std::size_t ne = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
        edges.assign(ne, {});
        for (std::size_t e = 0; e < ne; ++e) {
            edges[e].resize(static_cast<std::size_t>(b.desc->tessellation) + 1);
            W::engine::edge_points(world.K, v[e], v[(e + 1) % n], b.desc->tessellation,
                                   [&](int k, geo::Polar<T> p) { edges[e][static_cast<std::size_t>(k)] = p; });
        }
        if (!first) out += ',';
        first = false;
        detail::body_head(out, b, world.game().size_of(bi));
        out += ",\"center\":";
        detail::polar(out, static_cast<double>(b.centre.r), static_cast<double>(b.centre.theta));
        out += ",\"facing\":";
        num(out, detail::degrees(static_cast<double>(b.facing)));
        out += ",\"travel\":[";
        num(out, static_cast<double>(b.speed));
        out += ',';
        num(out, detail::degrees(static_cast<double>(b.travel)));
        out += "],\"vertices\":[";
        for (std::size_t i = 0; i < n; ++i) {
            if (i) out += ',';
            detail::polar(out, static_cast<double>(v[i].r), static_cast<double>(v[i].theta));
        }
        out += "],\"edges\":[";
        for (std::size_t e = 0; e < ne; ++e) {
            out += e ? ",[" : "[";
            for (std::size_t k = 0; k < edges[e].size(); ++k) {
                if (k) out += ',';
                detail::polar(out, static_cast<double>(edges[e][k].r), static_cast<double>(edges[e][k].theta));
            }
            out += ']';
        }
        out += "],\"screen\":[";
        for (std::size_t e = 0; e < ne; ++e) {
            out += e ? ",[" : "[";
            for (std::size_t k = 0; k < edges[e].size(); ++k) {
                if (k) out += ',';
                const double r = static_cast<double>(edges[e][k].r), th = static_cast<double>(edges[e][k].theta);
                const geo::Projected<double> p = geo::project(K, r, o.projection);
                if (!p.visible || !std::isfinite(p.rho) || !std::isfinite(th)) {
                    out += "null";
                    continue;
                }
                out += '[';
                num(out, cx + scale * p.rho * std::cos(th));
                out += ',';
                num(out, cy - scale * p.rho * std::sin(th));
                out += ']';
            }
            out += ']';
        }
        out += "]}";
    }
    out += ']';
    detail::measure_tail(out, world.gauges());
}

}  // namespace noneuclid::files
