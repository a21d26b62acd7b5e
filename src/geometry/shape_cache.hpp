// What drawing a rigid body needs that changes only with K and its shape: each vertex as its
// local 3-vector about the centre, and each edge's length with the first halving weight of its
// adaptive tessellation (geometry/edge_curve.hpp; a rigid motion keeps the edge's length, so it
// comes from the local polar vertices). One per body (the exact engine's Cache,
// geometry/engine.hpp), owned by the drawing's scratch (render's DrawScratch, ParallelScratch),
// made for the body when the scratch is prepared (this allocates), and refreshed in place,
// without allocating, when K differs from the K it was last refreshed at, the body took a new
// shape of as many vertices (its `shape` count) or its vertices' rho changed (`sized`). A body here is anything with `local` (its
// vertices in local polar coordinates), `shape` and `closed()` (world::Body). The
// threaded frame hands each body to one thread, which alone refreshes
// that body's cache: no cache is written by two threads at once.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/detail.hpp"
#include "geometry/geometry.hpp"
#include "geometry/edge_curve.hpp"
#include "geometry/screen_map.hpp"

namespace noneuclid::geo {

template <class T>
struct alignas(kThreadAlign) ShapeCache {  // (a cache line of its own: neighbours may be another thread's)
    using Math = SlerpMath<T>;
    T K{};
    uint32_t shape = 0;  // the body's shape count it was made for (world::Body::shape)
    uint32_t sized = 0;  // and its count of changes to the vertices' rho alone (world::Body::sized)
    bool valid = false;
    std::vector<Vec3<T>> local;  // per vertex
    std::vector<T> root;              // per vertex: root_S_K(K, rho), for the edge lengths
    // Per edge: its length, u = K (d/2)^2 and the halving weight h = half(u) of edge_curve, and
    // whether it is walked (its ends antipodal on the sphere, or too long for the weights:
    // body_screen_points cuts it in two first).
    std::vector<T> length;
    std::vector<typename Math::U> u;
    std::vector<typename Math::W> h;
    std::vector<uint8_t> walked;
    // Set by make, whatever K: each vertex's (cos phi, sin phi), each edge's
    // sine_of_half(phi1 - phi2), and whether its ends lie on one geodesic through the body's
    // centre (a grid line's edges: its vertices lie on one line through it), on the same side
    // (kSameSide: d = |rho1 - rho2|) or on opposite sides (kOppositeSides: d = rho1 + rho2), for
    // every K, with nothing computed.
    enum Radial : uint8_t { kNotRadial, kSameSide, kOppositeSides };
    std::vector<T> cos_phi, sin_phi;
    std::vector<HalfSine<T>> half_sine;
    std::vector<uint8_t> radial;
    bool all_radial = false;
    // A line simplified for the view (geometry/detail.hpp): its tree (the body's scene
    // description's, if it has one), the vertices the view keeps (local, root and the edges
    // above are then theirs, `count` and `edges` of them), the walk's stack, and the
    // DetailScale stamp they were kept for. Without a tree every vertex is drawn.
    // (kept and stack in a part of their own, made for a line with a tree alone: a pointer for
    // every other body, where RAM is short.)
    const DetailTree* tree = nullptr;
    struct Walk {
        std::vector<uint32_t> kept;
        std::vector<int32_t> stack;
    };
    std::unique_ptr<Walk> walk_room;
    uint32_t detail_stamp = 0;
    std::size_t count = 0, edges = 0;
    // A still body's screen points and a zoom level's record (Still), for a cache made to keep
    // them (render/body_points.hpp: a grid line's); null, not kept: one pointer a body where
    // RAM is short (the firmware).
    struct Still;
    std::unique_ptr<Still> still;

