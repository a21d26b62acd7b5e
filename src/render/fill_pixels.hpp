// A filled body's pixels, per engine: each pixel centre taken back through the projection
// (geo::unproject) and the body's motion (geo::body_motion_inverse) to its local 3-vector L,
// tested against the outline there (LocalOutline: geo::point_in_polygon's even-odd test in the
// body's own frame, where its vertices and edge normals are fixed for the frame), and painted:
// one colour, or the texel at the body's local equidistant coordinates E(L_w) (L_x, L_y)
// (geo::equidistant_ratio), the image centred on the body's centre, its +x along the facing.
// The fixed engine's equidistant view (the kiosk's) takes each pixel with integer arithmetic
// and table lookups (FastMap); every other engine and projection the general path (local_at).
// render/fill.hpp plans a body's fill and hands these functions to the row raster
// (render/fill_rows.hpp) in its FillJob.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fixed/math.hpp"
#include "geometry/geometry.hpp"
#include "geometry/local_frame.hpp"
#include "render/fill_rows.hpp"
#include "render/fill_span.hpp"
#include "render/screen_points.hpp"
#include "render/texture.hpp"

namespace noneuclid::render::fill {

using fx::fixed;

// The outline in the body's local frame, set each frame: vertex i's (w, y), for the side of the
// ray (det[L, e_x, a] = L_w a_y - L_y a_w, with e_x the facing), and edge i's (vertex i to i + 1)
// normal a x b (det[a, b, L] = L . (a x b)). inside(L) is geo::point_in_polygon with the chart
// at the centre and the ray along the facing.
template <class T>
struct LocalOutline {
    std::vector<T> aw, ay;
    std::vector<geo::Vec3<T>> normal;
    void make(std::size_t n) { aw.assign(n, T{}), ay.assign(n, T{}), normal.assign(n, {}); }
    void set(const geo::Vec3<T>* a, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            const geo::Vec3<T>&p = a[i], &q = a[i + 1 == n ? 0 : i + 1];
            aw[i] = p.w, ay[i] = p.y;
            normal[i] = {p.x * q.y - p.y * q.x, p.y * q.w - p.w * q.y, p.w * q.x - p.x * q.w};
        }
    }
    bool inside(const geo::Vec3<T>& L, bool hemisphere) const {
        if (hemisphere && !(L.w > T(0))) return false;
        const std::size_t n = aw.size();
        auto left = [&](std::size_t i) { return L.w * ay[i] - L.y * aw[i] > T(0); };
        bool in = false, was = left(n - 1);
        for (std::size_t i = 0; i < n; ++i) {
            const bool now = left(i);
            if (now != was) {
                const geo::Vec3<T>& N = normal[i == 0 ? n - 1 : i - 1];
                const T o = L.w * N.w + L.x * N.x + L.y * N.y;
                if (now ? o > T(0) : o < T(0)) in = !in;
            }
            was = now;
        }
        return in;
    }
};
// Fixed point: exact signs for the given vectors. The sides are 64-bit products of Q16.16
// values; the normals are exact in Q32 and rounded to Q24 (the plane turns by under 1e-7, far
// below L's own rounding), so that L . N (|L| < 2^31 raw, |N| < 2^28) fits in 64 bits.
template <>
struct LocalOutline<fixed> {
    struct Normal {
        int64_t w, x, y;
    };
    std::vector<int64_t> aw, ay;
    std::vector<Normal> normal;
    void make(std::size_t n) { aw.assign(n, 0), ay.assign(n, 0), normal.assign(n, {}); }
    void set(const geo::Vec3<fixed>* a, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            const geo::Vec3<fixed>&p = a[i], &q = a[i + 1 == n ? 0 : i + 1];
            const int64_t pw = p.w.raw(), px = p.x.raw(), py = p.y.raw(), qw = q.w.raw(), qx = q.x.raw(), qy = q.y.raw();
            aw[i] = pw, ay[i] = py;
            normal[i] = {fx::detail::round_shift(px * qy - py * qx, 8), fx::detail::round_shift(py * qw - pw * qy, 8),
                         fx::detail::round_shift(pw * qx - px * qw, 8)};
        }
    }
    bool inside(const geo::Vec3<fixed>& L, bool hemisphere) const {
        const int64_t lw = L.w.raw(), lx = L.x.raw(), ly = L.y.raw();
        if (hemisphere && lw <= 0) return false;
        const std::size_t n = aw.size();
        bool in = false, was = lw * ay[n - 1] - ly * aw[n - 1] > 0;
        for (std::size_t i = 0; i < n; ++i) {
            const bool now = lw * ay[i] - ly * aw[i] > 0;
            if (now != was) {
                const Normal& N = normal[i == 0 ? n - 1 : i - 1];
                const int64_t o = lw * N.w + lx * N.x + ly * N.y;
                if (now ? o > 0 : o < 0) in = !in;
            }
            was = now;
        }
        return in;
    }
};

