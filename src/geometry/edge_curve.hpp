// Adaptive tessellation on the screen: an edge (a geodesic from P to Q, 3-vectors) is cut in
// halves, and its halves again, wherever the projected curve departs from the drawn chord by
// more than kChordTolerance (screen_map.hpp, grade), and each chord goes to a sink (CurveSink
// below; render's ClipSink clips it to the clip circle). So an edge gets as many points as its
// picture needs and no more: none inside a straight edge (every edge at K = 0, every edge of
// the gnomonic view), many where the view stretches it (near the rim at K = +1).
//
// Every point is the generalised slerp a P + b Q of the edge's ends (docs/design.md), its
// weights found by halving: the midpoint of the segment between the points of weights
// (a0, b0) and (a1, b1), of length x, has weights h (a0 + a1, b0 + b1) with h = 1 / (2 C_K(x/2))
// (P + Q has <P + Q, P + Q> = 4 C_K(x/2)^2). The weights are computed, never the points from
// other points: a point's error does not grow with its depth. h depends on K and x alone:
// with u = K (x/2)^2 it is 1 / (2 Cf(u)), and each halving divides u by 4 (SlerpMath).
//
// Where the cutting stops: at kMaxDepth halvings (an edge's 1/4096), at kOutsideDepth for a
// piece wholly outside the clip circle (it can only show where it dips back in), at once for a
// piece whose ends lie in the ball about the sphere's antipode that the clip circle leaves out
// (ScreenMap::outside_is_ball: nothing of it can show), and when the body's budget of halvings
// (body_split_budget) is spent.
#pragma once

#include <cmath>
#include <concepts>
#include <cstdint>
#include <type_traits>

#include "fixed/division.hpp"
#include "fixed/fixed.hpp"
#include "geometry/geometry.hpp"
#include "geometry/screen_map.hpp"

