// The sphere's lines (world/sphere_lines.hpp).
#include "world/sphere_lines.hpp"

#include <cmath>
#include <cstdint>

namespace noneuclid::world {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180;

// A body's vertices (world units about O on the sphere of the level: angle rho / scale) as unit
// vectors of that sphere, in the centre's frame.
V3 on_sphere(SceneBody::Vertex v, double scale) {
    const double a = v.rho / scale, t = v.phi_deg * kDeg;
    return {std::cos(a), std::sin(a) * std::cos(t), std::sin(a) * std::sin(t)};
}

// The Douglas-Peucker tree of a line's vertices (geometry/detail.hpp), deviations and rho in
// world units. A bracket longer than max_step must be split (its deviation is the largest),
// so that no edge the view keeps is longer than the edges drawn whole.
class TreeMaker {
public:
    TreeMaker(const std::vector<SceneBody::Vertex>& v, double scale, double max_step) : v_(v), scale_(scale), max_step_(max_step) {
        for (const SceneBody::Vertex& x : v) p_.push_back(on_sphere(x, scale));
    }
    geo::DetailTree make(bool closed) {
        const int32_t n = static_cast<int32_t>(v_.size());
        geo::DetailTree t;
        for (int32_t i = 0; i < n; ++i)
            if (v_[i].rho > v_[t.ref].rho) t.ref = i;
        t.ref_rho = v_[t.ref].rho;
        if (closed && n > 2) {
            int32_t far = 1;
            for (int32_t i = 2; i < n; ++i)
                if (arc(p_[i], p_[0]) > arc(p_[far], p_[0])) far = i;
            t.far = far, t.root_count = 2;
            t.roots[0] = node(0, far), t.roots[1] = node(far, n);
        } else {
            t.root_count = 1;
            t.roots[0] = node(0, n - 1);
        }
        t.nodes = std::move(nodes_);
        return t;
    }

private:
    int32_t node(int32_t lo, int32_t hi) {
        if (hi <= lo + 1) return -1;
        const std::size_t n = p_.size();
        const V3 a = p_[lo], b = p_[hi % n];
        geo::DetailNode d;
        double worst = -1, rmin = v_[lo].rho, rmax = rmin;
        for (int32_t i = lo + 1; i < hi; ++i) {
            const double e = arc_distance(p_[i], a, b);
            if (e > worst) worst = e, d.split = i;
            rmin = std::fmin(rmin, v_[i].rho), rmax = std::fmax(rmax, v_[i].rho);
        }
        rmin = std::fmin(rmin, v_[hi % n].rho), rmax = std::fmax(rmax, v_[hi % n].rho);
        const bool long_edge = arc(a, b) * scale_ > max_step_;
        if (long_edge) {  // split where it halves the bracket best (not at a great circle's rounding noise)
            double even = 1e300;
            for (int32_t i = lo + 1; i < hi; ++i) {
                const double e = std::fabs(arc(a, p_[i]) - arc(p_[i], b));
                if (e < even) even = e, d.split = i;
            }
        }
        d.deviation = long_edge ? 3e38f : static_cast<float>(worst * scale_ * (1 + 1e-6) + 1e-9);
        d.rho_min = static_cast<float>(rmin * (1 - 1e-6)), d.rho_max = static_cast<float>(rmax * (1 + 1e-6));
        const int32_t at = static_cast<int32_t>(nodes_.size());
        nodes_.push_back(d);
        const int32_t left = node(lo, d.split), right = node(d.split, hi);
        nodes_[at].left = left, nodes_[at].right = right;
        return at;
    }
    const std::vector<SceneBody::Vertex>& v_;
    double scale_, max_step_;
    std::vector<V3> p_;
    std::vector<geo::DetailNode> nodes_;
};

}  // namespace

V3 unit(double lat, double lon) {
    const double p = lat * kDeg, l = lon * kDeg;
    return {std::cos(p) * std::cos(l), std::cos(p) * std::sin(l), std::sin(p)};
}

double arc(V3 a, V3 b) {
    const V3 c{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    return std::atan2(std::sqrt(dot(c, c)), dot(a, b));
}

double arc_distance(V3 p, V3 a, V3 b) {
    const V3 c{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    const double cn = std::sqrt(dot(c, c));
    if (cn > 1e-15) {
        // p's foot on the circle is on the arc when it lies after a and before b, going round c.
        const V3 ca{c.y * a.z - c.z * a.y, c.z * a.x - c.x * a.z, c.x * a.y - c.y * a.x};
        const V3 cb{c.y * b.z - c.z * b.y, c.z * b.x - c.x * b.z, c.x * b.y - c.y * b.x};
        if (dot(p, ca) >= 0 && dot(p, cb) <= 0) return std::fabs(std::asin(std::fmax(-1.0, std::fmin(1.0, dot(p, c) / cn))));
    }
    return std::fmin(arc(p, a), arc(p, b));
}

geo::DetailTree line_tree(const std::vector<SceneBody::Vertex>& v, bool closed, double scale, double max_step) {
    return TreeMaker(v, scale, max_step).make(closed);
}

}  // namespace noneuclid::world