// What taking a pixel to the body's frame and its texture needs, set each frame.
template <class T>
struct Frame {
    T K{};
    geo::Projection proj = geo::Projection::azimuthal_equidistant;
    ScreenMap<T> m{};
    geo::Motion<T> to_local{};  // geo::body_motion_inverse
    bool hemisphere = false;    // K > 0: a point must be in the centre's hemisphere
    // Texture coordinates, texels: s = s0 + k xi, t = t0 - k eta for the local equidistant
    // coordinates (xi, eta) = E(L_w) (L_x, L_y).
    int64_t s0_8 = 0, t0_8 = 0;  // the image's middle, 1/256 texel
    T k{};                       // texels per world unit
};

// Whether a pixel's place in the projection plane is one the scalar can take further: always
// in floating point; in fixed point within +-128 (farther, a square would saturate).
template <class T>
bool within_scalar(T, T) {
    return true;
}
inline bool within_scalar(fixed X, fixed Y) {
    const fixed big(128);
    return !(X > big || X < -big || Y > big || Y < -big);
}
// A pixel's local 3-vector, any engine and projection: false where the projection shows no point.
template <class T>
bool local_at(const Frame<T>& f, int x, int y, geo::Vec3<T>& L) {
    const T X = (T(x) + T(0.5) - f.m.cx) / f.m.scale, Y = (f.m.cy - T(y) - T(0.5)) / f.m.scale;
    if (!within_scalar(X, Y)) return false;
    const geo::Unprojected<T> u = geo::unproject(f.K, X, Y, f.proj);
    if (!u.valid) return false;
    L = f.to_local(u.p);
    return true;
}

// Texture coordinates (1/256 texel) of the local 3-vector L of a point inside the body.
inline int64_t clamp_texel8(double v) { return static_cast<int64_t>(std::floor(std::fmax(-1e15, std::fmin(1e15, v)))); }
template <class T>
void texcoord(const Frame<T>& f, const geo::Vec3<T>& L, int64_t& s8, int64_t& t8) {
    const double E = geo::equidistant_ratio(static_cast<double>(L.w)), k = static_cast<double>(f.k) * 256;
    s8 = f.s0_8 + clamp_texel8(E * static_cast<double>(L.x) * k);
    t8 = f.t0_8 + clamp_texel8(-E * static_cast<double>(L.y) * k);
}
// Fixed point: E from its table (L_w of a point inside lies within [cos 1.4, cosh 1.4]), and L's
// coordinates clamped to +-4 (every point inside is within 1.4 of the centre) so that no
// product overflows.
inline void texcoord(const Frame<fixed>& f, const geo::Vec3<fixed>& L, int64_t& s8, int64_t& t8) {
    const int32_t lw = std::clamp<int32_t>(L.w.raw(), 0, (fx::tables::kEquiRange << 16) - 1);
    const int64_t E = fx::equidistant_ratio_q30(static_cast<uint32_t>(lw));        // Q30
    const int64_t G = (E * int64_t{f.k.raw()}) >> 30;                               // Q16 texels per unit
    const int64_t lx = std::clamp<int64_t>(L.x.raw(), -(4 << 16), 4 << 16), ly = std::clamp<int64_t>(L.y.raw(), -(4 << 16), 4 << 16);
    s8 = f.s0_8 + ((lx * G) >> 24);
    t8 = f.t0_8 + ((-ly * G) >> 24);
}


