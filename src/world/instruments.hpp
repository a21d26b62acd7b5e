// The instruments in a world (docs/measure.md): each one a gauge of marks that keep their polar
// coordinates while K changes, as bodies do, drawn as bodies (the engine moves nothing: it draws
// them through its own seam like any outline) and read in double with geometry/measure.hpp.
//
// A world has the gauges its scene declares ([[measure]]) and one live gauge, off until the
// `instrument` action turns it on and cycles it: triangle, circle, parallels, polygon, off. While
// it is on, fire drops a mark where the ship is (three make a triangle, the next starts a new
// one; a circle's first mark is its centre, its second a point on it; the parallels' two marks
// are the common perpendicular's ends; a polygon ring's mark is its shared vertex).
//
// A gauge's bodies are made with the world (no allocation later): 3 marks, the triangle and its
// 3 angle arcs, the circle and its radius, the parallels' perpendicular, its 2 geodesics and the
// rung between their ends, and `around` polygons of `sides` vertices. Each frame whose K or marks
// changed, the parts of the gauge's instrument are placed (their centres, facings and local
// vertices from the engine's scalar's own distances and bearings, so a fixed-point world stays
// integer-exact) and the rest are switched off; the readings are read again.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "geometry/geometry.hpp"
#include "geometry/measure.hpp"
#include "world/body.hpp"
#include "world/scene.hpp"

namespace noneuclid::world {

// One gauge's readings, whichever instrument it is.
struct GaugeReading {
    geo::Instrument kind = geo::Instrument::triangle;
    geo::MeasureError error = geo::MeasureError::none;
    int marks = 0, needed = 0;  // marks placed, marks the instrument needs (live)
    bool waiting = false;       // live, with too few marks to measure yet
    double K = 0;
    geo::Polar<double> points[3] = {};
    geo::TriangleReading triangle;
    geo::CircleReading circle;
    geo::ParallelsReading parallels;
    geo::PolygonReading polygon;
    double radius = 0, distance = 0, length = 0;
    int sides = 0, around = 0;
    double side = 0;
};

// The parts of a gauge, as offsets from its first body.
enum GaugePart : int {
    kMark0 = 0, kTriangle = 3, kArc0 = 4, kCircle = 7, kRadius = 8, kPerpendicular = 9, kGeodesic0 = 10, kRung = 12,
    kPolygon0 = 13
};
inline constexpr int kArcPoints = 9, kCirclePoints = 48;

// The scene bodies of one gauge (appended to `scene`): every part, off until placed.
void add_gauge_bodies(Scene& scene, const MeasureDecl& d, bool live);
inline int gauge_body_count(const MeasureDecl& d) { return kPolygon0 + std::clamp(d.around, 3, kMeasureMaxAround); }

template <class T>
class Gauge {
public:
    Gauge(const MeasureDecl& d, int first_body, bool live) : decl_(&d), first_(first_body), live_(live), on_(!live) {
        kind_ = d.kind;
        for (const MeasureDecl::Mark& m : d.marks)
            if (count_ < 3) marks_[count_++] = {T(m.r), geo::wrap_pi(T(m.theta_deg * kDeg))};
        if (!live && kind_ == geo::Instrument::triangle && count_ < 3) {  // the default: about O, 1 from it
            for (int i = 0; i < 3; ++i) marks_[i] = {T(1), geo::wrap_pi(T((90 + 120 * i) * kDeg))};
            count_ = 3;
        }
    }
    void rebind(const MeasureDecl& d) { decl_ = &d; }
    void touch() { dirty_ = true; }  // place the parts again (after a reset of the bodies)

    bool on() const { return on_; }
    bool live() const { return live_; }
    geo::Instrument kind() const { return kind_; }
    const GaugeReading& reading() const { return reading_; }

    // The live gauge's `instrument` action: the next instrument, or off after the last.
    void cycle() {
        const int k = static_cast<int>(kind_);
        if (!on_) on_ = true, kind_ = geo::Instrument::triangle;
        else if (k + 1 < static_cast<int>(std::size(geo::kInstruments))) kind_ = static_cast<geo::Instrument>(k + 1);
        else on_ = false;
        count_ = 0, dirty_ = true;
    }
    // A mark where the ship is (live): the instrument's marks fill up, then start again.
    void drop(geo::Polar<T> at) {
        if (count_ >= needed()) count_ = 0;
        marks_[count_++] = at;
        dirty_ = true;
    }

