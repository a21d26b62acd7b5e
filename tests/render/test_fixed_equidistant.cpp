// The fixed engine's equidistant kernel (render/fixed_points.hpp) and the motion it starts
// from: geo::MotionApply<fixed> bit for bit M(L); one FixedEquidistant point against double;
// the points the adaptive tessellation takes, in every engine, against the reference geodesic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "curve_reference.hpp"
#include "record.hpp"
#include "render/draw_world.hpp"
#include "test_common.hpp"


namespace {

using namespace noneuclid;
using fx::fixed;
using test::kPi;

// geo::MotionApply<fixed> is M(L) (dot3 per row), bit for bit: on its fast path (entries below
// 2^14, coordinates anything up to saturated values, sums that saturate) and through its
// fallback (larger entries), one vertex at a time and in batches (where the first row is
// (1, 0, 0), as in the plane, w is copied).
TEST(FastPaths, MotionApplyIsTheMotionBitForBit) {
    std::mt19937 rng(21);
    auto value = [&](int bits) {  // |raw| below 2^bits, sometimes exactly at a limit
        const uint32_t r = rng();
        if (r % 17 == 0) return fixed::from_raw(r % 2 ? INT32_MAX : INT32_MIN);
        if (r % 13 == 0) return fixed::from_raw((r % 2 ? 1 : -1) * ((int32_t{1} << 30) - static_cast<int32_t>(r % 2)));
        const int32_t m = static_cast<int32_t>(rng() >> (32 - bits));
        return fixed::from_raw(rng() % 2 ? m : -m);
    };
    long fast = 0, total = 0, clamped = 0, batch_redone = 0, plane_rows = 0;
    for (int i = 0; i < 20000; ++i) {
        geo::Motion<fixed> M;
        const int bits = 17 + i % 15;  // up to 2^31
        if (i % 3 == 0) {  // a body's motion, as the draw makes it; every third in the plane (first row (1, 0, 0))
            const double K = i % 9 == 0 ? 0.0 : -1 + 2 * (rng() % 1000) / 999.0;
            M = geo::body_motion(fixed(K), geo::Polar<fixed>{fixed((rng() % 4000) / 1000.0), fixed((rng() % 6283) / 1000.0)},
                                 fixed((rng() % 6283) / 1000.0));
        } else {
            for (auto& row : M.m)
                for (fixed& v : row) v = value(bits);
        }
        const geo::MotionApply<fixed> apply(M);
        // The batch form too (what the draw calls), over vertices of which none, or some,
        // saturate (its loop done again, saturating): usually small ones, as a body's are.
        const int count = 1 + i % 12;
        geo::Vec3<fixed> L[12], batch[12];
        const bool some_large = i % 4 == 0;
        for (int j = 0; j < count; ++j) {
            const int b = some_large && j == count / 2 ? bits : 17;
            L[j] = {value(b), value(b), value(b)};
        }
        apply(L, batch, static_cast<std::size_t>(count));
        plane_rows += apply.small && M.m[0][0] == fixed(1) && M.m[0][1].raw() == 0 && M.m[0][2].raw() == 0;
        for (int j = 0; j < count; ++j) {
            const geo::Vec3<fixed> got = apply(L[j]), want = M(L[j]);
            ASSERT_EQ(got.w.raw(), want.w.raw()) << i << " " << j;
            ASSERT_EQ(got.x.raw(), want.x.raw()) << i << " " << j;
            ASSERT_EQ(got.y.raw(), want.y.raw()) << i << " " << j;
            ASSERT_EQ(batch[j].w.raw(), want.w.raw()) << i << " " << j;
            ASSERT_EQ(batch[j].x.raw(), want.x.raw()) << i << " " << j;
            ASSERT_EQ(batch[j].y.raw(), want.y.raw()) << i << " " << j;
            fast += apply.small;
            bool sat = false;
            for (const fixed v : {got.w, got.x, got.y}) sat = sat || v.raw() == INT32_MAX || v.raw() == INT32_MIN;
            clamped += apply.small && sat;
            batch_redone += apply.small && sat && count > 1;
            ++total;
        }
    }
    EXPECT_GT(fast, total / 10);  // both paths were taken
    EXPECT_LT(fast, total - total / 10);
    EXPECT_GT(clamped, 100);       // and the fast path saturated
    EXPECT_GT(batch_redone, 100);  // in a batch of several (the batch's second loop)
    EXPECT_GT(plane_rows, 1000);   // and the batch's loop that copies w
}

// geo::FixedEquidistant, one point: the 3-vector (C_K(r), S_K(r) cos t, S_K(r) sin t)
// rounded to Q16.16 lands within 0.012 px of centre + scale r (cos t, -sin t) computed in double
// (measured: 0.0106 px; the floor to 1/256 px alone is up to 0.0055 px), for curvatures from
// the sphere (past its equator too) to the hyperbolic plane and two screens; points outside
// its domain (w < -1/2, w >= 32, |x| or |y| > 100, or > 16 past the equator) are left to the
// general path.
TEST(FastPaths, FixedEquidistantPointAgainstDouble) {
    std::mt19937 rng(5);
    for (const double K : {-1.0, -0.6, -0.05, 0.0, 0.3, 1.0})
        for (const auto& size : {std::pair{800, 480}, std::pair{1920, 1080}}) {
            const double R = K > 0 ? kPi / std::sqrt(K) : 3.2;
            const auto m = render::ScreenMap<fixed>::of(size.first, size.second, fixed(K), fixed(R), geo::Projection::azimuthal_equidistant);
            geo::FixedEquidistant fe;
            ASSERT_TRUE(geo::FixedEquidistant::make(m, fe));
            const double cx = static_cast<double>(m.cx), cy = static_cast<double>(m.cy), scale = static_cast<double>(m.scale);
            double worst = 0, flat_worst = 0;
            long shown = 0, left = 0, south_points = 0, flat = 0;
            for (int i = 0; i < 100000; ++i) {
                const double r = (rng() % 100000) / 100000.0 * (K == 0 ? 5.0 : (K > 0 ? 2.7 : 5.0) / std::sqrt(std::fabs(K))),
                             t = (rng() % 62832) / 10000.0;
                const double S = geo::S_K(K, r), C = geo::C_K(K, r);
                auto q16 = [](double v) { return static_cast<int64_t>(std::llround(v * 65536)); };
                const int64_t w = q16(C), x = q16(S * std::cos(t)), y = q16(S * std::sin(t));
                render::SubPoint p;
                const bool north = w >= 0 && w < (int64_t{32} << 16) && std::llabs(x) <= (int64_t{100} << 16) &&
                                   std::llabs(y) <= (int64_t{100} << 16);
                const bool south = w >= -(int64_t{1} << 15) && w < 0 && std::llabs(x) <= (int64_t{16} << 16) &&
                                   std::llabs(y) <= (int64_t{16} << 16);
                const bool in = north || south;
                south_points += south;
                ASSERT_EQ(fe.point(w, x, y, p), in) << K << " r " << r;
                if (!in) {
                    ++left;
                    continue;
                }
                ++shown;
                worst = std::max(worst, std::hypot(p.x / 256.0 - (cx + scale * r * std::cos(t)), p.y / 256.0 - (cy - scale * r * std::sin(t))));
                if (K == 0) {  // the plane's own path (w not looked at, E = 1), within the same bound
                    render::SubPoint q;
                    ASSERT_TRUE(fe.point<true>(w, x, y, q)) << r;
                    flat_worst = std::max(flat_worst, std::hypot(q.x / 256.0 - (cx + scale * r * std::cos(t)),
                                                                 q.y / 256.0 - (cy - scale * r * std::sin(t))));
                    ++flat;
                }
            }
            ::noneuclid_test_record("K %5.2f %dx%d: worst %.4f px over %ld points (%ld past the equator; %ld left to the general "
                        "path)\n", K, size.first, size.second, worst, shown, south_points, left);
            if (K > 0) {
                EXPECT_GT(south_points, 10000) << K;
            }
            EXPECT_GT(shown, 50000);
            EXPECT_LE(worst, 0.012) << K;
            if (K != 0) {
                EXPECT_GT(left, 0) << K;  // the domain's edge was reached
            } else {
                ::noneuclid_test_record("K  0.00 %dx%d, the plane's path: worst %.4f px over %ld points\n", size.first, size.second,
                            flat_worst, flat);
                EXPECT_EQ(flat, shown);
                EXPECT_LE(flat_worst, 0.012);
                // Outside |x|, |y| <= 100 the plane's path refuses too.
                render::SubPoint q;
                EXPECT_FALSE(fe.point<true>(int64_t{1} << 16, int64_t{101} << 16, 0, q));
                EXPECT_FALSE(fe.point<true>(int64_t{1} << 16, 0, -(int64_t{101} << 16), q));
            }
        }
}

// The points the adaptive tessellation takes (render/edge_curve.hpp: each a slerp of its
// edge's ends with weights found by halving) against the reference geodesic (ref::along at the
// same fraction t), on the screen: every dyadic point of every edge to depth 5 (t = k/32), in
// the fixed engine's equidistant kernel (FixedEquidistantEval), its general evaluator, float and
// double, in every projection, in scenes whose edges leave the kernel's domain mid-edge (below
// w = -1/2 on the sphere), with K from -1 to 1. Points the reference shows within the clip
// circle are compared; where the two disagree on whether a point is shown or inside, both
// must be within 0.05 px of the clip circle or the horizon's image. Fixed point within 0.05 px
// more than 10 px inside the clip circle, and 0.3 px within it, where at K = 1 the antipode's
// neighbourhood turns its Q16.16 error into the bearing: the ends' rounding (2^-17 a
// coordinate) times the weights (up to 2 there) over the point's small S_K(r) (0.014 at 0.1 px
// inside an 800x480 clip circle) is 0.001 rad of bearing, 0.25 px; float within 0.05 px,
// double 0.01 px.
// A misplaced point is pixels away.
struct HalvingErr {
    double worst = 0, inner = 0;  // all points; those more than 10 px inside the clip circle
    long points = 0, disagree = 0;
};
template <class T, class Eval>
void halving_errors(const world::World<T>& w, const Eval& ev0, geo::Projection proj,
                    render::DrawScratch<T>& s, int width, int height, HalvingErr& out) {
    using Math = geo::SlerpMath<T>;
    const double K = static_cast<double>(w.K);
    const noneuclid::testing::ReferenceView view(K, static_cast<double>(w.R), proj, width, height);
    for (std::size_t bi = 0; bi < w.bodies.size(); ++bi) {
        const auto& b = w.bodies[bi];
        const geo::ShapeCache<T>& sh = s.shapes[bi].refresh(w.K, b);
        const geo::Motion<T> motion = geo::body_motion(w.K, b.centre, b.facing);
        const std::size_t n = b.local.size(), edges = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
        std::vector<geo::Vec3<T>> v(n);
        std::vector<geo::Polar<double>> rv(n);
        const geo::Polar<double> centre{static_cast<double>(b.centre.r), static_cast<double>(b.centre.theta)};
        for (std::size_t i = 0; i < n; ++i) {
            v[i] = geo::MotionApply<T>(motion)(sh.local[i]);
            rv[i] = geo::ref::vertex(K, centre, static_cast<double>(b.facing),
                                     {static_cast<double>(b.local[i].r), static_cast<double>(b.local[i].theta)});
        }
        for (std::size_t e = 0; e < edges; ++e) {
            if (sh.walked[e]) continue;
            const std::size_t f = (e + 1) % n;
            Eval ev = ev0;
            ev.ends(v[e], v[f]);
            // Every node of the halving tree to depth 5, each from its two neighbours' weights.
            constexpr int kDepth = 5, kN = 1 << kDepth;
            typename Math::W a[kN + 1], bw[kN + 1];
            a[0] = Math::one(), bw[0] = Math::zero(), a[kN] = Math::zero(), bw[kN] = Math::one();
            typename Math::U u = sh.u[e];
            for (int d = 0; d < kDepth; ++d) {
                const typename Math::W h = d == 0 ? sh.h[e] : Math::half(u = Math::quarter(u));
                const int step = kN >> d;
                for (int k = step / 2; k < kN; k += step) {
                    a[k] = Math::mid(a[k - step / 2], a[k + step / 2], h);
                    bw[k] = Math::mid(bw[k - step / 2], bw[k + step / 2], h);
                }
            }
            for (int k = 1; k < kN; ++k) {
                const render::Spot got = ev.point(a[k], bw[k]);
                const auto want = view.screen(geo::ref::along(K, rv[e], rv[f], double(k) / kN));
                const double gx = got.at.x / 256.0, gy = got.at.y / 256.0;
                if (got.in != want.inside || got.shown != want.visible) {
                    // Only on the clip circle or where the view's horizon cuts the edge.
                    const double off_clip = std::fabs(want.from_centre - view.clip());
                    const bool near = off_clip < 0.05 || !want.visible || !got.shown;
                    EXPECT_TRUE(near) << "edge " << e << " of " << b.desc->name << " t " << double(k) / kN << " K " << K << " " << geo::projection_name(proj) << " got " << got.shown << got.in << " want " << want.visible << want.inside << " from centre " << want.from_centre << " clip " << view.clip() << " got at " << gx << "," << gy << " want " << want.x << "," << want.y;
                    ++out.disagree;
                    continue;
                }
                if (!want.inside) continue;
                const double err = std::hypot(gx - want.x, gy - want.y);
                out.worst = std::max(out.worst, err);
                if (want.from_centre < view.clip() - 10) out.inner = std::max(out.inner, err);
                ++out.points;
            }
        }
    }
}

TEST(FastPaths, HalvingPointsAreOnTheGeodesic) {
    struct Case {
        const char* scene;
        double K;
    } cases[] = {{"stress", 1.0}, {"kiosk", 0.8}, {"stress", -1.0}, {"kiosk", -0.6}, {"kiosk", 0.0}, {"kiosk", 1.0}, {"fig17", 0.3}};
    const int W = 800, H = 480;
    HalvingErr kernel, general, single, twice;
    for (const Case& c : cases)
        for (geo::Projection proj : geo::kProjections) {
            world::Scene scene;
            ASSERT_TRUE(world::builtin_scene(c.scene, {40, 6, 5}, scene));
            scene.curvature = c.K;
            world::World<fixed> wf(scene);
            world::World<float> wl(scene);
            world::World<double> wd(scene);
            render::DrawScratch<fixed> sf;
            render::DrawScratch<float> sl;
            render::DrawScratch<double> sd;
            sf.prepare(wf), sl.prepare(wl), sd.prepare(wd);
            for (int frame = 0; frame < 3; ++frame) {
                wf.step(0.5), wl.step(0.5), wd.step(0.5);
                const auto mf = render::ScreenMap<fixed>::of(W, H, wf.K, wf.R, proj);
                const auto ml = render::ScreenMap<float>::of(W, H, wl.K, wl.R, proj);
                const auto md = render::ScreenMap<double>::of(W, H, wd.K, wd.R, proj);
                geo::FixedEquidistant fe;
                if (proj == geo::Projection::azimuthal_equidistant && geo::FixedEquidistant::make(mf, fe))
                    halving_errors(wf, geo::FixedEquidistantEval<false>{fe, wf.K, mf}, proj, sf, W, H, kernel);
                halving_errors(wf, geo::VecEval<fixed>{wf.K, proj, mf}, proj, sf, W, H, general);
                halving_errors(wl, geo::VecEval<float>{wl.K, proj, ml}, proj, sl, W, H, single);
                halving_errors(wd, geo::VecEval<double>{wd.K, proj, md}, proj, sd, W, H, twice);
            }
        }
    ::noneuclid_test_record("halving points from the reference geodesic, worst px at 800x480 (more than 10 px inside the clip "
                            "circle): fixed kernel %.4f (%.4f, %ld points), fixed general %.4f (%.4f), float %.4f, double %.2g; "
                            "shown or inside differ at %ld points\n",
                            kernel.worst, kernel.inner, kernel.points, general.worst, general.inner, single.worst, twice.worst,
                            kernel.disagree + general.disagree + single.disagree + twice.disagree);
    EXPECT_GT(kernel.points, 10000);
    EXPECT_LE(kernel.inner, 0.05);
    EXPECT_LE(general.inner, 0.05);
    EXPECT_LE(kernel.worst, 0.3);
    EXPECT_LE(general.worst, 0.3);
    EXPECT_LE(single.worst, 0.05);
    EXPECT_LE(twice.worst, 0.01);
}

}  // namespace
