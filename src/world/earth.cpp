// The earth scene (world/earth.hpp): lat/lon to polar coordinates about the centre, and the
// coastlines and graticule as polylines whose every point keeps its distance and bearing.
#include "world/earth.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "geometry/projection.hpp"
#include "world/earth_data.hpp"
#include "world/sphere_lines.hpp"

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
// halved (at its great circle's midpoint) while, at K = -1, where the same two polar points are
// farthest apart and the geodesic bends most from the mapped great circle, the geodesic's
// midpoint lies more than kBendPx pixels of the kiosk's disc from the great circle's in any of
// the five projections (docs/earth.md), or the edge is longer than kMaxStep there (kCullStep
// where it leaves the view, zoomed: no vertex lies more than kCullMargin + kCullStep outside
// it). Within a few degrees of the antipode, where a short arc spans a wide range of bearings,
// halving down to kMinArc (radians of the Earth, divided by the zoom's scale) is not enough
// and the line breaks: that is the limit circle at K = +1.
constexpr double kBendPx = 1, kMaxStep = 0.5, kCullStep = 0.1, kMinArc = 3 * kDeg / 256;
// The coastlines are simplified when the scene is built (Douglas-Peucker on the sphere): every
// point left out lies within kSimplifyPx of the kept line, in pixels of the kiosk's disc
// (kDiscPx: 800x480, the disc pi world units across its radius).
constexpr double kSimplifyPx = 0.5, kDiscPx = 240;
// A body's vertices at most (Budget::kVerticesPerBody is far above it): a longer line goes on
// in a new body from the same point.
constexpr std::size_t kPieceVertices = 1000;
// Zoomed in (--view), the lines are kept to the view: a line ends at its first vertex past
// kCullMargin outside the limit circle, and an edge whose every point lies farther (both ends
// farther than half its length) is not halved at all.
constexpr double kCullMargin = 0.25;
// Past this rho the bend bound's K = -1 numbers overflow (cosh 710 is double's largest).
constexpr double kFarRho = 100;
// A polar point on the hyperboloid of K = -1 (x0 = cosh r), and the Minkowski product.
struct H3 {
    double t, x, y;
};
H3 hyperboloid(SceneBody::Vertex v) {
    const double s = std::sinh(v.rho), a = v.phi_deg * kDeg;
    return {std::cosh(v.rho), s * std::cos(a), s * std::sin(a)};
}
double minkowski(H3 a, H3 b) { return a.t * b.t - a.x * b.x - a.y * b.y; }

// At K = -1: the length of the geodesic from a to b.
double hyperbolic_length(SceneBody::Vertex a, SceneBody::Vertex b) {
    return std::acosh(std::fmax(minkowski(hyperboloid(a), hyperboloid(b)), 1.0));
}

// At K = -1, the pixels of the kiosk's disc between the geodesic midpoint of a and b and the
// point m, in the view that draws them farthest apart: the five projections' screen radius
// there (geometry/projection.hpp at K = -1), scaled to put the limit circle at kDiscPx.
double midpoint_bend_px(SceneBody::Vertex a, SceneBody::Vertex b, SceneBody::Vertex m) {
    const H3 p = hyperboloid(a), q = hyperboloid(b), s{p.t + q.t, p.x + q.x, p.y + q.y};
    const double n = std::sqrt(minkowski(s, s));
    const double gr = std::acosh(std::fmax(s.t / n, 1.0)), ga = std::atan2(s.y, s.x), ma = m.phi_deg * kDeg;
    double worst = 0;
    for (geo::Projection p : geo::kProjections) {
        auto f = [p](double r) {
            return geo::with_projection(p, [r](auto P) { return decltype(P)::project(-1.0, r).rho; });
        };
        const double k = kDiscPx / f(kPi), g = f(gr) * k, h = f(m.rho) * k;
        worst = std::fmax(worst, std::hypot(g * std::cos(ga) - h * std::cos(ma), g * std::sin(ga) - h * std::sin(ma)));
    }
    return worst;
}

