// `noneuclid dump` of an uneven world (files/dump.hpp's line, for uneven/world.hpp): after "K",
// "gain" (the strength keys' factor) and "bumps", each with its kind, "center" ([r, theta] as
// the scene gives it), "chart" ([x, y]), "width" and "strength" (the scene's times the gain);
// each body with "center" ([r, theta] of the world of constant K at the world's K), "chart"
// ([x, y], the state the integrator carries), "heading" (its direction of travel as a chart
// angle, degrees), "facing", "travel" ([speed, heading]) and "vertices" ([r, theta] each, by the
// exponential map from its centre), so that anyone's integrator can check the paths.
#pragma once

#include <string>

#include "files/dump.hpp"
#include "uneven/world.hpp"

namespace noneuclid::files {

inline void dump_frame(const uneven::World& world, const DumpOptions&, std::string& out) {
    using detail::num;
    auto pair = [&](double a, double b) {
        out += '[';
        num(out, a);
        out += ',';
        num(out, b);
        out += ']';
    };
    out += "{\"frame\":" + std::to_string(world.frame) + ",\"t\":";
    num(out, world.time);
    out += ",\"K\":";
    num(out, world.K);
    out += ",\"gain\":";
    num(out, world.gain());
    out += ",\"bumps\":[";
    const uneven::Metric& m = world.metric();
    for (int i = 0; i < m.bump_count; ++i) {
        const uneven::Bump& b = m.bumps[i];
        out += i ? ",{\"kind\":\"" : "{\"kind\":\"";
        out += b.kind == uneven::BumpKind::mass ? "mass" : "hill";
        out += "\",\"center\":";
        const geo::Polar<double> p = world.polar(b.centre);
        detail::polar(out, p.r, p.theta);
        out += ",\"chart\":";
        pair(b.centre.x, b.centre.y);
        out += ",\"width\":";
        num(out, b.width);
        out += ",\"strength\":";
        num(out, b.strength);
        out += '}';
    }
    out += "],\"bodies\":[";
    bool first = true;
    for (const uneven::Body& b : world.bodies) {
        if (!b.active) continue;
        out += first ? "{\"name\":\"" : ",{\"name\":\"";
        first = false;
        for (char c : b.desc->name) {
            if (c == '"' || c == '\\') out += '\\';
            if (static_cast<unsigned char>(c) >= 0x20) out += c;
        }
        out += "\",\"kind\":\"";
        out += world::kind_name(b.desc->kind());
        out += "\",\"center\":";
        const geo::Polar<double> c = world.polar(b.g.x);
        detail::polar(out, c.r, c.theta);
        out += ",\"chart\":";
        pair(b.g.x.x, b.g.x.y);
        out += ",\"heading\":";
        num(out, detail::degrees(b.g.phi));
        out += ",\"facing\":";
        num(out, detail::degrees(b.facing));
        out += ",\"travel\":";
        pair(b.speed, detail::degrees(b.g.phi));
        out += ",\"vertices\":[";
        for (std::size_t i = 0; i < b.local.size(); ++i) {
            const geo::Polar<double> v = world.polar(world.vertex(b, i));
            if (i) out += ',';
            detail::polar(out, v.r, v.theta);
        }
        out += "]}";
    }
    out += "]}\n";
}

}  // namespace noneuclid::files