    // Sized for body b, its parts that do not depend on K set; not valid until refreshed.
    template <class B>
    void make(const B& b) {
        const std::size_t n = b.local.size(), edges = n < 2 ? 0 : (b.closed() ? n : n - 1);
        valid = false;
        local.assign(n, {});
        root.assign(n, T{});
        length.assign(edges, T{});
        u.assign(edges, {});
        h.assign(edges, {});
        walked.assign(edges, 0);
        cos_phi.assign(n, T{}), sin_phi.assign(n, T{}), half_sine.assign(edges, {}), radial.assign(edges, kNotRadial);
        tree = nullptr;
        if constexpr (requires { b.desc->detail; })
            if (b.desc && b.desc->detail && !b.desc->detail->empty()) tree = b.desc->detail.get();
        walk_room.reset();
        if (tree) walk_room = std::make_unique<Walk>(Walk{std::vector<uint32_t>(n), std::vector<int32_t>(n)});
        count = n, this->edges = edges;
        set_angles(b);
    }
    // The parts that depend on the shape alone, in place (a game's asteroid takes a new shape
    // in a body of the same vertex count: nothing is allocated).
    template <class B>
    void set_angles(const B& b) {
        using std::cos, std::sin;  // and fx:: ones by ADL for fixed
        const std::size_t n = b.local.size();
        for (std::size_t i = 0; i < n; ++i) cos_phi[i] = cos(b.local[i].theta), sin_phi[i] = sin(b.local[i].theta);
        all_radial = true;
        for (std::size_t e = 0; e < half_sine.size(); ++e) {
            const Polar<T>&p = b.local[e], &q = b.local[(e + 1) % n];
            half_sine[e] = sine_of_half(p.theta - q.theta);
            const T turn = p.theta > q.theta ? p.theta - q.theta : q.theta - p.theta;
            radial[e] = p.r == T(0) || q.r == T(0) || turn == pi_v<T> ? kOppositeSides
                        : turn == T(0)                                     ? kSameSide
                                                                           : kNotRadial;
            all_radial = all_radial && radial[e] != kNotRadial;
        }
        shape = b.shape, valid = false;
    }

