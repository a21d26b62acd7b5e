// The points along an edge: the paper's solution (c), the generalised slerp of docs/design.md,
// in polar coordinates (edge_points) and straight to the projection plane (edge_projected); the
// slerp's weights (slerp_weights: the recurrence in fixed point, the direct form otherwise);
// and the edges whose ends are antipodal on the sphere, walked instead.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "geometry/fx/slerp.hpp"
#include "geometry/model.hpp"
#include "geometry/projection.hpp"
#include "geometry/walk.hpp"

namespace noneuclid::geo {

// (c) Points along the edge p -> q at tessellation level n: n segments, n + 1 points, at
//     fractions k/n of the length (k = 0 .. n), by the generalised slerp of docs/design.md
//         X(t) = (S_K((1 - t) d) P + S_K(t d) Q) / S_K(d),
//     with the ratios written as (1 - t) Sf(K ((1-t)d)^2) / Sf(K d^2), which has no 0/0 at
//     d = 0. For antipodal ends on the sphere (S_K(d) = 0: every great circle through them is
//     a geodesic) the edge follows the one through p's radial line. out(k, Polar) is called
//     for each point.
// Whether an edge of length d (sfd = Sf(K d^2)) has antipodal ends on the sphere: S_K(d) ~ 0
// with d near pi/sqrt K, not merely d ~ 0. The slerp's weights divide by S_K(d) and cannot be
// used there.
template <class T>
bool antipodal_edge(T K, T d, T sfd) {
    return K > T(0) && K * d * d > T(2) && sfd * d <= num<T>(1e-4);
}
// The points of an edge whose ends are antipodal on the sphere (antipodal_edge), at fractions
// k/n of its length d: walked from p along p's radial line (q's when p is O), out(k, Polar) for
// k = 0 .. n.
template <class T, class Out>
void antipodal_walk(T K, Polar<T> p, Polar<T> q, T d, int n, Out&& out) {
    const T heading = p.r > T(0) ? p.theta : q.theta;
    out(0, p);
    for (int k = 1; k < n; ++k) out(k, walk(K, p, heading, d * T(k) / T(n)).end);
    out(n, q);
}
// The slerp's weights in the direct form along an edge of length d at level n (1 < n < 32768;
// sfd = Sf(K d^2)): b_k = t Sf(K (t d)^2) / sfd at t = k/n, a_k the same at u = (n - k)/n, for
// k = 1 .. n - 1 in turn: out(k, a_k, b_k). The same arithmetic as t = T(k)/T(n) and a
// division by sfd, but in fixed point without a 64-bit divide per point: the fractions are
// carried from k to k (Fractions), and sfd's reciprocal is taken once (divisor); the quotients
// are bit for bit those of operator/. With BothWeights false a_k is not computed (out gets 0):
// u rounds at k exactly as t does at n - k, so a_k = b_{n-k}. Always inlined: as a function
// of its own GCC compiles the loop into more instructions per weight.
template <bool BothWeights, class T, class Out>
[[gnu::always_inline]] inline void direct_slerp_weights(T K, T d, T sfd, int n, Out&& out) {
    Fractions<T> f(n);
    const auto by_sfd = divisor(sfd);
    auto weight = [&](T x) __attribute__((always_inline)) { return by_sfd(x * Sf(K * (x * d) * (x * d))); };
    for (int k = 1; k < n; ++k) {
        f.next();
        out(k, BothWeights ? weight(f.u(k)) : T(0), weight(f.t(k)));
    }
}
template <class T, class Out>
void edge_points(T K, Polar<T> p, Polar<T> q, int n, Out&& out) {
    const T d = distance(K, p, q);
    const T sfd = Sf(K * d * d);
    if (antipodal_edge(K, d, sfd)) return antipodal_walk(K, p, q, d, n, out);
    const Vec3<T> P = to_vec(K, p), Q = to_vec(K, q);
    out(0, p);
    if (n > 1 && n < 32768) {
        direct_slerp_weights<true>(K, d, sfd, n, [&](int k, T a, T b) { out(k, to_polar(K, slerp_point(a, P, b, Q))); });
    } else {
        for (int k = 1; k < n; ++k) {
            const T t = T(k) / T(n), u = T(n - k) / T(n);
            const T a = u * Sf(K * (u * d) * (u * d)) / sfd;
            const T b = t * Sf(K * (t * d) * (t * d)) / sfd;
            out(k, to_polar(K, slerp_point(a, P, b, Q)));
        }
    }
    out(n, q);
}

// The slerp's weights a_k = S_K((n - k) delta) / S_K(d), b_k = S_K(k delta) / S_K(d) for
// delta = d / n, by the recurrence of docs/design.md: with sigma_k = S_K(k delta) / delta,
//   sigma_0 = 0, sigma_1 = Sf(K delta^2), sigma_{k+1} = 2 C_K(delta) sigma_k - sigma_{k-1},
// a_k = sigma_{n-k} / sigma_n, b_k = sigma_k / sigma_n: no trigonometry, no table and no
// division per point, and no 0/0 for short edges. Fixed point only, in 64-bit integers with
// 30 fractional bits (fx::slerp_sigmas), one reciprocal per edge. prepare() is false where the
// caller should use the direct form instead: floating point, fewer than 4 or more than 64 segments,
// |K delta^2| > 2, or an edge near the sphere's antipode, where sigma_n is small and the
// weights large.
template <class T>
class SlerpWeights {
public:
    // Floating point keeps the direct form: the recurrence in float lost accuracy near the
    // gnomonic horizon and in the orthographic view (tests/perf/test_fast_paths.cpp), and
    // double's libm Sf is not the cost it is in fixed point's 64-bit emulation on 32-bit ARM.
    bool prepare(T, T, int) { return false; }
    T a(int) const { return T(0); }
    T b(int) const { return T(0); }
};
template <>
class SlerpWeights<fixed> {
public:
    bool prepare(fixed K, fixed d, int n) {
        // From 4 segments on: below, the direct form's two table lookups per point cost less
        // than the recurrence's set-up per edge.
        if (n < 4 || n > kMax) return false;
        if (!fx::slerp_sigmas(K, d, n, sigma_)) return false;
        const int64_t top = sigma_[n];
        if (top < (int64_t{1} << 27)) return false;  // sigma_n < 1/8
        for (int k = 1; k < n; ++k)
            if (sigma_[k] >= 2 * top || sigma_[k] <= -2 * top) return false;
        n_ = n;
        // top 2^e in [2^31, 2^32): inv ~ 2^(62 + e) / top.
        e_ = std::countl_zero(static_cast<uint64_t>(top)) - 32;
        inv_ = fx::detail::recip_q62(static_cast<uint32_t>(e_ >= 0 ? top << e_ : top >> -e_));
        return true;
    }
    fixed a(int k) const { return weight(sigma_[n_ - k]); }
    fixed b(int k) const { return weight(sigma_[k]); }

private:
    // sigma / sigma_n in Q16.16: (sigma 2^e) (2^(62+e) / top) / 2^(62 + 2e - ...) -> x' inv >> 46.
    fixed weight(int64_t sig) const {
        const int64_t x = e_ >= 0 ? sig * (int64_t{1} << e_) : sig >> -e_;  // |x| < 2^33
        const uint64_t m = static_cast<uint64_t>(x < 0 ? -x : x);
        const uint64_t q = (m * inv_ + (uint64_t{1} << 45)) >> 46;
        return fixed::from_raw(static_cast<int32_t>(x < 0 ? -static_cast<int64_t>(q) : static_cast<int64_t>(q)));
    }
    static constexpr int kMax = 64;
    int64_t sigma_[kMax + 1];
    uint64_t inv_ = 0;
    int e_ = 0;
    int n_ = 0;
};

// The weights (a_k, b_k), k = 1 .. n - 1, of the generalised slerp along an edge of length d
// at level n (edge_projected's, in the same arithmetic: the recurrence in fixed point where
// SlerpWeights takes it, else the direct form), written to ab[2 (k - 1)], ab[2 (k - 1) + 1].
// They depend on K, d and n alone, so a rigid body keeps them until K changes. False, and
// nothing written, for an edge whose ends are antipodal on the sphere (S_K(d) ~ 0), where the
// caller walks the edge instead (edge_projected does).
template <class T>
bool slerp_weights(T K, T d, int n, T* ab) {
    const T sfd = Sf(K * d * d);
    if (antipodal_edge(K, d, sfd)) return false;
    SlerpWeights<T> w;
    if (w.prepare(K, d, n)) {
        for (int k = 1; k < n; ++k) ab[2 * (k - 1)] = w.a(k), ab[2 * (k - 1) + 1] = w.b(k);
    } else if (n > 1 && n < 32768) {  // each weight computed once: a_k = b_{n-k}
        direct_slerp_weights<false>(K, d, sfd, n, [&](int k, T, T b) { ab[2 * (k - 1) + 1] = b, ab[2 * (n - k - 1)] = b; });
    }
    return true;
}

// (c, for drawing) The points of edge_points, projected: out(k, visible, X, Y) with
// (X, Y) = rho (cos theta, sin theta), the point in the projection plane relative to O
// (pixels: cx + scale X, cy - scale Y). The interior points skip the polar reading: for the
// 3-vector (w, x, y) = (C_K(r), S_K(r) cos theta, S_K(r) sin theta), rho(r) / S_K(r) depends on
// w and S^2 = x^2 + y^2 alone, so (X, Y) = (x, y) rho/S with, for g = 2 / (1 + w) (w >= 0),
//   equidistant    r / S = g ATf(K S^2 g^2 / 4)     (arc_K without its square root)
//   stereographic  2 T_K(r/2) / S = g
//   Lambert        2 S_K(r/2) / S = sqrt(g)
// and no atan2, hypot, sine or cosine is needed per point. The end points, points past the
// sphere's equator (w < 0), points too far out for S^2 in the scalar, antipodal edges, and the
// gnomonic and orthographic projections take the polar path (project, then the bearing's cosine
// and sine): in fixed point 1/w near the gnomonic horizon, and x, y read straight off the
// 3-vector in the orthographic view, were measured less accurate than the polar path
// (tests/perf/test_fast_paths.cpp holds the others to the polar path's error).
// With the end points' 3-vectors P = to_vec(K, p), Q = to_vec(K, q) given (a polygon's vertices
// are each an end of two edges: the caller computes them once), and the start point left out
// when `with_start` is false (it is the previous edge's end).
template <class T, class Out>
void edge_projected(T K, Polar<T> p, Polar<T> q, const Vec3<T>& P, const Vec3<T>& Q, int n, Projection proj,
                    bool with_start, Out&& out) {
    const T d = distance(K, p, q);
    const T sfd = Sf(K * d * d);
    auto polar = [&](int k, Polar<T> x) {
        if (k == 0 && !with_start) return;
        const ProjectedPoint<T> pp = project_polar(K, x, proj);
        out(k, pp.visible, pp.X, pp.Y);
    };
    if (antipodal_edge(K, d, sfd)) return antipodal_walk(K, p, q, d, n, polar);
    polar(0, p);
    auto point = [&](int k, T a, T b) {
        const ProjectedPoint<T> pp = project_vec(K, slerp_point(a, P, b, Q), proj);
        out(k, pp.visible, pp.X, pp.Y);
    };
    SlerpWeights<T> w;
    if (w.prepare(K, d, n)) {
        for (int k = 1; k < n; ++k) point(k, w.a(k), w.b(k));
    } else if (n > 1 && n < 32768) {
        direct_slerp_weights<true>(K, d, sfd, n, point);
    }
    polar(n, q);
}
// The same points from the end points' 3-vectors and the edge's slerp_weights (ab, n - 1
// pairs), the end points projected from their 3-vectors as well: no polar coordinates at all.
template <class T, class Out>
void edge_projected(T K, const Vec3<T>& P, const Vec3<T>& Q, const T* ab, int n, Projection proj, bool with_start,
                    Out&& out) {
    auto point = [&](int k, const Vec3<T>& v) {
        const ProjectedPoint<T> pp = project_vec(K, v, proj);
        out(k, pp.visible, pp.X, pp.Y);
    };
    if (with_start) point(0, P);
    for (int k = 1; k < n; ++k) {
        point(k, slerp_point(ab[2 * (k - 1)], P, ab[2 * (k - 1) + 1], Q));
    }
    point(n, Q);
}
template <class T, class Out>
void edge_projected(T K, Polar<T> p, Polar<T> q, int n, Projection proj, Out&& out) {
    edge_projected(K, p, q, to_vec(K, p), to_vec(K, q), n, proj, true, out);
}

}  // namespace noneuclid::geo