// The fixed engine's equidistant view, per pixel in integers: X, Y in Q24 from the pixel's
// 1/256 px offset and the reciprocal of the scale (no division per pixel), u = K (X^2 + Y^2),
// Sf(u) and Cf(u) from their tables (Q28, Q27), the 3-vector (Cf, Sf X, Sf Y) in Q24 and the
// motion's nine products to L in Q16.16. At K = 0 every Sf and Cf is 1 and no table is read.
// Its domain: |X|, |Y| <= 8 (and X^2 + Y^2 <= 64), where no body reaches (every point of a
// world is within 2 pi of O) and every product fits in 64 bits: |Sf| <= 186 (u >= -64) in Q28,
// times |X| < 2^27, below 2^63; the motion's entries below 2^20 (cosh pi < 12) times the
// 3-vector's below 2^35.
struct FastMap {
    int64_t cx8 = 0, cy8 = 0;  // the screen centre, 1/256 px
    int64_t inv = 0;           // world units per 1/256 px, Q40: X in Q24 is (dx8 inv) >> 16
    int64_t K = 0;             // Q16
    int64_t m[3][3] = {};      // to_local, Q16
    bool flat = true;          // K = 0
    int64_t Y = 0, Y2 = 0;     // the row's Y (Q24) and Y^2 (Q48)
    bool row_ok = false;
    static constexpr int64_t kLimit = int64_t{8} << 24;
    static bool make(const Frame<fixed>& f, FastMap& out) {
        const int64_t scale = f.m.scale.raw();
        if (f.proj != geo::Projection::azimuthal_equidistant || scale < (int64_t{1} << 16)) return false;
        out.cx8 = f.m.cx.raw() >> 8, out.cy8 = f.m.cy.raw() >> 8;
        out.inv = ((int64_t{1} << 48) + scale / 2) / scale;
        out.K = f.K.raw(), out.flat = out.K == 0;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) out.m[r][c] = f.to_local.m[r][c].raw();
        return true;
    }
    void row(int y) {
        Y = ((cy8 - (int64_t{y} * kSub + kSub / 2)) * inv) >> 16;
        row_ok = Y <= kLimit && Y >= -kLimit;
        Y2 = Y * Y;
    }
    [[gnu::always_inline]] bool local(int x, geo::Vec3<fixed>& L) const {
        const int64_t X = ((int64_t{x} * kSub + kSub / 2 - cx8) * inv) >> 16;
        if (!row_ok || X > kLimit || X < -kLimit) return false;
        const int64_t rho2 = X * X + Y2;  // Q48
        if (rho2 > (int64_t{64} << 48)) return false;
        int64_t pw = int64_t{1} << 24, px = X, py = Y;
        if (!flat) {
            const int64_t u = ((rho2 >> 16) * K) >> 32;  // Q16
            if (K > 0 && u >= 646815) return false;       // pi^2 in Q16: the antipode's circle and past it
            int64_t sf, cf;
            using namespace fx::tables;
            if (u >= -(kSfCfRange << 16) && u <= (kSfCfRange << 16)) {
                sf = fx::detail::lerp_table_raw<kSfStepBits>(sf_q28.data(), static_cast<int32_t>(u), -(kSfCfRange << 16));
                cf = fx::detail::lerp_table_raw<kCfStepBits>(cf_q27.data(), static_cast<int32_t>(u), -(kSfCfRange << 16));
            } else {
                const fixed uf = fixed::from_raw(static_cast<int32_t>(u));
                sf = int64_t{fx::Sf(uf).raw()} << 12, cf = int64_t{fx::Cf(uf).raw()} << 11;
            }
            pw = cf >> 3, px = (sf * X) >> 28, py = (sf * Y) >> 28;
        }
        auto row = [&](const int64_t* r) {
            return fixed::from_raw(fx::detail::saturate32((r[0] * pw + r[1] * px + r[2] * py) >> 24));
        };
        L = {row(m[0]), row(m[1]), row(m[2])};
        return true;
    }
};

