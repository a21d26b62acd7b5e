// Filled and textured bodies (a body's fill or texture, world::SceneBody), drawn before their
// outlines, in every engine and projection. Per body and frame, plan() (the geometry, on any
// thread, for the bodies it owns) builds the body's FillJob:
//  - its vertices' 3-vectors, local and moved (geo::body_motion), the outline in its own frame
//    (fill::LocalOutline) and the way back from a pixel (geo::body_motion_inverse);
//  - a polyline that follows each projected geodesic edge: each edge halved in the 3-vector
//    model (the midpoint of p and q is (p + q) / |p + q|, exact for every K) and each half
//    halved again while its projected midpoint lies more than kSag from its chord's middle, or
//    the chord is over kChord long (and at least once). A half whose midpoint is d from the
//    middle of its chord is followed by its two chords within about d / 4, for a projected
//    geodesic's curvature changes little along it; the zone (fill_rows.hpp) is twice that, the
//    largest over the body, plus kSlack for the rounding of points and pixels;
//  - on the sphere, whether the body holds the antipode of O: its picture in the equidistant
//    view then reaches the antipode's circle, which becomes a second boundary (the rim); other
//    projections, and any point a projection cannot show, test every pixel (brute).
// fill_rows (render/fill_rows.cpp) draws the job's rows: on one thread after plan(), or band
// by band on the threads of render/parallel_frame.hpp. docs/rendering.md has the whole story.
//
// Memory: a FillScratch sized once for the world (prepare) holds every buffer; a frame
// allocates nothing.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/geometry.hpp"
#include "geometry/local_frame.hpp"
#include "render/draw_options.hpp"
#include "render/fill_pixels.hpp"
#include "render/fill_rows.hpp"
#include "render/screen_points.hpp"
#include "render/texture.hpp"
#include "world/world.hpp"

namespace noneuclid::render {

namespace fill {
inline constexpr int64_t kSag = kSub / 2;      // a half is halved while its midpoint is farther (1/2 px)
inline constexpr int64_t kChord = 32 * kSub;   // or its chord is longer (32 px)
inline constexpr int64_t kSlack = kSub * 3 / 20;  // added to the zone (0.15 px)
inline constexpr int kMaxDepth = 12;
// The most points an edge's polyline may have: fewer for bodies of many vertices (at least the
// midpoint), so that a body's polyline stays within about 4096 points.
inline std::size_t edge_budget(std::size_t vertices) {
    return std::clamp<std::size_t>(4096 / std::max<std::size_t>(vertices, 1), 4, 128);
}
// Whether the body is filled or textured.
template <class B>
bool filled(const B& b) {
    return b.desc->closed && b.local.size() >= 3 && (b.desc->filled || b.desc->texture);
}
}  // namespace fill

template <class T>
struct FillScratch {
    std::vector<int32_t> slot;  // world.bodies[i]'s fill is bodies[slot[i]] (-1: none)
    std::vector<fill::Body<T>> bodies;
    std::vector<std::unique_ptr<PackedTexture>> textures;  // one per image
    std::vector<RowWork> work;                             // one per thread
    PixelFormat format{};                                  // the canvas's, set by begin_frame

