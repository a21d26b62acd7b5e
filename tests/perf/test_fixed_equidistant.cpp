// The fixed engine's equidistant inner loop (render/fixed_points.hpp) and the motion it
// starts from: geo::MotionApply<fixed> bit for bit M(L); one FixedEquidistant point against
// double; the whole loop against the general 3-vector path it replaced.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "record.hpp"
#include "render/draw_world.hpp"


namespace {

using namespace noneuclid;
using fx::fixed;

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

// render::detail::FixedEquidistant, one point: the 3-vector (C_K(r), S_K(r) cos t, S_K(r) sin t)
// rounded to Q16.16 lands within 0.012 px of centre + scale r (cos t, -sin t) computed in double
// (measured: 0.0106 px; the floor to 1/256 px alone is up to 0.0055 px), for curvatures from
// the sphere (past its equator too) to the hyperbolic plane and two screens; points outside
// its domain (w < -1/2, w >= 32, |x| or |y| > 100, or > 16 past the equator) are left to the
// general path.
TEST(FastPaths, FixedEquidistantPointAgainstDouble) {
    std::mt19937 rng(5);
    for (const double K : {-1.0, -0.6, -0.05, 0.0, 0.3, 1.0})
        for (const auto& size : {std::pair{800, 480}, std::pair{1920, 1080}}) {
            const double R = K > 0 ? 3.14159265358979 / std::sqrt(K) : 3.2;
            const auto m = render::ScreenMap<fixed>::of(size.first, size.second, fixed(R));
            render::detail::FixedEquidistant fe;
            ASSERT_TRUE(render::detail::FixedEquidistant::make(m, fe));
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

// The whole inner loop (render::detail::fixed_equidistant_points, which body_screen_points
// takes for the fixed engine's equidistant view) against the general 3-vector path it replaced
// (the same vertices, geo::edge_projected with project_vec, the generic screen mapping): the
// same breaks in the same places and every point within 0.03 px, in scenes whose edges leave
// the fast domain mid-edge (below w = -1/2 on the sphere) and come back. The two are different
// approximations, each within 0.021 px of the double reference (BodyPointsMatchThePolarPath);
// measured apart by up to 0.021 px (fig17, just past the sphere's equator, where the polar path
// reads r off the sine and E(w) off the cosine). A misplaced or missing point is pixels away.
// Bodies with an edge between antipodal points of the unit sphere (local vertices at rho = pi/2
// on opposite sides: antipodal_points walks it) as the first, a middle and the last edge, open
// and closed, at level 1, 2 (midpoint_run) and 8.
world::Scene antipodal_scene() {
    world::Scene scene;
    const double h = 3.14159265358979323846 / 2;
    int i = 0;
    for (const int level : {1, 2, 8})
        for (const bool closed : {false, true})
            for (int first = 0; first < 3; ++first) {
                world::SceneBody b;
                b.name = "antipodal";
                b.tessellation = level, b.closed = closed;
                b.r = 0.2 + 0.15 * i, b.theta_deg = 40.0 * i, b.spin_deg = 30, b.speed = 0.2, b.direction_deg = 70;
                std::vector<world::SceneBody::Vertex> v = {{0.4, 90}, {0.3, 200}, {0.5, 300}};
                v.insert(v.begin() + first, {{h, 10}, {h, 190}});
                b.vertices = v;
                scene.bodies.push_back(b);
                ++i;
            }
    return scene;
}

// What the general path passed through: slerp points and vertices below w = -1/2 (outside
// FixedEquidistant's domain), antipodal edges.
struct GeneralPathCounts {
    long outside = 0, vertices_outside = 0, antipodal = 0;
};
// Body b's screen points by the general 3-vector path (the same vertices, geo::edge_projected
// with project_vec, the generic screen mapping) into ref; returns their count.
std::size_t general_path_points(const world::World<fixed>& w, const world::Body<fixed>& b, const render::ShapeCache<fixed>& sh,
                                const render::ScreenMap<fixed>& m, geo::Vec3<fixed>* vecs, render::SubPoint* ref,
                                GeneralPathCounts& counts) {
    const geo::Projection proj = geo::Projection::azimuthal_equidistant;
    const geo::Motion<fixed> M = geo::body_motion(w.K, b.centre, b.facing);
    const std::size_t n = b.local.size(), edges = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
    for (std::size_t i = 0; i < n; ++i) {
        vecs[i] = M(sh.local[i]);
        counts.vertices_outside += vecs[i].w < fixed(-0.5);
    }
    render::detail::Cursor cur;
    auto emit = [&](int, bool vis, fixed X, fixed Y) { render::detail::put_point(ref, cur, m, vis, X, Y); };
    if (edges == 0) {
        const auto pp = geo::project_vec(w.K, vecs[0], proj);
        emit(0, pp.visible, pp.X, pp.Y);
    }
    for (std::size_t e = 0; e < edges; ++e) {
        const std::size_t f = (e + 1) % n;
        if (!sh.antipodal[e]) {
            geo::edge_projected(w.K, vecs[e], vecs[f], sh.weights_of(e), b.desc->tessellation, proj, e == 0, emit);
            const fixed* ab = sh.weights_of(e);
            for (int k = 1; k < b.desc->tessellation; ++k, ab += 2)
                counts.outside += dot2(ab[0], vecs[e].w, ab[1], vecs[f].w) < fixed(-0.5);
        } else {
            ++counts.antipodal;
            const auto p = geo::to_polar(w.K, vecs[e]), q = geo::to_polar(w.K, vecs[f]);
            geo::edge_projected(w.K, p, q, vecs[e], vecs[f], b.desc->tessellation, proj, e == 0, emit);
        }
    }
    return cur.count;
}

TEST(FastPaths, FixedEquidistantPointsAreTheGeneralPath) {
    struct Case {
        const char* scene;
        double K;
        int level = 5;  // stress's; the other scenes have their own
    } cases[] = {{"stress", 1.0},     {"kiosk", 0.8},     {"stress", -1.0},   {"kiosk", -0.6},  {"kiosk", 0.0},
                 {"fig17", 0.3},      {"antipodal", 1.0}, {"stress", 1.0, 1}, {"stress", 0.0, 1}, {"stress", 1.0, 3}};
    for (const Case& c : cases) {
        world::Scene scene;
        if (std::string(c.scene) == "antipodal")
            scene = antipodal_scene();
        else
            ASSERT_TRUE(world::builtin_scene(c.scene, {40, 6, c.level}, scene));
        scene.curvature = c.K;
        world::World<fixed> w(scene);
        render::DrawScratch<fixed> s;
        s.prepare(w);
        const render::DrawOptions o;  // equidistant
        std::vector<render::SubPoint> ref(s.points.size());
        std::vector<geo::Vec3<fixed>> vecs(s.vectors.size());
        double worst = 0;
        long points = 0, breaks = 0;
        GeneralPathCounts counts;
        for (int frame = 0; frame < 12; ++frame) {
            w.step(fixed(0.1));
            const auto m = render::ScreenMap<fixed>::of(800, 480, w.R);
            for (std::size_t bi = 0; bi < w.bodies.size(); ++bi) {
                const auto& b = w.bodies[bi];
                const std::size_t count =
                    render::body_screen_points(w, b, s.shapes[bi], m, o, s.vertices.data(), s.vectors.data(), s.points.data());
                ASSERT_EQ(count, general_path_points(w, b, s.shapes[bi], m, vecs.data(), ref.data(), counts)) << c.scene << " " << c.K;
                for (std::size_t i = 0; i < count; ++i) {
                    const bool brk = s.points[i].x == render::kBreak.x, ref_brk = ref[i].x == render::kBreak.x;
                    ASSERT_EQ(brk, ref_brk) << c.scene << " " << c.K << " entry " << i;
                    breaks += brk;
                    if (brk) continue;
                    worst = std::max(worst, std::hypot(s.points[i].x - ref[i].x, s.points[i].y - ref[i].y) / 256.0);
                    ++points;
                }
            }
        }
        const std::string name = std::string(c.scene) == "stress" ? "stress, level " + std::to_string(c.level) : c.scene;
        ::noneuclid_test_record("%-16s K %4.1f: worst %.4f px from the general path over %ld points; %ld slerp points "
                    "and %ld vertices below w = -1/2, %ld breaks\n", name.c_str(), c.K, worst, points, counts.outside,
                    counts.vertices_outside, breaks);
        EXPECT_LE(worst, 0.03) << c.scene << " " << c.K;
        if (c.K >= 0.8) {  // the general path was taken inside an edge, or (level 1) at vertices
            EXPECT_GT(c.level == 1 ? counts.vertices_outside : counts.outside, 100) << c.scene << " level " << c.level;
        }
        if (std::string(c.scene) == "antipodal") {
            EXPECT_GE(counts.antipodal, 12 * 12);  // every body's antipodal edge, every frame
        }
    }
}

}  // namespace