// The places' polar coordinates in the world: the centre's frame, and the world units a radian
// of the Earth is (1 / sqrt K when zoomed, earth_view_curvature; else 1).
struct Placing {
    Frame frame;
    double scale = 1, cull = 1e300;
    bool bend = true;  // halve edges by the bend bound (else only by length: great circles at K = z)
    // Every point kept, each line with its Douglas-Peucker tree, simplified when drawn for the
    // view (geometry/detail.hpp); else simplified here, for the kiosk's disc.
    bool per_view = false;
    double tolerance = kSimplifyPx * kPi / kDiscPx;  // the coastlines' simplification, radians of the Earth
    double min_arc = kMinArc;
    SceneBody::Vertex polar(V3 v) const {
        SceneBody::Vertex p = frame.polar(v);
        p.rho *= scale;
        return p;
    }
};



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
        edge(last_, p);
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
    void edge(V3 a, V3 b) {
        const SceneBody::Vertex pa = frame_.polar(a), pb = frame_.polar(b);
        if (std::fmin(pa.rho, pb.rho) - arc(a, b) * frame_.scale / 2 > frame_.cull) {
            flush();
            broken_ = true;
            outside_ = true, outside_at_ = pb;
            return;
        }
        V3 m{a.x + b.x, a.y + b.y, a.z + b.z};
        const double n = std::sqrt(dot(m, m));
        if (n < 1e-12) return add(pb);  // (antipodal ends: not in the data)
        m = {m.x / n, m.y / n, m.z / n};
        if (!frame_.bend) {  // the great circle is the geodesic: halved only to keep edges short
            if (arc(a, b) * frame_.scale <= kMaxStep) return add(pb);
            edge(a, m);
            return edge(m, b);
        }
        // (Far past the view the hyperboloid's cosh r overflows: such an edge is halved until
        // the cull above takes its pieces.)
        if (std::fmax(pa.rho, pb.rho) < kFarRho &&
            hyperbolic_length(pa, pb) <= (std::fmax(pa.rho, pb.rho) > frame_.cull ? kCullStep : kMaxStep) &&
            midpoint_bend_px(pa, pb, frame_.polar(m)) <= kBendPx) return add(pb);
        if (arc(a, b) < frame_.min_arc) {
            flush();
            broken_ = true;
            return add(pb);
        }
        edge(a, m);
        edge(m, b);
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
            if (frame_.per_view) b.detail = std::make_shared<const geo::DetailTree>(line_tree(b.vertices, closed, frame_.scale, kMaxStep));
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


// Douglas-Peucker on the sphere: keep[i] for the points of pts[first..last] a line within
// tolerance (radians) of every point needs; the ends are kept.
void simplify(const std::vector<V3>& pts, std::size_t first, std::size_t last, double tolerance, std::vector<char>& keep) {
    keep[first] = keep[last] = 1;
    if (last <= first + 1) return;
    std::size_t far = first;
    double worst = -1;
    for (std::size_t i = first + 1; i < last; ++i) {
        const double d = arc_distance(pts[i], pts[first], pts[last]);
        if (d > worst) worst = d, far = i;
    }
    if (worst <= tolerance) return;
    simplify(pts, first, far, tolerance, keep);
    simplify(pts, far, last, tolerance, keep);
}

// A line through pts (closed: a ring, back to its first point) simplified to f.tolerance: a
// ring from its start and the point farthest from it, so that it keeps an area.
void simplified(Lines& lines, std::vector<V3>& pts, bool closed, const Placing& f, std::vector<char>& keep) {
    if (closed) pts.push_back(pts.front());
    keep.assign(pts.size(), 0);
    if (f.per_view) {
        keep.assign(pts.size(), 1);
    } else if (closed) {
        std::size_t far = 0;
        for (std::size_t i = 1; i < pts.size(); ++i)
            if (arc(pts[i], pts[0]) > arc(pts[far], pts[0])) far = i;
        simplify(pts, 0, far, f.tolerance, keep);
        simplify(pts, far, pts.size() - 1, f.tolerance, keep);
    } else {
        simplify(pts, 0, pts.size() - 1, f.tolerance, keep);
    }
    lines.start(pts[0]);
    for (std::size_t i = 1; i < pts.size(); ++i)
        if (keep[i]) lines.to(pts[i]);
    lines.end(closed);
}

// Meridians every 15 degrees from pole to pole, parallels every 15 degrees from 75 S to 75 N,
// from a point every degree, simplified as the coastlines are (a meridian, a great circle, to
// its poles and equator; the halving adds the points K = -1 needs).
void graticule(Scene& s, const Placing& f) {
    std::vector<V3> pts;
    std::vector<char> keep;
    Lines meridians(s, f, "meridian", kGraticule);
    for (int lon = -180; lon < 180; lon += 15) {
        pts.clear();
        for (int lat = -90; lat <= 90; ++lat) pts.push_back(unit(lat, lon));
        simplified(meridians, pts, false, f, keep);
    }
    Lines parallels(s, f, "parallel", kGraticule);
    for (int lat = -75; lat <= 75; lat += 15) {
        pts.clear();
        for (int lon = -180; lon < 180; ++lon) pts.push_back(unit(lat, lon));
        simplified(parallels, pts, true, f, keep);
    }
}

// Natural Earth's lines, simplified to f.tolerance.
void coastlines(Scene& s, const Placing& f) {
    Lines coast(s, f, "coast", kCoast);
    std::vector<V3> pts;
    std::vector<char> keep;
    for (const earth_data::Line& l : earth_data::kLines) {
        pts.clear();
        for (int32_t i = 0; i < l.count; ++i)
            pts.push_back(unit(earth_data::kPoints[l.first + i][0] * 1e-4, earth_data::kPoints[l.first + i][1] * 1e-4));
        simplified(coast, pts, l.closed, f, keep);
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

void earth_scene(Scene& s, double lat0, double lon0, double view_km, bool tissot_circles, bool bend) {
    s.curvature = view_km > 0 ? earth_view_curvature(view_km) : 1;
    s.limit_radius = kPi;
    Placing f{Frame(lat0, lon0)};
    f.bend = bend;
    f.per_view = !bend;
    if (view_km > 0) {
        f.scale = 1 / std::sqrt(s.curvature);
        f.cull = s.limit_radius + kCullMargin;
        f.min_arc /= f.scale;
        f.tolerance /= f.scale;
    }
    graticule(s, f);
    coastlines(s, f);
    if (tissot_circles) tissot(s, f);
}

void earth_zoom_scene(Scene& s, double lat0, double lon0, double view_km, bool tissot_circles) {
    std::vector<double> views = {0};  // the whole globe, then each half the last
    for (double w = kEarthZoomFirstKm; w >= kEarthViewMinKm; w /= 2) views.push_back(w);
    if (view_km > 0 && view_km < kEarthViewMaxKm) {  // the start, a level of its own (as --view drew it)
        bool known = false;
        for (double w : views) known = known || w == view_km;
        if (!known) views.push_back(view_km);
    }
    for (double w : views)
        for (bool bent : {false, true}) {
            Scene t;
            earth_scene(t, lat0, lon0, w, tissot_circles, bent);
            s.zoom.levels.push_back({t.curvature, bent, static_cast<int>(s.bodies.size()), static_cast<int>(t.bodies.size())});
            for (SceneBody& b : t.bodies) s.bodies.push_back(std::move(b));
        }
    s.curvature = s.zoom.start = view_km > 0 ? earth_view_curvature(view_km) : 1;
    s.limit_radius = kPi;
    s.zoom.least = earth_view_curvature(kEarthViewMinKm);
    s.zoom.most = 1;
}

}  // namespace noneuclid::world
