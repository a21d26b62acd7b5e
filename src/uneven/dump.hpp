// `noneuclid dump` of an uneven world (files/dump.hpp's line, for uneven/world.hpp): after "K"
// (and a game's fields, as there), "gain" (the strength keys' factor) and "bumps", each with its kind, "center" ([r, theta] as
// the scene gives it), "chart" ([x, y]), "width" and "strength" (the scene's times the gain);
// each body with "center" ([r, theta] of the world of constant K at the world's K), "chart"
// ([x, y], the state the integrator carries), "heading" (its direction of travel as a chart
// angle, degrees), "facing", "travel" ([speed, heading]) and "vertices" ([r, theta] each, by the
// exponential map from its centre), so that anyone's integrator can check the paths; then, as
// files/dump.hpp, "measure": the triangles' readings (k_area_deg: the integral of K dA).
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
    detail::game_fields(world.game(), out);
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
    for (std::size_t bi = 0; bi < world.bodies.size(); ++bi) {
        const uneven::Body& b = world.bodies[bi];
        if (!b.active) continue;
        if (!first) out += ',';
        first = false;
        detail::body_head(out, b, world.game().size_of(bi));
        out += ",\"center\":";
        detail::polar(out, b.centre.r, b.centre.theta);
        const uneven::Vec2 x = world.chart(b.centre);
        out += ",\"chart\":";
        pair(x.x, x.y);
        out += ",\"heading\":";
        num(out, detail::degrees(b.travel));
        out += ",\"facing\":";
        num(out, detail::degrees(b.facing));
        out += ",\"travel\":";
        pair(b.speed, detail::degrees(b.travel));
        out += ",\"vertices\":[";
        for (std::size_t i = 0; i < b.local.size(); ++i) {
            const geo::Polar<double> v = world.polar(world.vertex(b, i));
            if (i) out += ',';
            detail::polar(out, v.r, v.theta);
        }
        out += "]}";
    }
    out += ']';
    detail::measure_tail(out, world.gauges());
}

}  // namespace noneuclid::files