// How a row's pixels reach the body's frame: row(f, y, g) calls g(local) once, with local(x, L)
// the pixel's local 3-vector (false where none), chosen once a row. In general local_at; the
// fixed engine's equidistant view, FastMap (set each frame by make).
template <class T>
struct PixelMap {
    void make(const Frame<T>&) {}
    template <class G>
    decltype(auto) row(const Frame<T>& f, int y, G&& g) const {
        return g([&f, y](int x, geo::Vec3<T>& L) { return local_at(f, x, y, L); });
    }
};
template <>
struct PixelMap<fixed> {
    FastMap fast;
    bool use_fast = false;
    void make(const Frame<fixed>& f) { use_fast = FastMap::make(f, fast); }
    template <class G>
    decltype(auto) row(const Frame<fixed>& f, int y, G&& g) const {
        if (!use_fast) return g([&f, y](int x, geo::Vec3<fixed>& L) { return local_at(f, x, y, L); });
        FastMap map = fast;
        map.row(y);
        return g([&map](int x, geo::Vec3<fixed>& L) { return map.local(x, L); });
    }
};

// One body's fill: its outline in its frame, the frame, how it is painted, and its FillJob with
// the polyline (render/fill.hpp sets them).
template <class T>
struct Body {
    std::size_t index = 0;                   // in World::bodies
    std::vector<geo::Vec3<T>> local, world;  // the vertices' 3-vectors
    std::vector<SubPoint> points;            // the polyline's room
    std::size_t per_edge = 2;                // the most segments an edge's polyline may have
    LocalOutline<T> outline;
    std::vector<geo::Polar<T>> verts;  // an engine's outline's scratch (render/fill.hpp)
    bool by_polyline = false;          // pixels tested against the job's polyline (else the outline)
    Frame<T> frame;
    PixelMap<T> pixels;
    TexelMap texels;  // (texels.tex null: one colour)
    FillJob job;
};

// Pixels [x0, x1) of row y: the local 3-vectors of each in turn.
template <class T, class F>
[[gnu::always_inline]] inline void for_pixels(const Body<T>& b, int y, int x0, int x1, F&& f) {
    b.pixels.row(b.frame, y, [&](auto&& local) {
        for (int x = x0; x < x1; ++x) {
            geo::Vec3<T> L;
            f(x, local(x, L), L);
        }
    });
}

// n pixels from x of a textured run, the i-th at texture coordinates (s + i ds, t + i dt) in
// 1/65536 texel, each stored by store(x, word). The nearest texel of a piece that stays within
// the image (as a body's pieces do, unless its texture repeats) is one load.
template <class Store>
[[gnu::always_inline]] inline void texture_piece(const TexelMap& tm, int x, int n, int64_t s, int64_t t, int64_t ds, int64_t dt,
                                                 Store&& store) {
    const PackedTexture& p = *tm.tex;
    const int64_t se = s + ds * (n - 1), te = t + dt * (n - 1);
    if (!tm.bilinear && std::min(s, se) >= 0 && std::max(s, se) < (int64_t{p.width} << 16) && std::min(t, te) >= 0 &&
        std::max(t, te) < (int64_t{p.height} << 16)) {
        const uint32_t* words = p.words.data();
        const int64_t width = p.width;
        for (int i = 0; i < n; ++i, s += ds, t += dt) store(x + i, words[(t >> 16) * width + (s >> 16)]);
        return;
    }
    for (int i = 0; i < n; ++i, s += ds, t += dt) store(x + i, tm.word(s >> 8, t >> 8));
}