namespace noneuclid::geo {

// Where a curve's chords go: its first point (start), each chord to the next point (chord),
// the end of a piece (end), and whether a curve through three points all outside the clip
// circle stays outside it (stays_outside: the sink owns the clip circle).
template <class S>
concept CurveSink = requires(S& s, const Spot& p, SubPoint a) {
    s.start(p);
    s.chord(p, p);
    s.end();
    { s.stays_outside(a, a, a) } -> std::convertible_to<bool>;
};

inline constexpr int kMaxDepth = 12;
inline constexpr int kOutsideDepth = 6;

// The halvings a body of `edges` edges may take a frame: its points are bounded by them
// (body_point_capacity).
inline long body_split_budget(long edges) { return 4 * edges + 256; }

// The slerp's weights and the halving weight h in the engine's arithmetic: floating point here,
// Q30 in 64-bit integers for fixed point (below).
template <class T>
struct SlerpMath {
    using W = T;  // a weight
    using U = T;  // u = K (x/2)^2
    static W one() { return T(1); }
    static W zero() { return T(0); }
    // u of an edge of length d.
    static U u_of(T K, T d) { return K * d * d / T(4); }
    static U quarter(U u) { return u / T(4); }
    // 1 / (2 Cf(u)): the series of sec sqrt(u) / 2 where it is exact to the last bit (its
    // first term left out is 0.014 u^5), else the closed form.
    static W half(U u) {
        using std::fabs;
        if (fabs(u) <= (std::is_same_v<T, float> ? T(1) / T(64) : T(1e-4)))
            return T(0.5) * (T(1) + u * (T(0.5) + u * (T(5) / T(24) + u * (T(61) / T(720) + u * (T(277) / T(8064))))));
        return T(0.5) / Cf(u);
    }
    static W mid(W a0, W a1, W h) { return h * (a0 + a1); }
    // Whether an edge with this u is too long for the halving weights (h near 4, where the
    // fixed engine's weights would overflow, or u past the range its series covers): such an
    // edge is first cut in two by a walk (geometry/outline.hpp).
    static bool too_long(U u) { return u > T(2.08) || u < T(-2.2); }
    static Vec3<T> combine(W a, const Vec3<T>& P, W b, const Vec3<T>& Q) {
        return {a * P.w + b * Q.w, a * P.x + b * Q.x, a * P.y + b * Q.y};
    }
};
template <>
struct SlerpMath<fx::fixed> {
    using W = int64_t;  // Q30, in [0, 4]
    using U = int64_t;  // Q30
    static constexpr int kFrac = 30;
    static constexpr int64_t kOne = int64_t{1} << kFrac;
    static W one() { return kOne; }
    static W zero() { return 0; }
    static U u_of(fx::fixed K, fx::fixed d) {
        const int64_t dr = d.raw() < 0 ? -int64_t{d.raw()} : d.raw();
        if (dr >= (int64_t{1} << 20)) return int64_t{1} << 40;  // d >= 16: too long
        return fx::detail::round_shift(int64_t{K.raw()} * (dr * dr), 16 + 32 - kFrac + 2);
    }
    static U quarter(U u) { return u >> 2; }
    static W half(U u) {
        const auto mul = [](int64_t a, int64_t b) { return fx::detail::round_shift(a * b, kFrac); };
        if (u <= (kOne >> 6) && u >= -(kOne >> 6)) {  // sec sqrt(u) / 2 to u^4: exact within 2^-33
            int64_t p = 36883245;                      // 277/8064, Q30
            p = 90969793 + mul(u, p);                  // 61/720
            p = 223696213 + mul(u, p);                 // 5/24
            p = (kOne >> 1) + mul(u, p);
            p = kOne + mul(u, p);
            return p >> 1;
        }
        // Cf(u) = 1 - u/(1 2) (1 - u/(3 4) (1 - ...)) to the 10th term (|u| <= 2.2: the next
        // is below 2^-40), then its reciprocal.
        int64_t c = kOne;
        for (int j = 19; j >= 1; j -= 2) c = kOne - mul(mul(u, c), kOne / (j * (j + 1)));
        return fx::detail::div_round(int64_t{1} << (2 * kFrac - 1), static_cast<uint32_t>(c));
    }
    static W mid(W a0, W a1, W h) { return fx::detail::round_shift((a0 + a1) * h, kFrac); }
    static bool too_long(U u) { return u > 2233382994 || u < -2362232013; }  // 2.08, -2.2
    static Vec3<fx::fixed> combine(W a, const Vec3<fx::fixed>& P, W b, const Vec3<fx::fixed>& Q) {
        auto c = [a, b](fx::fixed p, fx::fixed q) {
            return fx::fixed::from_raw(fx::detail::saturate32(fx::detail::round_shift(a * p.raw() + b * q.raw(), kFrac)));
        };
        return {c(P.w, Q.w), c(P.x, Q.x), c(P.y, Q.y)};
    }
};

// The general evaluator: a 3-vector through project_vec in the engine's scalar, mapped to
// the screen. (The fixed engine's equidistant view has its own: geometry/fx/equidistant_eval.hpp.)
template <class T>
struct VecEval {
    using Math = SlerpMath<T>;
    T K;
    Projection projection;
    const ScreenMap<T>& m;
    Vec3<T> P{}, Q{};

    void ends(const Vec3<T>& p, const Vec3<T>& q) { P = p, Q = q; }
    Spot vertex(const Vec3<T>& v) const {
        const ProjectedPoint<T> pp = project_vec(K, v, projection);
        if (!pp.visible) return {};
        return spot_at(m, to_pixels(ScreenPoint<T>{m.cx + m.scale * pp.X, m.cy - m.scale * pp.Y}));
    }
    Spot point(typename Math::W a, typename Math::W b) const { return vertex(Math::combine(a, P, b, Q)); }
};

// The evaluator of a view (a projection and a screen map) for scalar T: f(eval) with the
// general one, VecEval. The fixed scalar's equidistant view has its own kernel
// (geometry/fx/equidistant_eval.hpp overloads this).
template <class T, class F>
void with_view_eval(T K, const ScreenMap<T>& m, Projection p, F&& f) {
    f(VecEval<T>{K, p, m});
}

namespace detail {
// edge_curve past its first midpoint: the piece from a to b (its weights and its ends' spots)
// at `depth`, cut in halves depth first while the cutting goes on (the header comment). Each
// chord to the sink in order. Recursive: at most kMaxDepth deep.
template <class T, class Eval, class Sink>
struct EdgePieces {
    using Math = SlerpMath<T>;
    using W = typename Math::W;
    struct End {
        W a, b;  // the weights of P and Q
        Spot s;
    };
    EdgePieces(const Eval& e, const ScreenMap<T>& map, Sink& s, long& left, bool line, typename Math::U u0, W h0)
        : ev(e), m(map), sink(s), budget(left), straight(line), u(u0) {
        h[0] = h0;
    }
    const Eval& ev;
    const ScreenMap<T>& m;
    Sink& sink;
    long& budget;
    bool straight;
    typename Math::U u;  // u of the deepest halving weight found so far
    int known = 1;       // h[0 .. known) found
    W h[kMaxDepth];

