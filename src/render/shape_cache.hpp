// What drawing a rigid body needs that changes only with K and its shape: each vertex as its local 3-vector
// about the centre, and each edge's slerp weights (a rigid motion keeps the edge's length, so
// they come from the local polar vertices). One per body, owned by the drawing's scratch
// (DrawScratch, ParallelScratch), made for the body when the scratch is prepared (this
// allocates), and refreshed in place, without allocating, when K differs from the K it was
// last refreshed at or the body took a new shape of as many vertices (world::Body::shape). The threaded frame hands each body to one thread, which alone refreshes
// that body's cache: no cache is written by two threads at once.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/geometry.hpp"
#include "world/world.hpp"

namespace noneuclid::render {

template <class T>
struct alignas(64) ShapeCache {  // (a cache line of its own: neighbours may be another thread's)
    T K{};
    uint32_t shape = 0;  // the body's shape count it was made for (world::Body::shape)
    bool valid = false;
    std::vector<geo::Vec3<T>> local;  // per vertex
    std::vector<T> root;              // per vertex: root_S_K(K, rho), for the edge lengths
    std::vector<T> weights;           // per edge, (level - 1) pairs (a_k, b_k): weights_of(e)
    std::vector<uint8_t> antipodal;   // per edge: no weights (ends antipodal on the sphere)
    // Set by make, whatever K: each vertex's (cos phi, sin phi), each edge's
    // sine_of_half(phi1 - phi2).
    std::vector<T> cos_phi, sin_phi;
    std::vector<geo::HalfSine<T>> half_sine;
    std::size_t per_edge = 0;     // 2 (level - 1): the weights of one edge
    bool any_antipodal = false;  // whether any edge is antipodal
    T* weights_of(std::size_t e) { return weights.data() + e * per_edge; }
    const T* weights_of(std::size_t e) const { return weights.data() + e * per_edge; }

    // Sized for body b, its parts that do not depend on K set; not valid until refreshed.
    void make(const world::Body<T>& b) {
        const std::size_t n = b.local.size(), edges = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
        valid = false;
        local.assign(n, {});
        root.assign(n, T{});
        antipodal.assign(edges, 0);
        cos_phi.assign(n, T{}), sin_phi.assign(n, T{}), half_sine.assign(edges, {});
        const int level = b.desc->tessellation;
        per_edge = static_cast<std::size_t>(level > 1 ? 2 * (level - 1) : 0);
        weights.assign(edges * per_edge, T{});
        set_angles(b);
    }
    // The parts that depend on the shape alone, in place (a game's asteroid takes a new shape
    // in a body of the same vertex count: nothing is allocated).
    void set_angles(const world::Body<T>& b) {
        using std::cos, std::sin;  // and fx:: ones by ADL for fixed
        using geo::sine_of_half;
        const std::size_t n = b.local.size();
        for (std::size_t i = 0; i < n; ++i) cos_phi[i] = cos(b.local[i].theta), sin_phi[i] = sin(b.local[i].theta);
        for (std::size_t e = 0; e < half_sine.size(); ++e)
            half_sine[e] = sine_of_half(b.local[e].theta - b.local[(e + 1) % n].theta);
        shape = b.shape, valid = false;
    }

    // The cache at curvature K for body b (the body it was made for), refreshed first if K
    // changed since.
    const ShapeCache& refresh(T curvature, const world::Body<T>& b) {
        if (shape != b.shape) set_angles(b);
        if (valid && K == curvature) return *this;
        const std::size_t n = b.local.size(), edges = antipodal.size();
        const int level = b.desc->tessellation;
        for (std::size_t i = 0; i < n; ++i) {  // geo::to_vec and root_S_K, S_K taken once
            const T rho = b.local[i].r, s = geo::S_K(curvature, rho);
            local[i] = {geo::C_K(curvature, rho), s * cos_phi[i], s * sin_phi[i]};
            root[i] = geo::clamped_root(s);
        }
        any_antipodal = false;
        for (std::size_t e = 0; e < edges; ++e) {
            const std::size_t f = (e + 1) % n;
            // geo::distance(K, b.local[e], b.local[f]), bit for bit, from the kept parts.
            const T d = geo::distance_from(curvature, b.local[e].r, b.local[f].r, root[e], root[f], half_sine[e]);
            antipodal[e] = !geo::slerp_weights(curvature, d, level, weights_of(e));
            any_antipodal = any_antipodal || antipodal[e];
        }
        K = curvature, valid = true;
        return *this;
    }
};

// A cache for each of a world's bodies, made for them.
template <class W>
void make_shape_caches(const W& world, std::vector<ShapeCache<typename W::scalar>>& caches) {
    caches.resize(world.bodies.size());
    for (std::size_t i = 0; i < caches.size(); ++i) caches[i].make(world.bodies[i]);
}

}  // namespace noneuclid::render