    // Sized for this world and `threads` threads (allocates).
    template <class W>
    void prepare(const W& world, int threads) {
        slot.assign(world.bodies.size(), -1);
        bodies.clear(), textures.clear();
        std::size_t longest = 0;
        for (std::size_t i = 0; i < world.bodies.size(); ++i) {
            const auto& b = world.bodies[i];
            if (!fill::filled(b)) continue;
            slot[i] = static_cast<int32_t>(bodies.size());
            fill::Body<T>& f = bodies.emplace_back();
            const std::size_t n = b.local.size();
            f.index = i, f.per_edge = fill::edge_budget(n);
            f.local.assign(n, {}), f.world.assign(n, {}), f.outline.make(n);
            f.points.assign(std::max(n * f.per_edge, points_of<typename W::engine>(b)) + 1, {});
            if constexpr (W::engine::kFillsItsOutline) f.verts.assign(n, {});
            longest = std::max(longest, f.points.size());
            if (const world::Image* im = b.desc->texture.get()) f.texels = {texture_for(*im), b.desc->texture_bilinear};
        }
        work.assign(static_cast<std::size_t>(std::max(threads, 1)), {});
        for (RowWork& w : work) w.reserve(longest);
    }
    // Before a frame's plans: the textures packed for the canvas (only when its format changed).
    void begin_frame(const Canvas& c) {
        format = c.format();
        for (auto& t : textures) t->pack_for(format);
    }
    // World.bodies[i]'s fill for this frame, or null if it has none (geometry: writes only its
    // own Body, so bodies can be planned on different threads at once).
    template <class W>
    const FillJob* plan(const W& world, std::size_t i, const ScreenMap<T>& m, const DrawOptions& o, int width,
                        int height) {
        if (i >= slot.size() || slot[i] < 0) return nullptr;
        fill::Body<T>& f = bodies[static_cast<std::size_t>(slot[i])];
        const auto& b = world.bodies[i];
        f.job.on = false;
        if (b.local.size() != f.local.size()) return nullptr;
        set_frame(world, b, m, o, f);
        using E = typename W::engine;
        if constexpr (E::kFillsItsOutline) engine_polyline<E>(world, b, f, m, o, width, height);
        else outline_polyline(f, m, width, height);
        return f.job.on ? &f.job : nullptr;
    }

private:
    // The most points an engine that fills its outline gives a body's outline (else none).
    template <class E, class B>
    static std::size_t points_of(const B& b) {
        if constexpr (E::kFillsItsOutline) return E::chords(b) + 1;
        else return 0;
    }

    // An engine that fills its outline (geometry/engine.hpp): the polyline is the engine's
    // outline itself, each pixel near it tested against that polyline (fill::Body::by_polyline),
    // so fill and outline are one shape. A point the projection cannot show, or a body holding
    // the antipode (whose picture the polyline does not bound), is tested pixel by pixel
    // against the geodesic polygon instead (brute).
    template <class E, class W>
    void engine_polyline(const W& world, const world::Body<T>& b, fill::Body<T>& f, const ScreenMap<T>& m,
                         const DrawOptions& o, int width, int height) {
        struct Collect {
            SubPoint* out;
            std::size_t room, n = 0;
            bool ok = true;
            void add(const geo::Spot& s) {
                if (!s.shown || n == room) ok = false;
                else out[n++] = s.at;
            }
            void start(const geo::Spot& s) { add(s); }
            void chord(const geo::Spot&, const geo::Spot& s) { add(s); }
            void end() {}
            bool stays_outside(SubPoint, SubPoint, SubPoint) const { return false; }
        } sink{f.points.data(), f.points.size()};
        typename E::Cache cache;
        E::outline(world.K, b, cache, m, o.projection, f.verts.data(), f.world.data(), sink);
        FillJob& j = f.job;
        const bool antipode = f.frame.K > T(0) && f.outline.inside(antipode_local(f.frame), true);
        if (!sink.ok || sink.n < 4 || antipode) return brute(f, width, height);
        j.points = f.points.data(), j.count = sink.n;
        j.zone = static_cast<int32_t>(fill::kSlack);
        if (j.aa) j.zone = std::max(j.zone, kSub / 2 + j.zone);
        f.by_polyline = true;
        rows_of(f, sink.n, width, height);
    }
    // The antipode (-1, 0, 0) in the body's frame: -(the first column of to_local).
    static geo::Vec3<T> antipode_local(const fill::Frame<T>& fr) {
        return {-fr.to_local.m[0][0], -fr.to_local.m[1][0], -fr.to_local.m[2][0]};
    }
    // The job's rows: those of its polyline's points, widened by its zone.
    // (lo and hi: rows the polyline's points must widen, 1/256 px: the rim's.)
    static void rows_of(fill::Body<T>& f, std::size_t count, int width, int height, int64_t lo = INT64_MAX,
                        int64_t hi = INT64_MIN) {
        FillJob& j = f.job;
        for (std::size_t k = 0; k < count; ++k) lo = std::min<int64_t>(lo, f.points[k].y), hi = std::max<int64_t>(hi, f.points[k].y);
        j.top = static_cast<int>(std::clamp<int64_t>((lo - j.zone - kSub / 2 + kSub - 1) >> kSubBits, 0, height));
        j.bottom = static_cast<int>(std::clamp<int64_t>(((hi + j.zone - kSub / 2) >> kSubBits) + 1, 0, height));
        j.left = 0, j.right = width;
        j.on = j.top < j.bottom;
    }

