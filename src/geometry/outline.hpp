// A rigid body's outline on the screen in the 3-vector model (the exact engine's,
// geometry/engine.hpp): its vertices are its local 3-vectors moved by its motion, and each edge
// is drawn by edge_curve (adaptive halving) in the view's evaluator. An edge too long for the
// halving weights, or whose ends are antipodal on the sphere, is a walked edge: cut in two at
// its midpoint, found by a geodesic walk, first.
#pragma once

#include <cstddef>

#include "geometry/edge_curve.hpp"
#include "geometry/fx/equidistant_eval.hpp"
#include "geometry/geometry.hpp"
#include "geometry/screen_map.hpp"
#include "geometry/shape_cache.hpp"

namespace noneuclid::geo {

namespace detail {
// A walked edge P -> Q of length d: cut in two at its midpoint, found by a walk from P (along
// P's radial line when the ends are antipodal: every great circle through them is a geodesic,
// and the one through P's radial line is the convention; else toward Q), and each half drawn by
// edge_curve (halves still too long are cut again, three times at most, then drawn as chords).
template <class T, class Eval, class Sink>
void walked_edge(const Eval& ev, const ScreenMap<T>& m, T K, const Vec3<T>& P, const Vec3<T>& Q, const Spot& sp,
                 const Spot& sq, T d, typename SlerpMath<T>::U u, bool straight, Sink& sink, long& budget, int cuts = 0) {
    using Math = SlerpMath<T>;
    if (cuts == 3 || budget <= 0) return sink.chord(sp, sq);
    --budget;
    const Polar<T> p = to_polar(K, P), q = to_polar(K, Q);
    const T heading = antipodal_edge(K, d, Sf(K * d * d)) ? (p.r > T(0) ? p.theta : q.theta) : bearing(K, p, q);
    const Vec3<T> M = to_vec(K, walk_end(K, p, heading, d / T(2)));
    const Spot sm = ev.vertex(M);
    const typename Math::U half_u = Math::quarter(u);
    Eval e = ev;
    for (int k = 0; k < 2; ++k) {
        const Vec3<T>&A = k == 0 ? P : M, &B = k == 0 ? M : Q;
        const Spot &sa = k == 0 ? sp : sm, &sb = k == 0 ? sm : sq;
        if (Math::too_long(half_u)) {
            walked_edge(ev, m, K, A, B, sa, sb, d / T(2), half_u, straight, sink, budget, cuts + 1);
        } else {
            e.ends(A, B);
            edge_curve<T>(e, m, sa, sb, half_u, Math::half(half_u), straight, sink, budget);
        }
    }
}
// Every edge of a body whose vertices' 3-vectors are vecs (n of them), in the evaluator ev.
template <class T, class Eval, class Sink>
void body_curve(Eval ev, const ScreenMap<T>& m, T K, const ShapeCache<T>& sh, const Vec3<T>* vecs, std::size_t n,
                std::size_t edges, bool straight, Sink& sink) {
    long budget = body_split_budget(static_cast<long>(edges));
    const Spot first = ev.vertex(vecs[0]);
    sink.start(first);
    Spot sp = first;
    for (std::size_t e = 0; e < edges; ++e) {
        const std::size_t f = e + 1 == n ? 0 : e + 1;
        const Spot sq = f == 0 ? first : ev.vertex(vecs[f]);
        if (straight && sp.shown && sq.shown) {  // (edge_curve's first case, without ends())
            sink.chord(sp, sq);
        } else if (sh.walked[e]) {
            walked_edge(ev, m, K, vecs[e], vecs[f], sp, sq, sh.length[e], sh.u[e], straight, sink, budget);
        } else {
            ev.ends(vecs[e], vecs[f]);
            edge_curve<T>(ev, m, sp, sq, sh.u[e], sh.h[e], straight, sink, budget);
        }
        sp = sq;
    }
}
}  // namespace detail

// The outline of body b (its local vertices, centre and facing, cache `sh` refreshed for K) in
// projection p into `sink`; vecs (room for its vertex count) receives its vertices' 3-vectors.
template <class T, class B, class Sink>
void rigid_outline(T K, const B& b, ShapeCache<T>& cache, const ScreenMap<T>& m, Projection p, Vec3<T>* vecs,
                   Sink& sink) {
    const ShapeCache<T>& sh = cache.refresh(K, b, m.detail);
    const std::size_t n = sh.count, edges = sh.edges;  // (the vertices the view keeps: all but of a simplified line)
    const Motion<T> motion = body_motion(K, b.centre, b.facing);  // (MotionApply keeps a reference to it)
    const MotionApply<T> apply(motion);
    apply(sh.local.data(), vecs, n);
    const bool straight = straight_geodesics(K, p);
    with_view_eval(K, m, p, [&](const auto& ev) { detail::body_curve(ev, m, K, sh, vecs, n, edges, straight, sink); });
}

}  // namespace noneuclid::geo