    // The cache at curvature K for body b (the body it was made for), refreshed first if K
    // changed since.
    // With a tree and `view`, for that view too (the vertices it keeps).
    template <class B>
    const ShapeCache& refresh(T curvature, const B& b, const DetailScale* view = nullptr) {
        if (shape != b.shape) set_angles(b);
        if (tree && view) {
            if (!(valid && K == curvature && sized == b.sized && detail_stamp == view->stamp)) refresh_kept(curvature, b, *view);
            return *this;
        }
        if (valid && K == curvature && sized == b.sized && count == b.local.size()) return *this;
        const std::size_t n = b.local.size(), edges = walked.size();
        count = n, this->edges = edges, detail_stamp = 0;  // (every vertex: no view's kept set; stamps start at 1)
        for (std::size_t i = 0; i < n; ++i) {  // to_vec and root_S_K, S_K taken once
            const T rho = b.local[i].r, s = S_K(curvature, rho);
            local[i] = {C_K(curvature, rho), s * cos_phi[i], s * sin_phi[i]};
            if (!all_radial) root[i] = clamped_root(s);
        }
        for (std::size_t e = 0; e < edges; ++e) {
            const std::size_t f = (e + 1) % n;
            const T r1 = b.local[e].r, r2 = b.local[f].r;
            // distance(K, b.local[e], b.local[f]), from the kept parts (bit for bit), or exactly.
            const T d = radial[e] == kSameSide        ? (r1 > r2 ? r1 - r2 : r2 - r1)
                        : radial[e] == kOppositeSides ? r1 + r2
                                                      : distance_from(curvature, r1, r2, root[e], root[f], half_sine[e]);
            length[e] = d;
            u[e] = Math::u_of(curvature, d);
            // (Sf only where antipodal_edge needs it: K d^2 > 2.)
            walked[e] = Math::too_long(u[e]) ||
                        (curvature * d * d > T(2) && antipodal_edge(curvature, d, Sf(curvature * d * d)));
            h[e] = walked[e] ? typename Math::W{} : Math::half(u[e]);
        }
        K = curvature, sized = b.sized, valid = true;
        return *this;
    }

private:
    // The vertices the view keeps (in order: each bracket's left part, its split, its right
    // part), then local, root and the edges between consecutive kept vertices, as refresh
    // makes them for every vertex.
    template <class B>
    void refresh_kept(T curvature, const B& b, const DetailScale& view) {
        std::vector<uint32_t>& kept = walk_room->kept;
        std::vector<int32_t>& stack = walk_room->stack;
        const std::size_t n = b.local.size();
        const double ref = static_cast<double>(b.local[tree->ref].r);
        const double f = tree->ref_rho > 0 ? ref / tree->ref_rho : 1, px = kDetailTolerancePx;
        std::size_t m = 0;
        // In-order, from the explicit stack: a node is pushed as its index + 1 to be refined,
        // as -(index + 1) to emit its split after its left part.
        auto walk = [&](int32_t root) {
            std::size_t top = 0;
            if (root >= 0) stack[top++] = root + 1;
            while (top > 0) {
                const int32_t e = stack[--top];
                if (e < 0) {
                    const DetailNode& d = tree->nodes[-e - 1];
                    kept[m++] = static_cast<uint32_t>(d.split);
                    if (d.right >= 0) stack[top++] = d.right + 1;
                    continue;
                }
                const DetailNode& d = tree->nodes[e - 1];
                if (!(d.deviation * f * view.over(d.rho_min * f, d.rho_max * f) > px)) continue;
                stack[top++] = -e;
                if (d.left >= 0) stack[top++] = d.left + 1;
            }
        };
        kept[m++] = 0;
        walk(tree->roots[0]);
        if (tree->far > 0) {  // a ring: its far vertex, then the way back
            kept[m++] = static_cast<uint32_t>(tree->far);
            walk(tree->roots[1]);
        } else if (n > 1) {
            kept[m++] = static_cast<uint32_t>(n - 1);
        }
        count = m, edges = m < 2 ? 0 : (b.closed() ? m : m - 1);
        for (std::size_t k = 0; k < m; ++k) {  // as refresh does for every vertex
            const std::size_t i = kept[k];
            const T rho = b.local[i].r, s = S_K(curvature, rho);
            local[k] = {C_K(curvature, rho), s * cos_phi[i], s * sin_phi[i]};
            root[k] = clamped_root(s);
        }
        for (std::size_t e = 0; e < edges; ++e) {
            const std::size_t k = e + 1 == m ? 0 : e + 1;
            const Polar<T>&p = b.local[kept[e]], &q = b.local[kept[k]];
            const T turn = p.theta > q.theta ? p.theta - q.theta : q.theta - p.theta;
            const T d = p.r == T(0) || q.r == T(0) || turn == pi_v<T> ? p.r + q.r
                        : turn == T(0) ? (p.r > q.r ? p.r - q.r : q.r - p.r)
                                       : distance_from(curvature, p.r, q.r, root[e], root[k], sine_of_half(p.theta - q.theta));
            length[e] = d;
            u[e] = Math::u_of(curvature, d);
            walked[e] = Math::too_long(u[e]) ||
                        (curvature * d * d > T(2) && antipodal_edge(curvature, d, Sf(curvature * d * d)));
            h[e] = walked[e] ? typename Math::W{} : Math::half(u[e]);
        }
        K = curvature, sized = b.sized, valid = true;
        detail_stamp = view.stamp;
    }
};

// A still body's clipped screen points (render/still_points.hpp), kept with what they were
// made from, so that a frame in which none of it changed copies them instead of drawing them
// again; and a zoom level's line's record (world::Body::image_scale): its outline's spots
// before clipping, as drawn at `record_scale` (the map's scale times image_scale) within a clip
// circle kRecordReach times the view's, so that the frames of a zoom scale them instead of
// drawing them again. Room reserved when the scratch is prepared (record: for lines with a tree).
template <class T>
struct ShapeCache<T>::Still {
    struct ScreenKey {
        T K{}, R{}, scale{}, cx{}, cy{}, facing{}, r{}, theta{};  // (r, theta: the body's centre)
        int64_t clip = 0;
        uint32_t shape = 0, sized = 0, detail = 0;
        Projection projection{};
        bool operator==(const ScreenKey&) const = default;
    };
    std::vector<SubPoint> screen;
    ScreenKey screen_key{};
    bool screen_valid = false;
    bool screen_scaled = false;  // `screen` was scaled from `record`, not drawn: drawn again once still
    struct SpotRecord {
        Spot s;
        uint8_t op;  // 0 start, 1 a chord's first end, 2 its second, 3 end
    };
    std::vector<SpotRecord> record;
    double record_scale = 0;
    ScreenKey record_key{};
    bool record_valid = false;
    // Which frames of a zoom draw the record again though it is still near enough (the view's
    // stamp modulo render::kRecordPhases): the lines' redrawing spread over the frames by their
    // size, so that no frame of a zoom draws them all.
    uint32_t record_phase = 0;
};

}  // namespace noneuclid::geo
