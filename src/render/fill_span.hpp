// A textured run of pixels inside a body, at a fraction of the per-pixel cost: the texture
// coordinates are taken exactly (the pixel's way back to the body's frame, fill_pixels.hpp) at
// pixels at most kSpanStep apart, and linearly interpolated between them. Each piece is checked
// at its middle pixel, where a smooth map's departure from its chord is largest: if the exact
// coordinates there are more than kSpanError from the interpolated ones, the piece is halved,
// down to single pixels. So a flat map (K = 0, a body near O) costs two exact pixels per
// kSpanStep, and a map bent hard (toward the sphere's antipode, toward the limit circle) is
// followed as closely as it needs. docs/rendering.md ("Filled and textured bodies") has why.
#pragma once

#include <cstdint>

namespace noneuclid::render::fill {

inline constexpr int kSpanStep = 32;           // pixels between exact samples, at most
inline constexpr int64_t kSpanError = 256 / 2;  // 1/256 texel: half a texel

// Texture coordinates of a pixel, 1/256 texel.
struct Texcoord {
    int64_t s = 0, t = 0;
};

// Pixels [x0, x1) of one row: exact(x, tc) sets pixel x's coordinates (false where the
// projection shows no point there); paint(x, n, s, t, ds, dt) paints pixels x .. x + n - 1, the
// i-th at (s + i ds, t + i dt) in 1/65536 texel. Pixels whose piece holds a point the
// projection cannot show are each taken exactly (painted only where exact succeeds).
template <class Exact, class Paint>
void sampled_span(int x0, int x1, Exact&& exact, Paint&& paint) {
    if (x0 >= x1) return;
    auto one = [&](int x, Texcoord c) { paint(x, 1, c.s * 256 + 128, c.t * 256 + 128, int64_t{0}, int64_t{0}); };
    Texcoord a;
    bool a_ok = exact(x0, a);
    int xa = x0;
    while (xa < x1 - 1) {
        int xb = xa + kSpanStep < x1 - 1 ? xa + kSpanStep : x1 - 1;
        Texcoord b;
        bool b_ok = exact(xb, b);
        while (a_ok && b_ok && xb - xa > 1) {  // halve the piece until its middle is on the chord
            const int n = xb - xa, xm = xa + n / 2;
            Texcoord m;
            if (!exact(xm, m)) {
                xb = xm, b_ok = false;
                break;
            }
            const int64_t es = m.s - (a.s + (b.s - a.s) * (xm - xa) / n), et = m.t - (a.t + (b.t - a.t) * (xm - xa) / n);
            if (es <= kSpanError && es >= -kSpanError && et <= kSpanError && et >= -kSpanError) break;
            xb = xm, b = m;
        }
        const int n = xb - xa;
        if (a_ok && b_ok) {  // pixels [xa, xb) on the chord from a to b
            paint(xa, n, a.s * 256 + 128, a.t * 256 + 128, ((b.s - a.s) * 256) / n, ((b.t - a.t) * 256) / n);
        } else {  // a point not shown in the piece: each pixel on its own
            for (int x = xa; x < xb; ++x) {
                Texcoord c;
                if (exact(x, c)) one(x, c);
            }
        }
        xa = xb, a = b, a_ok = b_ok;
    }
    if (a_ok) one(xa, a);  // the run's last pixel, exact
}

}  // namespace noneuclid::render::fill
