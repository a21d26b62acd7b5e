// A geometry engine: the one seam between a world and its geometry. World<T, E> steps its
// bodies through E, and render draws a body through E alone, so that a new engine (or a world
// whose curvature varies) is a new policy here and a row in the engine table (world/engines.hpp),
// and nothing in render. An engine E provides, for its scalar T = E::scalar:
//   move(K, b, dt)          body b one step of dt (a Tick) along its geodesic (speed, direction of travel,
//                           facing and acceleration's direction carried); true if it walked b's
//                           coast (geometry/coast.hpp)
//   settle(b, R, walked)    after the step: the limit circle's wrap of a centre past R, and what
//                           the next step must know of this one
//   vertex(K, c, facing, v) a vertex's global position from its local polar coordinates v
//   edge_points(K, p, q, n, out)  the points at fractions k / n of the edge p -> q, out(k, point)
//   Cache                   what drawing a body keeps between frames (one per body)
//   chords(b)               the most chords outline() gives for body b
//   outline(K, b, cache, m, p, verts, vecs, sink)  body b's outline in projection p on screen
//                           map m into a CurveSink (geometry/edge_curve.hpp); verts and vecs are
//                           scratch room for its vertex count
//   kFillsItsOutline        true: a filled body is filled inside the polyline outline() gives
//                           (render/fill.hpp), for an engine whose outline is not the geodesic
//                           polygon's image within a pixel; false: the fill follows the exact
//                           geodesic polygon, which the engine's outline is within a pixel of
// A body b is anything with centre, facing, travel, speed, accel_dir, coast, local (its vertices
// in local polar coordinates), shape (its shape count), closed() and tessellation() (world::Body).
#pragma once

#include <algorithm>
#include <concepts>
#include <cstddef>

#include "geometry/coast.hpp"
#include "geometry/edge_curve.hpp"
#include "geometry/geometry.hpp"
#include "geometry/outline.hpp"
#include "geometry/paper.hpp"
#include "geometry/screen_map.hpp"
#include "geometry/shape_cache.hpp"

namespace noneuclid::geo {

// The number of edges of a body: its vertices, or one fewer if it is open; none for one vertex.
template <class B>
std::size_t edge_count(const B& b) {
    const std::size_t n = b.local.size();
    return n < 2 ? 0 : (b.closed() ? n : n - 1);
}

// The exact forms of geometry/geometry.hpp in the 3-vector model, for any scalar: bodies walk
// their coasts, outlines are adaptive slerps (geometry/outline.hpp).
template <class T>
struct Exact {
    using scalar = T;
    using Cache = ShapeCache<T>;
    static constexpr bool kFillsItsOutline = false;  // its outline follows the geodesics

    template <class B>
    static bool move(T K, B& b, const Tick<T>& dt) {
        coast_step(K, b, dt);
        return true;
    }
    template <class B>
    static void settle(B& b, T R, bool walked) {
        b.wrapped = b.centre.r > R;
        if (b.wrapped) {  // the limit circle: the same as the plain wrap, in the coast's numbers
            if (walked)
                b.centre = coast_wrap(b.coast, R);
            else
                b.centre = {T(2) * R - b.centre.r > T(0) ? T(2) * R - b.centre.r : T(0), wrap_pi(b.centre.theta + pi_v<T>)};
        }
        b.coast.left = b.centre, b.coast.left_travel = b.travel;
    }
    static Polar<T> vertex(T K, Polar<T> c, T facing, Polar<T> local) { return vertex_position(K, c, facing, local); }
    template <class Out>
    static void edge_points(T K, Polar<T> p, Polar<T> q, int n, Out&& out) {
        geo::edge_points(K, p, q, n, out);
    }
    template <class B>
    static std::size_t chords(const B& b) {
        const long edges = static_cast<long>(edge_count(b));
        return static_cast<std::size_t>(2 * edges + body_split_budget(edges));
    }
    template <class B, class Sink>
    static void outline(T K, const B& b, Cache& cache, const ScreenMap<T>& m, Projection p, Polar<T>*, Vec3<T>* vecs,
                        Sink& sink) {
        rigid_outline(K, b, cache, m, p, vecs, sink);
    }
};

// The paper's formulas, literally (geometry/paper.hpp), in double: each step from the last, each
// edge at the body's tessellation level, in polar coordinates.
struct Paper {
    using scalar = double;
    // Its outline is the paper's: tessellation() chords an edge, which a large body's geodesic
    // image (far out, in the stereographic view) leaves by many pixels; its fill is inside them.
    static constexpr bool kFillsItsOutline = true;
    struct Cache {
        template <class B>
        void make(const B&) {}
    };

    template <class B>
    static bool move(double K, B& b, const Tick<double>& dt) {
        const Pose<double> p = paper::move(K, Pose<double>{b.centre, b.travel, b.facing}, b.speed * dt.dt);
        b.accel_dir = wrap_pi(b.accel_dir + (p.facing - b.facing));
        b.centre = p.centre, b.travel = p.travel, b.facing = p.facing;
        return false;
    }
    template <class B>
    static void settle(B& b, double R, bool walked) {
        Exact<double>::settle(b, R, walked);
    }
    static Polar<double> vertex(double K, Polar<double> c, double facing, Polar<double> local) {
        return paper::vertex_position(K, c, facing, local);
    }
    template <class Out>
    static void edge_points(double K, Polar<double> p, Polar<double> q, int n, Out&& out) {
        out(0, p);
        for (int k = 1; k < n; ++k) out(k, paper::edge_point(K, p, q, static_cast<double>(k) / n));
        out(n, q);
    }
    template <class B>
    static std::size_t chords(const B& b) {
        return edge_count(b) * static_cast<std::size_t>(std::max(b.tessellation(), 1));
    }
    template <class B, class Sink>
    static void outline(double K, const B& b, Cache&, const ScreenMap<double>& m, Projection p, Polar<double>* verts,
                        Vec3<double>*, Sink& sink) {
        const std::size_t n = b.local.size(), edges = edge_count(b);
        for (std::size_t i = 0; i < n; ++i) verts[i] = vertex(K, b.centre, b.facing, b.local[i]);
        if (edges == 0) return sink.start(polar_spot(m, K, verts[0], p));
        Spot prev;
        for (std::size_t e = 0; e < edges; ++e)
            edge_points(K, verts[e], verts[(e + 1) % n], b.tessellation(), [&](int k, Polar<double> q) {
                if (k == 0 && e > 0) return;
                const Spot s = polar_spot(m, K, q, p);
                if (k == 0)
                    sink.start(s);
                else
                    sink.chord(prev, s);
                prev = s;
            });
    }
};

// What a world and render need of an engine (the list above), checked where it is used.
template <class E>
concept Engine = requires(typename E::scalar K, Polar<typename E::scalar> q, typename E::Cache cache) {
    typename E::scalar;
    { E::vertex(K, q, K, q) } -> std::same_as<Polar<typename E::scalar>>;
    { E::kFillsItsOutline } -> std::convertible_to<bool>;
};

}  // namespace noneuclid::geo
