// The uneven world (see world.hpp).
#include "uneven/world.hpp"

#include <cmath>

#include "world/ranges.hpp"

namespace noneuclid::uneven {
namespace {

constexpr double kPi = 3.14159265358979323846, kDegree = kPi / 180;

double wrap(double a) { return geo::wrap_pi(a); }
double clamp(double v, double lo, double hi) { return v < lo ? lo : (v > hi ? hi : v); }

}  // namespace

World::World(const world::Scene& scene) : scene_(scene) {
    K = scene_.curvature;
    R = scene_.limit_radius;
    gain_most_ = world::bump_gain_most(scene_);
    build_metric();
    for (const world::SceneBody& sb : scene_.bodies) {
        Body b;
        b.centre = {sb.r, wrap(sb.theta_deg * kDegree)};
        b.facing = wrap(sb.facing_deg * kDegree);
        b.speed = sb.speed;
        b.travel = wrap(sb.direction_deg * kDegree);
        b.accel = sb.accel;
        b.accel_dir = wrap(sb.accel_direction_deg * kDegree);
        b.spin = sb.spin_deg * kDegree;
        for (const world::SceneBody::Vertex& v : sb.vertices) b.local.push_back({v.rho, v.phi_deg * kDegree});
        bodies.push_back(b);
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) bodies[i].desc = &scene_.bodies[i];
    fold();
    game_.setup(*this);
    for (const world::MeasureDecl& d : scene_.measures) {  // (triangles: the scene file refuses others)
        Gauge g;
        g.shown = true;
        const world::MeasureDecl::Mark fallback[3] = {{1.2, 90}, {1.2, 210}, {1.2, 330}};
        for (int i = 0; i < 3; ++i) {
            const world::MeasureDecl::Mark m = d.marks.size() == 3 ? d.marks[i] : fallback[i];
            g.triangle.mark[i] = chart({m.r, wrap(m.theta_deg * kDegree)});
        }
        g.marks = 3;
        gauges_.push_back(g);
    }
    Gauge live;
    live.live = true;
    gauges_.push_back(live);
    read_gauges();
    initial_ = bodies;
    initial_K_ = K;
    initial_game_ = game_;
}

void World::place_mark(geo::Polar<double> at) {
    Gauge& g = gauges_.back();
    if (!g.shown) g.shown = true, g.marks = 0;
    drop(g, chart(at));
    read_gauges();
}

// A mark of the live triangle at chart point x: its first, second or third (then a new one).
void World::drop(Gauge& g, Vec2 x) {
    if (g.marks == 3) g.marks = 0;
    g.triangle.mark[g.marks++] = x;
    g.version = 0;
}

// Each shown triangle with its marks, measured again if the metric or its marks changed.
void World::read_gauges() {
    constexpr double kDeg = 180 / kPi;
    for (Gauge& g : gauges_) {
        if (!g.shown || g.version == version_ + 1) continue;
        g.version = version_ + 1;
        world::GaugeReading& r = g.read;
        r = world::GaugeReading{};
        r.kind = geo::Instrument::triangle;
        r.K = K, r.marks = g.marks, r.needed = 3;
        for (int i = 0; i < g.marks; ++i) r.points[i] = polar(g.triangle.mark[i]);
        if (g.marks < 3) {
            r.waiting = true;
            g.triangle.valid = false;
            continue;
        }
        measure(metric_, g.triangle);
        const Triangle& t = g.triangle;
        if (!t.valid) {
            r.error = geo::MeasureError::collinear;
            continue;
        }
        geo::TriangleReading& tr = r.triangle;
        for (int i = 0; i < 3; ++i) tr.side[i] = t.side[i], tr.angle_deg[i] = t.angle[i] * kDeg;
        tr.sum_deg = tr.angle_deg[0] + tr.angle_deg[1] + tr.angle_deg[2];
        tr.excess_deg = t.excess * kDeg;
        tr.area = t.area;
        tr.k_area_deg = t.curvature * kDeg;
    }
}

World& World::operator=(const World& o) {
    if (this == &o) return *this;
    scene_ = o.scene_;
    K = o.K, R = o.R, time = o.time, frame = o.frame;
    bodies = o.bodies, initial_ = o.initial_, initial_K_ = o.initial_K_;
    metric_ = o.metric_, gain_ = o.gain_, gain_most_ = o.gain_most_, version_ = o.version_, sweep_dir_ = o.sweep_dir_;
    game_ = o.game_, initial_game_ = o.initial_game_, gauges_ = o.gauges_;
    game_.rebind(scene_.game), initial_game_.rebind(scene_.game);
    for (int i = 0; i < world::kActionCount; ++i) held_[i] = o.held_[i];
    for (std::size_t i = 0; i < bodies.size(); ++i) bodies[i].desc = initial_[i].desc = &scene_.bodies[i];
    return *this;
}

double World::limit() const {
    return geo::shown_radius(K, R, geo::Projection::stereographic);
}

geo::Polar<double> World::polar(Vec2 x) const {
    const double rho = std::hypot(x.x, x.y);
    return {world_radius(K, rho), rho > 0 ? std::atan2(x.y, x.x) : 0.0};
}
Vec2 World::chart(geo::Polar<double> p) const {
    const double rho = chart_radius(K, p.r);
    return {rho * std::cos(p.theta), rho * std::sin(p.theta)};
}

Vec2 World::vertex(const Body& b, std::size_t i) const {
    return exp_map(metric_, chart(b.centre), b.facing + b.local[i].theta, b.local[i].r).x;
}

void World::shape_vectors(const Body& b, geo::Vec3<double>& c, geo::Vec3<double>* out, std::size_t n) const {
    c = geo::to_vec(K, b.centre);
    for (std::size_t i = 0; i < n; ++i) out[i] = geo::to_vec(K, polar(vertex(b, i)));
}
double World::model_length(const Body& b, double length) const {
    const Vec2 x = chart(b.centre);
    const double beta = metric_.at(x).psi + std::log(1 + K * dot(x, x) / 4);  // psi less the constant-K part
    return length * std::exp(-beta);
}

// The metric at K and the gain: each bump where a body at its (r, theta) would be.
void World::build_metric() {
    metric_ = Metric{};
    metric_.K = K;
    for (const world::SceneBump& sb : scene_.bumps) {
        if (metric_.bump_count == kMaxBumps) break;  // (the scene file refuses more)
        Bump& b = metric_.bumps[metric_.bump_count++];
        b.kind = sb.mass ? BumpKind::mass : BumpKind::hill;
        b.centre = chart({sb.r, wrap(sb.theta_deg * kDegree)});
        b.width = sb.width;
        b.strength = sb.strength * gain_;
    }
    ++version_;
}

// Every body inside the limit circle in force (after K changed it).
void World::fold() {
    for (Body& b : bodies) {
        settle(b);
        b.wrapped = false;
    }
}

// K changed: every body keeps its (r, theta), folded into the limit circle (which may have
// shrunk), the bumps theirs.
void World::set_curvature(double k) {
    k = clamp(k, -1, 1);
    if (k == K) return;
    K = k;
    fold();
    build_metric();
}

void World::set_gain(double g) {
    g = clamp(g, 0, gain_most_);
    if (g == gain_) return;
    gain_ = g;
    build_metric();
}

void World::press(world::Action a) {
    using world::Action;
    held_[static_cast<int>(a)] = true;
    switch (a) {
        case Action::preset: {
            const std::vector<double>& p = scene_.presets;
            if (p.empty()) break;
            double next = p.front();
            for (double v : p)
                if (v > K + 1e-9) {
                    next = v;
                    break;
                }
            set_curvature(next);
            break;
        }
        case Action::reset: reset(); break;
        case Action::hyperbolic: set_curvature(-1); break;
        case Action::flat: set_curvature(0); break;
        case Action::spherical: set_curvature(1); break;
        case Action::fire:
            if (measuring()) {
                drop(gauges_.back(), chart(ship_centre()));
                read_gauges();
            } else {
                game_.press_fire();
            }
            break;
        case Action::instrument: {  // the live triangle on (from no marks) or off
            Gauge& g = gauges_.back();
            g.shown = !g.shown, g.marks = 0, g.version = 0;
            read_gauges();
            break;
        }
        default: break;
    }
}

void World::reset() {
    bodies = initial_;
    K = initial_K_;
    game_ = initial_game_;
    gain_ = 1;
    sweep_dir_ = 1;
    build_metric();
    read_gauges();
}

geo::Polar<double> World::ship_centre() const {
    for (const Body& b : bodies)
        if (b.active && b.desc->controlled) return b.centre;
    return {};
}

void World::step(double dt) {
    using world::Action;
    const int dk = held(Action::curvature_up) - held(Action::curvature_down);
    if (dk != 0) set_curvature(K + scene_.curvature_rate * dk * dt);
    if (scene_.sweep_rate != 0) {
        double k = K + scene_.sweep_rate * sweep_dir_ * dt;
        if (k >= 1) k = 1, sweep_dir_ = -1;
        if (k <= -1) k = -1, sweep_dir_ = 1;
        set_curvature(k);
    }
    const int ds = held(Action::strength_up) - held(Action::strength_down);
    if (ds != 0) set_gain(gain_ + scene_.strength_rate * ds * dt);
    const double turn = scene_.turn_rate_deg * kDegree * (held(Action::left) - held(Action::right));
    for (Body& b : bodies)
        if (b.active) step_body(b, dt, turn);
    time += dt;
    ++frame;
    const double k = K;
    game_.step(*this, dt, held(Action::fire) && !measuring());
    if (K != k) {  // a game's new level sets K
        const double set = K;
        K = k;
        set_curvature(set);
    }
    read_gauges();
}

// Steps 1-4 of world.hpp for one body.
void World::step_body(Body& b, double dt, double turn) const {
    double a = b.accel, adir = b.accel_dir;
    const bool ship = b.desc->controlled;
    if (ship && held(world::Action::thrust)) a = scene_.thrust, adir = b.facing;
    if (a != 0) {  // velocity += a dt in the tangent plane (the chart's angles are the world's)
        const double vx = b.speed * std::cos(b.travel) + a * dt * std::cos(adir);
        const double vy = b.speed * std::sin(b.travel) + a * dt * std::sin(adir);
        b.speed = std::hypot(vx, vy);
        if (b.speed != 0) b.travel = std::atan2(vy, vx);
        if (b.speed > world::Ranges::kSpeed) b.speed = world::Ranges::kSpeed;
        if (ship && b.speed > game_.top_speed(world::Ranges::kSpeed)) b.speed = game_.top_speed(world::Ranges::kSpeed);
    }
    if (b.speed != 0) {
        const Geodesic g = uneven::step(metric_, Geodesic{chart(b.centre), b.travel}, b.speed, dt);
        const double turned = g.phi - b.travel;  // parallel transport keeps angles to the heading
        b.centre = polar(g.x);
        b.travel = wrap(g.phi);
        b.facing = wrap(b.facing + turned);
        b.accel_dir = wrap(b.accel_dir + turned);
    }
    const double spin = ship ? b.spin + turn : b.spin;
    if (spin != 0) b.facing = wrap(b.facing + spin * dt);
    settle(b);
}

// The limit circle: a centre past it comes back at (2L - r, theta + pi), its headings unchanged
// (K may have grown so far that it takes more than one fold).
void World::settle(Body& b) const {
    const double L = limit();
    geo::Polar<double>& p = b.centre;
    b.wrapped = p.r > L;
    for (int i = 0; i < 8 && p.r > L; ++i) {
        p.r = 2 * L - p.r;
        p.theta = wrap(p.theta + kPi);
        if (p.r < 0) p.r = -p.r, p.theta = wrap(p.theta + kPi);
    }
    if (p.r > L) p.r = L;
}

}  // namespace noneuclid::uneven