    // Places the parts and reads the instrument when K or the marks changed since the last time.
    void update(T K, T R, std::vector<Body<T>>& bodies) {
        if (!dirty_ && K == last_K_) return;
        dirty_ = false, last_K_ = K;
        for (int i = 0; i < gauge_body_count(*decl_); ++i) bodies[first_ + i].active = false;
        if (!on_) return;
        reading_ = GaugeReading{};
        reading_.kind = kind_, reading_.K = static_cast<double>(K);
        reading_.marks = count_, reading_.needed = needed();
        for (int i = 0; i < count_ && live_; ++i) mark(bodies, i);
        switch (kind_) {
            case geo::Instrument::triangle: triangle(K, R, bodies); break;
            case geo::Instrument::circle: circle(K, R, bodies); break;
            case geo::Instrument::parallels: parallels(K, bodies); break;
            case geo::Instrument::polygon: polygon(K, bodies); break;
        }
    }

private:
    static constexpr double kDeg = 3.14159265358979323846 / 180;
    using P = geo::Polar<T>;

    int needed() const {
        switch (kind_) {
            case geo::Instrument::triangle: return 3;
            case geo::Instrument::circle: return 2;
            case geo::Instrument::parallels: return 2;
            case geo::Instrument::polygon: return 1;
        }
        return 1;
    }
    static geo::Polar<double> D(P p) { return {static_cast<double>(p.r), static_cast<double>(p.theta)}; }
    Body<T>& part(std::vector<Body<T>>& bodies, int i) const { return bodies[first_ + i]; }

    // Part i as the polyline through `points` (its vertex count), from the first point.
    void place(std::vector<Body<T>>& bodies, int i, T K, const P* points) const {
        Body<T>& b = part(bodies, i);
        b.centre = points[0], b.facing = T(0), b.active = true;
        for (std::size_t k = 0; k < b.local.size(); ++k)
            b.local[k] = k == 0 ? P{T(0), T(0)} : P{geo::distance(K, points[0], points[k]), geo::bearing(K, points[0], points[k])};
        ++b.shape;
    }
    // Part i about `centre` facing `facing` with its own local vertices (made with the scene).
    void place_about(std::vector<Body<T>>& bodies, int i, P centre, T facing) const {
        Body<T>& b = part(bodies, i);
        b.centre = centre, b.facing = facing, b.active = true;
    }
    void mark(std::vector<Body<T>>& bodies, int i) const { place_about(bodies, kMark0 + i, marks_[i], T(0)); }

