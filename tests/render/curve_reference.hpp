// The within-one-pixel check of a drawn world: every body drawn alone as the program draws it
// (render::body_screen_points, then the rasteriser's aliased one-pixel lines), against its true
// projected curve computed densely in double by an independent route: the vertices from the GLM
// reference model (geometry/reference.hpp), the points along each edge by the reference's own
// geodesic (ref::along), the projections, the shown disc, the screen scale and the clip circle
// from their textbook formulas and the rules docs/rendering.md states, not from the program's
// code. Reference points are spaced at most 0.2 px apart on the screen.
//
//   worst  the largest distance of a drawn pixel's centre from the reference curve (from its
//          nearest reference point, which is never nearer than the curve);
//   gap    the largest distance of a reference point from the nearest drawn pixel's centre, for
//          reference points more than 1.5 px inside the clip circle (what the drawing leaves
//          out of the curve).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "geometry/reference.hpp"
#include "render/draw_world.hpp"
#include "test_common.hpp"

namespace noneuclid::testing {

// The length of (dx, dy): screen distances here are at most a few thousand pixels, so the plain
// square root is exact enough and much cheaper than std::hypot's care for overflow.
inline double px_distance(double dx, double dy) { return std::sqrt(dx * dx + dy * dy); }

// The bounds the checks assert. Within: the one pixel. Gap: a thin polyline leaves none
// of its points more than sqrt 1.25 = 1.12 px from a lit pixel's centre (raster.hpp, tested in
// test_joins.cpp) and its chords stay within 0.35 px of the curve (edge_curve.hpp): 1.47 px.
inline constexpr double kWithinPx = 1.0;
inline constexpr double kGapPx = 1.5;

struct CurveCheck {
    double worst = 0, gap = 0;
    long pixels = 0, samples = 0;
    std::string worst_body, gap_body;
    void add(const CurveCheck& o) {
        if (o.worst > worst) worst = o.worst, worst_body = o.worst_body;
        if (o.gap > gap) gap = o.gap, gap_body = o.gap_body;
        pixels += o.pixels, samples += o.samples;
    }
};

// The screen of a view, by the formulas of docs/rendering.md ("Projections").
class ReferenceView {
public:
    ReferenceView(double K, double R, geo::Projection p, int width, int height) : K_(K), p_(p) {
        constexpr double pi = test::kPi;
        const double s = std::sqrt(std::fabs(K));
        double shown = R;
        if (K > 0) {
            if (p == geo::Projection::gnomonic) shown = std::min(R, pi / 3 / s);
            if (p == geo::Projection::stereographic) shown = std::min(R, 2 * pi / 3 / s);
            if (p == geo::Projection::orthographic) shown = std::min(R, pi / 2 / s);
        }
        bool vis = true;
        cx_ = width / 2.0, cy_ = height / 2.0;
        rim_ = std::min(width, height) / 2.0;
        scale_ = rim_ / rho(shown * (1 - 1e-12), vis);  // (the orthographic view's edge is its horizon)
        clip_ = rim_;
        if (K > 0 && (p == geo::Projection::azimuthal_equidistant || p == geo::Projection::lambert_equal_area))
            clip_ = std::min(rim_, rho(pi / s, vis) * scale_ - 1.0);
        // The farthest distance from O a kept point can have (every projection here is azimuthal
        // and its rho grows with r where it shows r, so "kept" is r <= keep_r_), by bisection.
        double lo = 0, hi = K > 0 ? pi / s : 1.0;
        while (K <= 0 && screen({hi, 0}).kept && hi < 1e6) lo = hi, hi *= 2;
        if (screen({hi, 0}).kept) lo = hi;
        for (int i = 0; i < 100 && lo < hi; ++i) {
            const double mid = (lo + hi) / 2;
            (screen({mid, 0}).kept ? lo : hi) = mid;
        }
        keep_r_ = lo;
    }
    // rho of a point at distance r; false where the view does not show it.
    double rho(double r, bool& visible) const {
        constexpr double pi = test::kPi;
        const double s = std::sqrt(std::fabs(K_)), x = s * r;
        visible = true;
        if (K_ == 0) return r;
        const bool sph = K_ > 0;
        switch (p_) {
            case geo::Projection::azimuthal_equidistant: return r;
            case geo::Projection::stereographic:
                if (sph && x / 2 >= pi / 2 - 1e-9) return visible = false, 0;
                return 2 * (sph ? std::tan(x / 2) : std::tanh(x / 2)) / s;
            case geo::Projection::gnomonic:
                if (sph && x >= pi / 2 - 1e-9) return visible = false, 0;
                return (sph ? std::tan(x) : std::tanh(x)) / s;
            case geo::Projection::orthographic:
                if (sph && x > pi / 2) return visible = false, 0;
                return (sph ? std::sin(x) : std::sinh(x)) / s;
            case geo::Projection::lambert_equal_area: return 2 * (sph ? std::sin(x / 2) : std::sinh(x / 2)) / s;
        }
        return r;
    }
    struct At {
        double x = 0, y = 0;
        bool visible = false, inside = false, kept = false;
        double from_centre = 0;
        double r = 0;  // the point's distance from O in the world
    };
    At screen(geo::Polar<double> q) const {
        At a;
        a.r = q.r;
        const double r = rho(q.r, a.visible);
        if (!a.visible || !std::isfinite(r)) return a.visible = false, a;
        a.x = cx_ + scale_ * r * std::cos(q.theta), a.y = cy_ - scale_ * r * std::sin(q.theta);
        a.from_centre = px_distance(a.x - cx_, a.y - cy_);
        a.inside = a.from_centre <= clip_;
        a.kept = a.from_centre <= rim_ + 2;
        return a;
    }
    double clip() const { return clip_; }
    double keep_r() const { return keep_r_; }
    double rim() const { return rim_; }

private:
    double K_;
    geo::Projection p_;
    double cx_ = 0, cy_ = 0, rim_ = 0, scale_ = 1, clip_ = 0, keep_r_ = 0;
};

namespace detail {
struct Sample {
    double x, y, from_centre;
};
// The reference points of the edge p -> q, at most 0.2 px apart where the curve is within 2 px
// of the limit circle or inside it (pieces wholly farther out halved ten times at most, to find
// where they dip in, unless their distance from O says they cannot). A drawn line that leaves the clip circle at a grazing angle ends within
// the chord tolerance of the curve, but the curve itself may be outside the clip circle there.
inline void edge_samples(double K, const ReferenceView& v, geo::Polar<double> p, geo::Polar<double> q,
                         std::vector<Sample>& out) {
    constexpr double pi = test::kPi;
    const glm::dvec3 rel = geo::ref::frame_inverse(K, p) * geo::ref::point(K, q);
    const double d = geo::ref::polar(K, rel).r;
    // Antipodal ends: the geodesic through p's radial line (q's when p is O), the convention.
    const bool antipodal = K > 0 && std::fabs(d * std::sqrt(K) - pi) < 1e-9;
    const double dir = antipodal ? (p.r > 0 ? p.theta : q.theta) : std::atan2(rel.z, rel.y);
    const glm::dmat3 start = geo::ref::frame(K, p) * geo::ref::Rot(dir);
    auto at = [&](double t) {
        return v.screen(geo::ref::polar(K, start * geo::ref::Tr(K, t * d) * glm::dvec3(1, 0, 0)));
    };
    struct Piece {
        double t0, t1;
        ReferenceView::At a, b;
        int depth;
    };
    std::vector<Piece> todo;
    constexpr int kFirst = 16;
    ReferenceView::At prev = at(0);
    for (int i = 1; i <= kFirst; ++i) {
        const ReferenceView::At next = at(double(i) / kFirst);
        todo.push_back({double(i - 1) / kFirst, double(i) / kFirst, prev, next, 0});
        prev = next;
    }
    if (prev.kept) out.push_back({prev.x, prev.y, prev.from_centre});
    std::reverse(todo.begin(), todo.end());
    while (!todo.empty()) {
        const Piece c = todo.back();
        todo.pop_back();
        if (c.a.kept) out.push_back({c.a.x, c.a.y, c.a.from_centre});
        const bool any = c.a.kept || c.b.kept;
        const bool far = !c.a.visible || !c.b.visible || px_distance(c.a.x - c.b.x, c.a.y - c.b.y) > 0.2;
        // A point of the piece is within half its length of an end, so no point of it is nearer
        // O than this: farther than keep_r(), it has no kept point and is not halved.
        const bool none_kept = std::min(c.a.r, c.b.r) - (c.t1 - c.t0) * d / 2 > v.keep_r() * (1 + 1e-12) + 1e-12;
        if ((any && far && c.depth < 40) || (!any && !none_kept && c.depth < 10)) {
            const double tm = (c.t0 + c.t1) / 2;
            const ReferenceView::At m = at(tm);
            todo.push_back({tm, c.t1, m, c.b, c.depth + 1});
            todo.push_back({c.t0, tm, c.a, m, c.depth + 1});
        }
    }
}
inline void collect(int x, int y, int, void* ctx) {
    static_cast<std::vector<std::pair<int, int>>*>(ctx)->push_back({x, y});
}
}  // namespace detail

// Checks body i of `world` as drawn on a width x height canvas in projection p.
template <class W>
CurveCheck check_body(const W& world, std::size_t i, geo::Projection p, int width, int height,
                      render::DrawScratch<typename W::scalar>& scratch) {
    using T = typename W::scalar;
    const auto& b = world.bodies[i];
    const double K = static_cast<double>(world.K);
    const ReferenceView view(K, static_cast<double>(world.R), p, width, height);
    CurveCheck out;
    // The program's pixels.
    render::DrawOptions o;
    o.projection = p;
    const auto m = render::ScreenMap<T>::of(width, height, world.K, world.R, p);
    const std::size_t n = render::body_screen_points(world, b, scratch.shapes[i], m, o, scratch.vertices.data(),
                                                     scratch.vectors.data(), scratch.points.data());
    std::vector<std::pair<int, int>> lit;
    const render::SubPoint* pts = scratch.points.data();
    for (std::size_t k = 0; k < n;) {
        std::size_t j = k;
        while (j < n && !(pts[j].x == render::kBreak.x && pts[j].y == render::kBreak.y)) ++j;
        if (j > k) render::visit_polyline(width, height, pts + k, static_cast<int>(j - k), false, {}, detail::collect, &lit);
        k = j + 1;
    }
    // The reference points.
    std::vector<detail::Sample> ref;
    std::vector<geo::Polar<double>> v;
    const geo::Polar<double> centre{static_cast<double>(b.centre.r), static_cast<double>(b.centre.theta)};
    for (const auto& l : b.local)
        v.push_back(geo::ref::vertex(K, centre, static_cast<double>(b.facing),
                                     {static_cast<double>(l.r), static_cast<double>(l.theta)}));
    const std::size_t nv = v.size(), edges = nv < 2 ? 0 : (b.desc->closed ? nv : nv - 1);
    if (edges == 0 && nv == 1) {
        const ReferenceView::At a = view.screen(v[0]);
        if (a.kept) ref.push_back({a.x, a.y, a.from_centre});
    }
    for (std::size_t e = 0; e < edges; ++e) detail::edge_samples(K, view, v[e], v[(e + 1) % nv], ref);
    out.pixels = static_cast<long>(lit.size()), out.samples = static_cast<long>(ref.size());
    // The reference points by pixel, as index ranges into `order`: a grid over the box of the
    // reference points grown by 4 px (a lit pixel outside it has no reference point within 3 px,
    // the cells the search visits). The buffers are kept from call to call, so that a check is
    // not mostly the kernel clearing fresh pages.
    constexpr long kPad = 4;
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    for (std::size_t k = 0; k < ref.size(); ++k) {
        const detail::Sample& r = ref[k];
        if (k == 0) x0 = x1 = r.x, y0 = y1 = r.y;
        x0 = std::min(x0, r.x), x1 = std::max(x1, r.x), y0 = std::min(y0, r.y), y1 = std::max(y1, r.y);
    }
    const long gx = std::max(-kPad, static_cast<long>(std::floor(x0)) - kPad);
    const long gy = std::max(-kPad, static_cast<long>(std::floor(y0)) - kPad);
    const long gw = std::max(0L, std::min<long>(width + kPad, static_cast<long>(std::floor(x1)) + kPad + 1) - gx);
    const long gh = std::max(0L, std::min<long>(height + kPad, static_cast<long>(std::floor(y1)) + kPad + 1) - gy);
    auto cell = [&](double x, double y) -> long {
        const long cx = static_cast<long>(std::floor(x)) - gx, cy = static_cast<long>(std::floor(y)) - gy;
        return cx < 0 || cy < 0 || cx >= gw || cy >= gh ? -1 : cy * gw + cx;
    };
    thread_local std::vector<uint32_t> first, order, fill;
    thread_local std::vector<uint8_t> on;
    first.assign(static_cast<std::size_t>(gw * gh + 1), 0), order.assign(ref.size(), 0);
    for (const detail::Sample& r : ref)
        if (const long c = cell(r.x, r.y); c >= 0) ++first[static_cast<std::size_t>(c) + 1];
    for (std::size_t c = 1; c < first.size(); ++c) first[c] += first[c - 1];
    fill.assign(first.begin(), first.end() - 1);
    for (std::size_t k = 0; k < ref.size(); ++k)
        if (const long c = cell(ref[k].x, ref[k].y); c >= 0) order[fill[static_cast<std::size_t>(c)]++] = static_cast<uint32_t>(k);
    // The drawn pixels on the same grid (the gap's search looks only within 3 px of a point).
    on.assign(static_cast<std::size_t>(gw * gh), 0);
    for (const auto& [x, y] : lit)
        if (const long c = cell(x, y); c >= 0) on[static_cast<std::size_t>(c)] = 1;
    for (const auto& [x, y] : lit) {
        double best = 1e9;
        for (long dy = -3; dy <= 3; ++dy)
            for (long dx = -3; dx <= 3; ++dx) {
                const long c = cell(x + dx, y + dy);
                if (c < 0) continue;
                for (uint32_t k = first[static_cast<std::size_t>(c)]; k < first[static_cast<std::size_t>(c) + 1]; ++k) {
                    const detail::Sample& r = ref[order[k]];
                    best = std::min(best, px_distance(r.x - (x + 0.5), r.y - (y + 0.5)));
                }
            }
        if (best > out.worst)
            out.worst = best, out.worst_body = b.desc->name + (" at (" + std::to_string(x) + ", " + std::to_string(y) + ")");
    }
    for (const detail::Sample& s : ref) {
        if (s.from_centre > view.clip() - 1.5) continue;
        double best = 1e9;
        const long px = static_cast<long>(std::floor(s.x)), py = static_cast<long>(std::floor(s.y));
        for (long dy = -3; dy <= 3; ++dy)
            for (long dx = -3; dx <= 3; ++dx) {
                const long x = px + dx, y = py + dy;
                if (x < 0 || y < 0 || x >= width || y >= height) continue;
                if (const long c = cell(x, y); c >= 0 && on[static_cast<std::size_t>(c)])
                    best = std::min(best, px_distance(s.x - (x + 0.5), s.y - (y + 0.5)));
            }
        if (best > out.gap)
            out.gap = best,
            out.gap_body = b.desc->name + (" at (" + std::to_string(s.x) + ", " + std::to_string(s.y) + ")");
    }
    return out;
}

// Every body of the world.
template <class W>
CurveCheck check_world(const W& world, geo::Projection p, int width, int height) {
    render::DrawScratch<typename W::scalar> scratch;
    scratch.prepare(world);
    CurveCheck all;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) all.add(check_body(world, i, p, width, height, scratch));
    return all;
}

}  // namespace noneuclid::testing