    // The piece a -> b at `depth`, whose midpoint mid (graded g) is already known.
    [[gnu::noinline]] void cut(const End& a, const End& b, const End& mid, Grade g, int depth) {
        --budget;
        if (g == kOneCut) {
            sink.chord(a.s, mid.s);
            return sink.chord(mid.s, b.s);
        }
        piece(a, mid, depth + 1);
        piece(mid, b, depth + 1);
    }
    void piece(const End& a, const End& b, int depth) {
        const bool out = !a.s.in && !b.s.in, shown = a.s.shown && b.s.shown;
        if (straight && shown) return sink.chord(a.s, b.s);
        if (out && m.outside_is_ball) return;  // nothing of it shows
        if (depth < (out ? kOutsideDepth : kMaxDepth) && budget > 0) {
            while (known <= depth) u = Math::quarter(u), h[known] = Math::half(u), ++known;
            End mid{Math::mid(a.a, b.a, h[depth]), Math::mid(a.b, b.b, h[depth]), {}};
            mid.s = ev.point(mid.a, mid.b);
            const Grade g = shown && mid.s.shown ? grade(a.s.at, mid.s.at, b.s.at) : kBent;
            if (g == kFlat) return sink.chord(a.s, b.s);
            if (out && g != kBent && !mid.s.in && sink.stays_outside(a.s.at, mid.s.at, b.s.at)) return;
            return cut(a, b, mid, g, depth);
        }
        // The cutting stopped first: a chord not known to follow its curve is drawn only between
        // two points within the clip circle; one leaving or entering the circle ends or starts
        // the polyline at its point inside, and one wholly outside is left out.
        if (a.s.in && b.s.in) return sink.chord(a.s, b.s);
        if (a.s.in) return sink.end();
        sink.start(b.s);
    }
};
}  // namespace detail

// The curve of one edge, from its first point (already given to the sink) to its last, each
// chord to the sink. u0 = SlerpMath::u_of(K, d) = K (d/2)^2 for the edge's length d, and
// h0 = half(u0) (the shape cache keeps both). `straight`: the view draws this edge's geodesic
// as a straight line (straight_geodesics). `budget`: the body's halvings left. The common
// case, a single chord, is decided here; the cutting is detail::EdgePieces.
template <class T, class Eval, CurveSink Sink>
[[gnu::always_inline]] inline void edge_curve(const Eval& ev, const ScreenMap<T>& m, const Spot& sp, const Spot& sq,
                                              typename SlerpMath<T>::U u0, typename SlerpMath<T>::W h0, bool straight,
                                              Sink& sink, long& budget) {
    const bool shown = sp.shown && sq.shown, out = !sp.in && !sq.in;
    if (straight && shown) return sink.chord(sp, sq);
    if (out && m.outside_is_ball) return;
    if (budget <= 0) return sp.in && sq.in ? sink.chord(sp, sq) : sp.in ? sink.end() : sink.start(sq);
    const Spot mid = ev.point(h0, h0);
    const Grade g = shown && mid.shown ? grade(sp.at, mid.at, sq.at) : kBent;
    if (g == kFlat) return sink.chord(sp, sq);
    if (out && g != kBent && !mid.in && sink.stays_outside(sp.at, mid.at, sq.at)) return;
    using Math = SlerpMath<T>;
    detail::EdgePieces<T, Eval, Sink> pieces(ev, m, sink, budget, straight, u0, h0);
    pieces.cut({Math::one(), Math::zero(), sp}, {Math::zero(), Math::one(), sq}, {h0, h0, mid}, g, 0);
}

}  // namespace noneuclid::geo