    PackedTexture* texture_for(const world::Image& im) {
        for (auto& t : textures)
            if (t->image == &im) return t.get();
        textures.push_back(std::make_unique<PackedTexture>());
        textures.back()->make(im);
        return textures.back().get();
    }

    // The body's vertices, its frame and how it is painted.
    template <class W>
    void set_frame(const W& world, const world::Body<T>& b, const ScreenMap<T>& m, const DrawOptions& o,
                   fill::Body<T>& f) {
        const T K = world.K;
        const std::size_t n = f.local.size();
        const geo::Motion<T> motion = geo::body_motion(K, b.centre, b.facing);
        T rho{};
        for (std::size_t v = 0; v < n; ++v) {
            f.local[v] = geo::to_vec(K, b.local[v]);
            f.world[v] = motion(f.local[v]);
            rho = std::max(rho, b.local[v].r);
        }
        f.outline.set(f.local.data(), n);
        fill::Frame<T>& fr = f.frame;
        fr.K = K, fr.proj = o.projection, fr.m = m, fr.hemisphere = K > T(0);
        fr.to_local = geo::body_motion_inverse(K, b.centre, b.facing);
        f.job = FillJob{};
        f.by_polyline = false;
        f.job.clip_cx = m.ox, f.job.clip_cy = m.oy, f.job.clip_r = m.clip;
        f.job.aa = o.antialias;
        f.job.solid = f.texels.tex == nullptr;
        f.job.word = format.pack({b.desc->fill.r, b.desc->fill.g, b.desc->fill.b});
        if (!f.job.solid) {  // the image's width spans texture_scale diameters of the body
            const PackedTexture& t = *f.texels.tex;
            const double across = b.desc->texture_scale * 2 * std::max(static_cast<double>(rho), 1e-3);
            fr.k = T(std::min(t.width / across, 16384.0));
            fr.s0_8 = int64_t{t.width} * kSub / 2, fr.t0_8 = int64_t{t.height} * kSub / 2;
        }
        f.pixels.make(fr);
        f.job.body = &f;
        f.job.span = &fill::span<T>;
        f.job.test = &fill::test<T>;
    }

    // A screen point of the projection of v, or false where the projection cannot show it.
    static bool screen(const fill::Frame<T>& fr, const geo::Vec3<T>& v, SubPoint& out) {
        const geo::ProjectedPoint<T> p = geo::project_vec(fr.K, v, fr.proj);
        if (!p.visible) return false;
        out = to_pixels(geo::ScreenPoint<T>{fr.m.cx + fr.m.scale * p.X, fr.m.cy - fr.m.scale * p.Y});
        return true;
    }
    // The midpoint of the geodesic from p to q: (p + q) / sqrt<p + q, p + q>, for every K.
    static geo::Vec3<T> midpoint(T K, const geo::Vec3<T>& p, const geo::Vec3<T>& q) {
        using std::sqrt, geo::dot2, geo::quotient;  // and fx:: ones by ADL for fixed
        const geo::Vec3<T> s{p.w + q.w, p.x + q.x, p.y + q.y};
        const T norm = sqrt(dot2(s.w, s.w, K, dot2(s.x, s.x, s.y, s.y)));
        if (!(norm > T(0))) return p;
        return {quotient(s.w, norm), quotient(s.x, norm), quotient(s.y, norm)};
    }