// FillJob::span: a run of pixels inside, textured: its texture coordinates sampled exactly and
// interpolated between (render/fill_span.hpp), each texel stored in the canvas's own format.
template <class T>
void span(const void* body, const Canvas& c, int y, int x0, int x1) {
    const Body<T>& b = *static_cast<const Body<T>*>(body);
    auto paint = [&](auto&& exact) {
        uint8_t* row = c.row(y);
        const TexelMap& tm = b.texels;
        switch (c.format().bits_per_pixel) {
            case 16:
                return sampled_span(x0, x1, exact, [&](int x, int n, int64_t s, int64_t t, int64_t ds, int64_t dt) {
                    texture_piece(tm, x, n, s, t, ds, dt, [&](int px, uint32_t w) {
                        const uint16_t h = static_cast<uint16_t>(w);
                        std::memcpy(row + 2 * px, &h, 2);
                    });
                });
            case 32:
                return sampled_span(x0, x1, exact, [&](int x, int n, int64_t s, int64_t t, int64_t ds, int64_t dt) {
                    texture_piece(tm, x, n, s, t, ds, dt, [&](int px, uint32_t w) { std::memcpy(row + 4 * px, &w, 4); });
                });
            default:
                return sampled_span(x0, x1, exact, [&](int x, int n, int64_t s, int64_t t, int64_t ds, int64_t dt) {
                    texture_piece(tm, x, n, s, t, ds, dt, [&](int px, uint32_t w) { c.set_word(px, y, w); });
                });
        }
    };
    b.pixels.row(b.frame, y, [&](auto&& local) {
        paint([&](int x, Texcoord& t) {
            geo::Vec3<T> L;
            if (!local(x, L)) return false;
            texcoord(b.frame, L, t.s, t.t);
            return true;
        });
    });
}
// Whether pixel (x, y)'s centre is inside the job's closed polyline (even-odd), for a body
// filled inside its engine's outline (Body::by_polyline).
inline bool inside_polyline(const FillJob& j, int x, int y) {
    const int64_t px = int64_t{x} * kSub + kSub / 2, py = int64_t{y} * kSub + kSub / 2;
    bool in = false;
    for (std::size_t i = 0, k = j.count - 1; i < j.count; k = i++) {
        const SubPoint a = j.points[i], b = j.points[k];
        if ((a.y > py) == (b.y > py)) continue;
        // x of the edge at py, compared without division: (px - a.x)(b.y - a.y) < (b.x - a.x)(py - a.y)
        const int64_t lhs = (px - a.x) * (int64_t{b.y} - a.y), rhs = (int64_t{b.x} - a.x) * (py - a.y);
        if ((b.y > a.y) ? lhs < rhs : lhs > rhs) in = !in;
    }
    return in;
}

// FillJob::test: each pixel tested, then painted (anti-aliased: with its coverage).
template <class T>
void test(const void* body, const Canvas& c, int y, int x0, int x1, const RowCover* cover) {
    const Body<T>& b = *static_cast<const Body<T>*>(body);
    const PixelWriter out{c};
    for_pixels(b, y, x0, x1, [&](int x, bool ok, const geo::Vec3<T>& L) {
        const bool in = b.by_polyline ? inside_polyline(b.job, x, y) : ok && b.outline.inside(L, b.frame.hemisphere);
        const int alpha = cover ? fill_coverage(*cover, x, in) : in ? 255 : 0;
        if (alpha <= 0 || (!ok && !b.job.solid)) return;
        uint32_t w = b.job.word;
        if (!b.job.solid) {
            int64_t s8, t8;
            texcoord(b.frame, L, s8, t8);
            w = b.texels.word(s8, t8);
        }
        out.blend(x, y, w, alpha);
    });
}

}  // namespace noneuclid::render::fill
