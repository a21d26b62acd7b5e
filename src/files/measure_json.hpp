// An instrument's readings as one JSON object (`noneuclid measure`, and each frame's "measure"
// list in `noneuclid dump`; docs/file-formats.md names every field):
//
//   {"instrument":"triangle","K":k,"points":[[r,theta],...],"sides":[a,b,c],
//    "angles":[A,B,C],"angle_sum":s,"excess":e,"area":x,"K_area":k}
//   {"instrument":"circle","K":k,"centre":[r,theta],"radius":rho,"circumference":c,
//    "flat_circumference":c0,"circumference_ratio":q,"area":x,"flat_area":x0,"area_ratio":q}
//   {"instrument":"parallels","K":k,"distance":d,"length":s,"apart":w,"ratio":q,"meet":bool,
//    "meet_at":m}                                        (meet_at null unless they meet)
//   {"instrument":"polygon","K":k,"sides":p,"around":q,"side":a,"angle":alpha,"gap":g,
//    "closing_K":k0}
//
// Angles (and "excess", "K_area", "gap") in degrees, lengths in world units, areas in world
// units squared; 17 significant digits, so that a reading round-trips exactly. An instrument
// whose construction is bad has "error": its sentence, and no readings.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "geometry/measure.hpp"
#include "world/instruments.hpp"

namespace noneuclid::files {

namespace measure_detail {
inline void num(std::string& out, double v) {
    if (!std::isfinite(v)) {
        out += "null";
        return;
    }
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v == 0 ? 0.0 : v);
    out += buf;
}
inline void field(std::string& out, const char* name, double v) {
    out += ",\"";
    out += name;
    out += "\":";
    num(out, v);
}
inline void list(std::string& out, const char* name, const double* v, int n) {
    out += ",\"";
    out += name;
    out += "\":[";
    for (int i = 0; i < n; ++i) {
        if (i) out += ',';
        num(out, v[i]);
    }
    out += ']';
}
inline void point(std::string& out, geo::Polar<double> p) {
    const double v[2] = {p.r, p.theta * 180 / 3.141592653589793};
    out += '[';
    num(out, v[0]);
    out += ',';
    num(out, v[1]);
    out += ']';
}
inline void head(std::string& out, geo::Instrument i, double K) {
    out += "{\"instrument\":\"";
    out += geo::instrument_name(i);
    out += "\"";
    field(out, "K", K);
}
inline bool failed(std::string& out, geo::MeasureError e) {
    if (e == geo::MeasureError::none) return false;
    out += ",\"error\":\"";
    out += geo::measure_error_sentence(e);
    out += "\"}";
    return true;
}
}  // namespace measure_detail

inline void append_triangle_json(std::string& out, double K, const geo::Polar<double> v[3], geo::MeasureError e,
                                 const geo::TriangleReading& t) {
    using namespace measure_detail;
    head(out, geo::Instrument::triangle, K);
    out += ",\"points\":[";
    for (int i = 0; i < 3; ++i) {
        if (i) out += ',';
        point(out, v[i]);
    }
    out += ']';
    if (failed(out, e)) return;
    list(out, "sides", t.side, 3);
    list(out, "angles", t.angle_deg, 3);
    field(out, "angle_sum", t.sum_deg);
    field(out, "excess", t.excess_deg);
    field(out, "area", t.area);
    field(out, "K_area", t.k_area_deg);
    out += '}';
}

inline void append_circle_json(std::string& out, double K, geo::Polar<double> centre, double rho, geo::MeasureError e,
                               const geo::CircleReading& c) {
    using namespace measure_detail;
    head(out, geo::Instrument::circle, K);
    out += ",\"centre\":";
    point(out, centre);
    field(out, "radius", rho);
    if (failed(out, e)) return;
    field(out, "circumference", c.circumference);
    field(out, "flat_circumference", c.flat_circumference);
    field(out, "circumference_ratio", c.circumference_ratio);
    field(out, "area", c.area);
    field(out, "flat_area", c.flat_area);
    field(out, "area_ratio", c.area_ratio);
    out += '}';
}

inline void append_parallels_json(std::string& out, double K, double d, double s, geo::MeasureError e,
                                  const geo::ParallelsReading& p) {
    using namespace measure_detail;
    head(out, geo::Instrument::parallels, K);
    field(out, "distance", d);
    field(out, "length", s);
    if (failed(out, e)) return;
    field(out, "apart", p.distance);
    field(out, "ratio", p.ratio);
    out += p.meet ? ",\"meet\":true" : ",\"meet\":false";
    field(out, "meet_at", p.meet ? p.meet_at : NAN);
    out += '}';
}

inline void append_polygon_json(std::string& out, double K, int p, int q, double a, geo::MeasureError e,
                                const geo::PolygonReading& r) {
    using namespace measure_detail;
    head(out, geo::Instrument::polygon, K);
    out += ",\"sides\":" + std::to_string(p) + ",\"around\":" + std::to_string(q);
    field(out, "side", a);
    if (failed(out, e)) return;
    field(out, "angle", r.angle_deg);
    field(out, "gap", r.gap_deg);
    field(out, "closing_K", r.closing_K);
    out += '}';
}

// A world's gauge (world/instruments.hpp): its instrument's object, or, while a live one waits
// for marks, {"instrument":...,"K":k,"waiting":true,"marks":n,"needed":m}.
inline void append_gauge_json(std::string& out, const world::GaugeReading& r) {
    using namespace measure_detail;
    if (r.waiting) {
        head(out, r.kind, r.K);
        out += ",\"waiting\":true,\"marks\":" + std::to_string(r.marks) + ",\"needed\":" + std::to_string(r.needed) + "}";
        return;
    }
    switch (r.kind) {
        case geo::Instrument::triangle: return append_triangle_json(out, r.K, r.points, r.error, r.triangle);
        case geo::Instrument::circle: return append_circle_json(out, r.K, r.points[0], r.radius, r.error, r.circle);
        case geo::Instrument::parallels: return append_parallels_json(out, r.K, r.distance, r.length, r.error, r.parallels);
        case geo::Instrument::polygon: return append_polygon_json(out, r.K, r.sides, r.around, r.side, r.error, r.polygon);
    }
}

}  // namespace noneuclid::files
