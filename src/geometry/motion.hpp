// A rigid body in the 3-vector model: the motion that takes its local frame to where it is, as
// a 3x3 matrix built once per body and frame (body_motion), applied to the body's local
// vertices (MotionApply; in fixed point without per-product overflow tests where the entries
// allow).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "geometry/model.hpp"

namespace noneuclid::geo {

// The rigid motion that takes a body's local frame (its centre at O, its facing along +x) to
// where the body is: a point given by its local 3-vector L = to_vec(K, (rho, phi)) lands at
// motion * L. It is walk_end's triangle as a matrix, built once per body and frame: with
// alpha = facing - theta_c (the facing against the centre's outward radial),
//   (w, x', y') = (C L_w - K S (cos alpha L_x - sin alpha L_y),
//                  S L_w + C (cos alpha L_x - sin alpha L_y),  sin alpha L_x + cos alpha L_y)
// for S = S_K(r_c), C = C_K(r_c), then (x', y') turned by theta_c. So a vertex costs nine
// products, not walk_end's sines, cosines, curvature functions, square root and atan2.
template <class T>
struct Motion {
    T m[3][3];  // rows w, x, y; columns L_w, L_x, L_y
    Vec3<T> operator()(const Vec3<T>& L) const {
        return {dot3(m[0][0], L.w, m[0][1], L.x, m[0][2], L.y), dot3(m[1][0], L.w, m[1][1], L.x, m[1][2], L.y),
                dot3(m[2][0], L.w, m[2][1], L.x, m[2][2], L.y)};
    }
};
// M(L) for many L, the same bits as M(L). In fixed point, where every entry of M is below 2^14
// in magnitude (`small`, checked once per body), without dot3's overflow tests: each product
// is then below 2^30 2^31 = 2^61 and a row's sum below 3 2^61 < 2^63, so it cannot overflow,
// and rounding it and saturating to 32 bits gives what dot3 gives (dot3's early clamp at
// 2^62 - 2^15 clamps what saturation clamps too).
template <class T>
struct MotionApply {
    explicit MotionApply(const Motion<T>& m) : M(m) {}
    explicit MotionApply(Motion<T>&&) = delete;  // it keeps a reference: not to a temporary
    Vec3<T> operator()(const Vec3<T>& L) const { return M(L); }
    void operator()(const Vec3<T>* L, Vec3<T>* out, std::size_t n) const {
        for (std::size_t i = 0; i < n; ++i) out[i] = M(L[i]);
    }
    const Motion<T>& M;
};
template <>
struct MotionApply<fixed> {
    static constexpr int64_t kLim = int64_t{1} << 30;  // 2^14 in Q16.16
    static bool below(fixed v) { return static_cast<uint64_t>(v.raw() + kLim) < uint64_t{2 * kLim}; }
    explicit MotionApply(Motion<fixed>&&) = delete;  // it keeps a reference: not to a temporary
    explicit MotionApply(const Motion<fixed>& m) : M(m) {
        for (const auto& row : m.m)
            for (fixed v : row) small = small && below(v);
    }
    [[gnu::always_inline]] Vec3<fixed> operator()(const Vec3<fixed>& L) const { return small ? fast(L) : M(L); }
    // M(L[i]) for n vertices, the same bits. The test for `small` is out of the loop, and so is
    // the saturation: the loop keeps each row's 32-bit truncation and ORs together whether any
    // did not fit, and only then (never, in the scenes) is the loop done again, saturating. So
    // its body has no branch: three multiply-adds a row (aarch64 smaddl). Where the first row
    // is (1, 0, 0) (the plane, K = 0, where every w is 1; or a body centred at O) w is L_w,
    // which is that row's rounded sum exactly, and is copied.
    void operator()(const Vec3<fixed>* L, Vec3<fixed>* out, std::size_t n) const {
        if (!small) {
            for (std::size_t i = 0; i < n; ++i) out[i] = M(L[i]);
            return;
        }
        const bool w_is_Lw = M.m[0][0].raw() == fixed::one_raw && M.m[0][1].raw() == 0 && M.m[0][2].raw() == 0;
        const uint64_t wide = w_is_Lw ? batch<true>(L, out, n) : batch<false>(L, out, n);
        if ((wide >> 32) != 0)
            for (std::size_t i = 0; i < n; ++i) out[i] = fast(L[i]);
    }
    template <bool WIsLw>
    [[gnu::always_inline]] uint64_t batch(const Vec3<fixed>* L, Vec3<fixed>* out, std::size_t n) const {
        const Motion<fixed> m = M;  // a copy, in registers: out[i] could alias M
        uint64_t wide = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const int64_t x = row(m.m[1], L[i]), y = row(m.m[2], L[i]);
            const int64_t w = WIsLw ? L[i].w.raw() : row(m.m[0], L[i]);
            wide |= (WIsLw ? 0 : biased(w)) | biased(x) | biased(y);
            out[i] = {fixed::from_raw(static_cast<int32_t>(w)), fixed::from_raw(static_cast<int32_t>(x)),
                      fixed::from_raw(static_cast<int32_t>(y))};
        }
        return wide;
    }
    [[gnu::always_inline]] static int64_t row(const fixed* m, const Vec3<fixed>& L) {
        int64_t s = (int64_t{1} << 15) + int64_t{m[0].raw()} * L.w.raw();  // rounded to nearest, as dot3
        s += int64_t{m[1].raw()} * L.x.raw();
        s += int64_t{m[2].raw()} * L.y.raw();
        return s >> 16;
    }
    // v + 2^31 is below 2^32 exactly when v fits in 32 bits.
    static uint64_t biased(int64_t v) { return static_cast<uint64_t>(v) + (uint64_t{1} << 31); }
    [[gnu::always_inline]] Vec3<fixed> fast(const Vec3<fixed>& L) const {
        const int64_t w = row(M.m[0], L), x = row(M.m[1], L), y = row(M.m[2], L);
        if (((biased(w) | biased(x) | biased(y)) >> 32) != 0)  // one does not: dot3 saturates it
            return {fixed::from_raw(fx::detail::saturate32(w)), fixed::from_raw(fx::detail::saturate32(x)),
                    fixed::from_raw(fx::detail::saturate32(y))};
        return {fixed::from_raw(static_cast<int32_t>(w)), fixed::from_raw(static_cast<int32_t>(x)),
                fixed::from_raw(static_cast<int32_t>(y))};
    }
    const Motion<fixed>& M;
    bool small = true;
};

template <class T>
Motion<T> body_motion(T K, Polar<T> centre, T facing) {
    using std::cos, std::sin;
    const T alpha = facing - centre.theta;
    const T ca = cos(alpha), sa = sin(alpha), ct = cos(centre.theta), st = sin(centre.theta);
    const T S = S_K(K, centre.r), C = C_K(K, centre.r);
    const T ks = K * S, cca = C * ca, csa = C * sa;
    Motion<T> M;
    M.m[0][0] = C, M.m[0][1] = -(ks * ca), M.m[0][2] = ks * sa;
    M.m[1][0] = ct * S, M.m[1][1] = dot2(ct, cca, -st, sa), M.m[1][2] = dot2(-ct, csa, -st, ca);
    M.m[2][0] = st * S, M.m[2][1] = dot2(st, cca, ct, sa), M.m[2][2] = dot2(-st, csa, ct, ca);
    return M;
}

}  // namespace noneuclid::geo
