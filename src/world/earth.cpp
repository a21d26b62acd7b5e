// The earth scene (world/earth.hpp): lat/lon to polar coordinates about the centre, and the
// coastlines and graticule as polylines whose every point keeps its distance and bearing.
#include "world/earth.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "world/earth_data.hpp"

namespace noneuclid::world {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;

// The data is checked when it is compiled: the polylines tile kPoints in order, each has two
// points or more, and every point is a latitude and longitude. A damaged header does not build.
constexpr bool earth_data_whole() {
    int32_t next = 0;
    for (const earth_data::Line& l : earth_data::kLines) {
        if (l.first != next || l.count < 2) return false;
        next += l.count;
    }
    if (next != static_cast<int32_t>(std::size(earth_data::kPoints))) return false;
    for (const auto& p : earth_data::kPoints)
        if (p[0] < -900000 || p[0] > 900000 || p[1] < -1800000 || p[1] > 1800000) return false;
    return true;
}
static_assert(earth_data_whole(), "src/world/earth_data.hpp is damaged: regenerate it (platform/tools/earth_coastlines.py)");

struct V3 {
    double x, y, z;
};
V3 unit(double lat, double lon) {
    const double p = lat * kDeg, l = lon * kDeg;
    return {std::cos(p) * std::cos(l), std::cos(p) * std::sin(l), std::sin(p)};
}
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The centre's frame: east, north and up, as unit vectors of the Earth's.
struct Frame {
    V3 east, north, up;
    Frame(double lat0, double lon0) {
        const double p = lat0 * kDeg, l = lon0 * kDeg;
        east = {-std::sin(l), std::cos(l), 0};
        north = {-std::sin(p) * std::cos(l), -std::sin(p) * std::sin(l), std::cos(p)};
        up = unit(lat0, lon0);
    }
    // r from atan2 (no acos: exact near the centre and the antipode), theta from east.
    SceneBody::Vertex polar(V3 v) const {
        const double e = dot(v, east), n = dot(v, north), u = dot(v, up);
        return {std::atan2(std::hypot(e, n), u), std::atan2(n, e) / kDeg};
    }
};

// A polyline's edges are geodesics of whatever K the world has, between points that keep their
// distance and bearing. So that the drawn line stays on the Earth's line at every K, an edge is
// halved (at its great circle's midpoint) until it is at most kStep long at K = -1, where the
// same two polar points are farthest apart. Within a few degrees of the antipode, where a short
// arc spans a wide range of bearings, halving kMaxDepth times is not enough and the line breaks:
// that is the limit circle at K = +1.
constexpr double kStep = 0.1;
constexpr int kMaxDepth = 8;
// A body's vertices at most (Budget::kVerticesPerBody is far above it): a longer line goes on
// in a new body from the same point.
constexpr std::size_t kPieceVertices = 4000;
// Zoomed in (--view), the lines are kept to the view: a line ends at its first vertex past
// kCullMargin outside the limit circle, and an edge whose every point lies farther (both ends
// farther than half its length) is not halved at all.
constexpr double kCullMargin = 0.25;

double hyperbolic_length(SceneBody::Vertex a, SceneBody::Vertex b) {
    const double dr = std::sinh((a.rho - b.rho) / 2), s = std::sin((a.phi_deg - b.phi_deg) * kDeg / 2);
    return 2 * std::asinh(std::sqrt(dr * dr + std::sinh(a.rho) * std::sinh(b.rho) * s * s));
}

// The places' polar coordinates in the world: the centre's frame, and the world units a radian
// of the Earth is (1 / sqrt K when zoomed, earth_view_curvature; else 1).
struct Placing {
    Frame frame;
    double scale = 1, cull = 1e300;
    int depth = kMaxDepth;
    SceneBody::Vertex polar(V3 v) const {
        SceneBody::Vertex p = frame.polar(v);
        p.rho *= scale;
        return p;
    }
};

double arc(V3 a, V3 b) {
    const V3 c{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    return std::atan2(std::sqrt(dot(c, c)), dot(a, b));
}

class Lines {
public:
    Lines(Scene& s, const Placing& f, const char* name, Rgb color) : scene_(s), frame_(f), name_(name), color_(color) {}
    void start(V3 p) {
        flush();
        last_ = p;
        outside_ = false;
        add(frame_.polar(p));
    }
    // The line on to p along the great circle.
    void to(V3 p) {
        edge(last_, p, 0);
        last_ = p;
    }
    // Ends the line; closed: it was a ring, drawn whole (its last edge back to its start).
    void end(bool closed) {
        if (closed && !broken_ && piece_.size() > 2) {
            piece_.pop_back();  // the start again
            flush(true);
        }
        flush();
        broken_ = false;
    }

private:
    void edge(V3 a, V3 b, int depth) {
        const SceneBody::Vertex pa = frame_.polar(a), pb = frame_.polar(b);
        if (std::fmin(pa.rho, pb.rho) - arc(a, b) * frame_.scale / 2 > frame_.cull) {
            flush();
            broken_ = true;
            outside_ = true, outside_at_ = pb;
            return;
        }
        if (hyperbolic_length(pa, pb) <= kStep) return add(pb);
        if (depth >= frame_.depth) {
            flush();
            broken_ = true;
            return add(pb);
        }
        V3 m{a.x + b.x, a.y + b.y, a.z + b.z};
        const double n = std::sqrt(dot(m, m));
        if (n < 1e-12) return add(pb);  // (antipodal ends: not in the data)
        m = {m.x / n, m.y / n, m.z / n};
        edge(a, m, depth + 1);
        edge(m, b, depth + 1);
    }
    void add(SceneBody::Vertex v) {
        if (v.rho > frame_.cull) {  // outside the view: the line ends here, or waits here
            if (!piece_.empty()) {
                piece_.push_back(v);
                flush();
                broken_ = true;
            }
            outside_ = true, outside_at_ = v;
            return;
        }
        if (piece_.empty() && outside_) piece_.push_back(outside_at_);  // (from just outside)
        outside_ = false;
        piece_.push_back(v);
        if (piece_.size() >= kPieceVertices) {
            flush();
            broken_ = true;
            piece_.push_back(v);
        }
    }
    void flush(bool closed = false) {
        if (piece_.size() >= 2) {
            SceneBody b;
            char name[48];
            std::snprintf(name, sizeof name, "%s %d", name_, ++count_);
            b.name = name;
            b.color = color_;
            b.closed = closed;
            b.grid = true;
            b.tessellation = 2;
            b.vertices = std::move(piece_);
            scene_.bodies.push_back(std::move(b));
        }
        piece_.clear();
    }
    Scene& scene_;
    const Placing& frame_;
    const char* name_;
    Rgb color_;
    std::vector<SceneBody::Vertex> piece_;
    V3 last_{};
    SceneBody::Vertex outside_at_{};
    int count_ = 0;
    bool broken_ = false, outside_ = false;
};

const Rgb kGraticule{55, 70, 95}, kCoast{130, 215, 150}, kTissot{235, 165, 70};

// Meridians every 15 degrees from pole to pole, parallels every 15 degrees from 75 S to 75 N,
// a point every 3 degrees (the halving above adds more where K = -1 needs them).
void graticule(Scene& s, const Placing& f) {
    Lines meridians(s, f, "meridian", kGraticule);
    for (int lon = -180; lon < 180; lon += 15) {
        meridians.start(unit(-90, lon));
        for (int lat = -87; lat <= 90; lat += 3) meridians.to(unit(lat, lon));
        meridians.end(false);
    }
    Lines parallels(s, f, "parallel", kGraticule);
    for (int lat = -75; lat <= 75; lat += 15) {
        parallels.start(unit(lat, -180));
        for (int lon = -177; lon <= 180; lon += 3) parallels.to(unit(lat, lon));
        parallels.end(true);
    }
}

void coastlines(Scene& s, const Placing& f) {
    Lines coast(s, f, "coast", kCoast);
    for (const earth_data::Line& l : earth_data::kLines) {
        auto at = [](int32_t i) { return unit(earth_data::kPoints[i][0] * 1e-4, earth_data::kPoints[i][1] * 1e-4); };
        coast.start(at(l.first));
        for (int32_t i = 1; i < l.count; ++i) coast.to(at(l.first + i));
        if (l.closed) coast.to(at(l.first));
        coast.end(l.closed);
    }
}

// Tissot's circles: about each place of the grid, the points kTissotRadiusKm away at every
// kTissotBearingDeg of bearing, joined as a closed ring (great-circle chords: each bulges
// inward from the circle by at most a (1 - cos(step / 2)), 0.48 km).
constexpr int kTissotBearingDeg = 5;
void tissot(Scene& s, const Placing& f) {
    Lines circles(s, f, "tissot", kTissot);
    const double a = kTissotRadiusKm / kEarthRadiusKm;
    auto circle = [&](double lat, double lon) {
        const Frame c(lat, lon);
        auto at = [&](int bearing) {
            const double b = bearing * kDeg, h = std::sin(a);
            return V3{std::cos(a) * c.up.x + h * (std::cos(b) * c.north.x + std::sin(b) * c.east.x),
                      std::cos(a) * c.up.y + h * (std::cos(b) * c.north.y + std::sin(b) * c.east.y),
                      std::cos(a) * c.up.z + h * (std::cos(b) * c.north.z + std::sin(b) * c.east.z)};
        };
        circles.start(at(0));
        for (int b = kTissotBearingDeg; b < 360; b += kTissotBearingDeg) circles.to(at(b));
        circles.to(at(0));
        circles.end(true);
    };
    for (int lat = -90 + kTissotGridDeg; lat < 90; lat += kTissotGridDeg)
        for (int lon = -180; lon < 180; lon += kTissotGridDeg) circle(lat, lon);
    circle(90, 0);
    circle(-90, 0);
}

}  // namespace

EarthPolar earth_polar(double lat0, double lon0, double lat, double lon) {
    const SceneBody::Vertex v = Frame(lat0, lon0).polar(unit(lat, lon));
    return {v.rho, v.phi_deg};
}

bool parse_centre(const std::string& text, double& lat, double& lon) {
    const char* s = text.c_str();
    char* end = nullptr;
    const double a = std::strtod(s, &end);
    if (end == s || *end != ',') return false;
    const char* t = end + 1;
    const double b = std::strtod(t, &end);
    if (end == t || *end != '\0') return false;
    if (!(a >= -90 && a <= 90 && b >= -180 && b <= 180)) return false;  // (NaN fails too)
    lat = a, lon = b;
    return true;
}

double earth_view_curvature(double view_km) {
    const double q = view_km / (kPi * kEarthRadiusKm);
    return q * q;
}

void earth_scene(Scene& s, double lat0, double lon0, double view_km, bool tissot_circles) {
    s.curvature = view_km > 0 ? earth_view_curvature(view_km) : 1;
    s.limit_radius = kPi;
    Placing f{Frame(lat0, lon0)};
    if (view_km > 0) {
        f.scale = 1 / std::sqrt(s.curvature);
        f.cull = s.limit_radius + kCullMargin;
        f.depth = kMaxDepth + static_cast<int>(std::ceil(std::log2(f.scale)));
    }
    graticule(s, f);
    coastlines(s, f);
    if (tissot_circles) tissot(s, f);
}

}  // namespace noneuclid::world