    // The polyline, the zone, the rim, the rows: the job.
    void outline_polyline(fill::Body<T>& f, const ScreenMap<T>& m, int width, int height) {
        const std::size_t n = f.local.size();
        const fill::Frame<T>& fr = f.frame;
        FillJob& j = f.job;
        std::size_t at = 0;
        int64_t worst = 0;   // the largest midpoint offset^2 of a final half, (1/256 px)^2
        int64_t forced = 0;  // the same of a half that had no room to be halved again
        bool shown = screen(fr, f.world[0], f.points[at++]);
        struct Half {
            geo::Vec3<T> p, q;
            SubPoint sp, sq;
            int depth;
        };
        Half stack[fill::kMaxDepth + 2];
        for (std::size_t e = 0; e < n && shown; ++e) {
            const std::size_t budget = at + f.per_edge;  // this edge's points end before it
            Half h{f.world[e], f.world[e + 1 == n ? 0 : e + 1], f.points[at - 1], {}, 0};
            shown = screen(fr, h.q, h.sq);
            int top = 0;
            stack[top++] = h;
            while (top > 0 && shown) {
                const Half c = stack[--top];
                const geo::Vec3<T> mid = midpoint(fr.K, c.p, c.q);
                SubPoint sm;
                if (!(shown = screen(fr, mid, sm))) break;
                auto clamp = [](int64_t v) { return std::clamp<int64_t>(v, -(int64_t{1} << 28), int64_t{1} << 28); };
                const int64_t ox = clamp(2 * int64_t{sm.x} - c.sp.x - c.sq.x), oy = clamp(2 * int64_t{sm.y} - c.sp.y - c.sq.y);
                const int64_t cx = clamp(int64_t{c.sq.x} - c.sp.x), cy = clamp(int64_t{c.sq.y} - c.sp.y);
                const int64_t off2 = (ox * ox + oy * oy) / 4;  // (midpoint - chord's middle)^2
                const bool split = c.depth < 1 || off2 > fill::kSag * fill::kSag || cx * cx + cy * cy > fill::kChord * fill::kChord;
                // Room for this half as two, and for every half still waiting, each as one.
                if (split && c.depth < fill::kMaxDepth && at + 4 + 2 * static_cast<std::size_t>(top) <= budget) {
                    stack[top++] = {mid, c.q, sm, c.sq, c.depth + 1};
                    stack[top++] = {c.p, mid, c.sp, sm, c.depth + 1};
                    continue;
                }
                f.points[at++] = sm, f.points[at++] = c.sq;
                worst = std::max(worst, off2);
                if (split) forced = std::max(forced, off2 + cx * cx + cy * cy);
            }
        }
        if (!shown) return brute(f, width, height);
        j.points = f.points.data(), j.count = at;
        // A final half's chords are within about a quarter of its midpoint's offset: twice that.
        // A half left long or bent (no room, or too deep) may be anywhere within its chord's
        // length and its offset of its ends.
        auto root = [](int64_t v) { return static_cast<int64_t>(fx::detail::isqrt64(static_cast<uint64_t>(v))); };
        j.zone = static_cast<int32_t>(std::min<int64_t>(std::max(root(worst) / 2, root(forced)) + fill::kSlack, int64_t{1} << 28));
        if (j.aa) j.zone = std::max(j.zone, kSub / 2 + j.zone);
        int64_t lo = INT64_MAX, hi = INT64_MIN;  // (the rim's rows, if it has one)
        if (fr.K > T(0)) {
            if (f.outline.inside(antipode_local(fr), true)) {
                if (fr.proj != geo::Projection::azimuthal_equidistant) return brute(f, width, height);
                using std::sqrt;
                const T r = geo::pi_v<T> / sqrt(fr.K) * m.scale;  // px
                const SubPoint c = to_pixels(geo::ScreenPoint<T>{m.cx, m.cy}), e = to_pixels(geo::ScreenPoint<T>{m.cx + r, m.cy});
                j.rim = true, j.rim_cx = c.x, j.rim_cy = c.y, j.rim_r = int64_t{e.x} - c.x;
                lo = j.rim_cy - j.rim_r, hi = j.rim_cy + j.rim_r;
            }
        }
        rows_of(f, at, width, height, lo, hi);
    }
    // Every pixel of the canvas tested: a body the polyline cannot follow.
    static void brute(fill::Body<T>& f, int width, int height) {
        FillJob& j = f.job;
        j.brute = true, j.aa = false;
        j.top = 0, j.bottom = height, j.left = 0, j.right = width;
        j.on = width > 0 && height > 0;
    }
};

}  // namespace noneuclid::render