    void triangle(T K, T R, std::vector<Body<T>>& bodies) {
        if (count_ < 3 && live_) return void(reading_.waiting = true);
        const P v[3] = {marks_[0], marks_[1], marks_[2]};
        for (int i = 0; i < 3; ++i) reading_.points[i] = D(v[i]);
        reading_.error = geo::measure_triangle(static_cast<double>(K), reading_.points, static_cast<double>(R), reading_.triangle);
        if (reading_.error != geo::MeasureError::none) return;
        place(bodies, kTriangle, K, v);
        // Each angle's arc: points a little way from the vertex, from one side's bearing to the other's.
        const double shortest = std::min({reading_.triangle.side[0], reading_.triangle.side[1], reading_.triangle.side[2]});
        const T radius = T(std::min(0.25, 0.3 * shortest));
        for (int i = 0; i < 3; ++i) {
            const T b1 = geo::bearing(K, v[i], v[(i + 1) % 3]), b2 = geo::bearing(K, v[i], v[(i + 2) % 3]);
            const T turn = geo::wrap_pi(b2 - b1);
            Body<T>& arc = part(bodies, kArc0 + i);
            arc.centre = v[i], arc.facing = b1, arc.active = true;
            for (int k = 0; k < kArcPoints; ++k) arc.local[k] = {radius, turn * T(k) / T(kArcPoints - 1)};
            ++arc.shape;
        }
    }
    void circle(T K, T R, std::vector<Body<T>>& bodies) {
        if (count_ < 1 && live_) return void(reading_.waiting = true);
        const P c = count_ >= 1 ? marks_[0] : P{};
        T rho = T(decl_->radius), heading = T(0);
        if (count_ >= 2) rho = geo::distance(K, c, marks_[1]), heading = geo::bearing(K, c, marks_[1]);
        reading_.points[0] = D(c), reading_.radius = static_cast<double>(rho);
        reading_.error = geo::measure_circle(static_cast<double>(K), D(c), static_cast<double>(rho), static_cast<double>(R), reading_.circle);
        if (reading_.error != geo::MeasureError::none) return;
        Body<T>& b = part(bodies, kCircle);
        b.centre = c, b.facing = T(0), b.active = true;
        for (int k = 0; k < kCirclePoints; ++k) b.local[k] = {rho, geo::wrap_pi(T(2 * 3.14159265358979323846 * k / kCirclePoints))};
        ++b.shape;
        Body<T>& r = part(bodies, kRadius);
        r.centre = c, r.facing = heading, r.active = true;
        r.local[0] = {T(0), T(0)}, r.local[1] = {rho, T(0)};
        ++r.shape;
    }
    void parallels(T K, std::vector<Body<T>>& bodies) {
        if (count_ < 2 && live_) return void(reading_.waiting = true);
        const T half = T(decl_->distance / 2), quarter = T(3.14159265358979323846 / 2);
        const P p = count_ >= 2 ? marks_[0] : P{half, quarter}, q = count_ >= 2 ? marks_[1] : P{half, -quarter};
        const T d = geo::distance(K, p, q), s = T(decl_->length);
        reading_.points[0] = D(p), reading_.points[1] = D(q);
        reading_.distance = static_cast<double>(d), reading_.length = static_cast<double>(s);
        reading_.error = geo::measure_parallels(static_cast<double>(K), static_cast<double>(d), static_cast<double>(s), reading_.parallels);
        if (reading_.error != geo::MeasureError::none) return;
        // Both leave the perpendicular on the same side: +90 degrees at p from the way to q,
        // -90 at q from the way to p.
        const T hp = geo::wrap_pi(geo::bearing(K, p, q) + quarter), hq = geo::wrap_pi(geo::bearing(K, q, p) - quarter);
        const P pq[2] = {p, q};
        place(bodies, kPerpendicular, K, pq);
        for (int i = 0; i < 2; ++i) {
            Body<T>& g = part(bodies, kGeodesic0 + i);
            g.centre = i == 0 ? p : q, g.facing = i == 0 ? hp : hq, g.active = true;
            g.local[0] = {T(0), T(0)}, g.local[1] = {s, T(0)};
            ++g.shape;
        }
        const P ends[2] = {geo::walk_end(K, p, hp, s), geo::walk_end(K, q, hq, s)};
        if (reading_.parallels.distance > 1e-6) place(bodies, kRung, K, ends);
    }
    void polygon(T K, std::vector<Body<T>>& bodies) {
        const int p = std::clamp(decl_->sides, 3, kMeasureMaxSides), q = std::clamp(decl_->around, 3, kMeasureMaxAround);
        const P v = count_ >= 1 ? marks_[0] : P{};
        reading_.points[0] = D(v), reading_.sides = p, reading_.around = q, reading_.side = decl_->side;
        const double Kd = static_cast<double>(K);
        reading_.error = geo::measure_polygon(Kd, p, q, decl_->side, reading_.polygon);
        if (reading_.error == geo::MeasureError::never_closes) reading_.error = geo::MeasureError::none;  // (drawn all the same)
        if (reading_.error != geo::MeasureError::none) return;
        // Each polygon's circumradius, and its centre on the bisector of its corner at v.
        const double pi = 3.14159265358979323846;
        const double circum = geo::AS_K(Kd, geo::S_K(Kd, decl_->side / 2) / std::sin(pi / p));
        const double alpha = reading_.polygon.angle_deg * kDeg;
        if (!std::isfinite(circum)) return;
        for (int j = 0; j < q; ++j) {
            const P c = geo::walk_end(K, v, geo::wrap_pi(T((j + 0.5) * alpha)), T(circum));
            Body<T>& b = part(bodies, kPolygon0 + j);
            b.centre = c, b.facing = geo::bearing(K, c, v), b.active = true;
            for (int k = 0; k < p; ++k) b.local[k] = {T(circum), geo::wrap_pi(T(2 * pi * k / p))};
            ++b.shape;
        }
    }

    const MeasureDecl* decl_;
    int first_ = 0;
    bool live_ = false, on_ = false, dirty_ = true;
    geo::Instrument kind_ = geo::Instrument::triangle;
    P marks_[3] = {};
    int count_ = 0;
    T last_K_{};
    GaugeReading reading_;
};

}  // namespace noneuclid::world
