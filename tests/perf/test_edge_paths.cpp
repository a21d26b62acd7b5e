// The geometry's fast paths against the arithmetic they replaced: geo::edge_points in fixed
// point bit for bit against the loop it replaced (t = T(k)/T(n), a = u Sf / sfd); walk_end the
// end of walk; the shape cache (render::ShapeCache) bit for bit the direct computation; and
// where the arithmetic differs on purpose, no less accurate than the path it replaced:
// edge_projected, and the draw's 3-vector path (cached shape, body motion), against the polar
// path, in pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "record.hpp"
#include "render/draw_world.hpp"


namespace {

using namespace noneuclid;
using fx::fixed;

// The edge loop as it was before the fast path (geometry.hpp, generalised slerp).
template <class T>
void old_edge_points(T K, geo::Polar<T> p, geo::Polar<T> q, int n, std::vector<geo::Polar<T>>& out) {
    using namespace geo;
    const T d = distance(K, p, q);
    const T sfd = Sf(K * d * d);
    if (K > T(0) && K * d * d > T(2) && sfd * d <= num<T>(1e-4)) {
        const T heading = p.r > T(0) ? p.theta : q.theta;
        out.push_back(p);
        for (int k = 1; k < n; ++k) out.push_back(walk(K, p, heading, d * T(k) / T(n)).end);
        out.push_back(q);
        return;
    }
    const Vec3<T> P = to_vec(K, p), Q = to_vec(K, q);
    out.push_back(p);
    for (int k = 1; k < n; ++k) {
        const T t = T(k) / T(n), u = T(n - k) / T(n);
        const T a = u * Sf(K * (u * d) * (u * d)) / sfd;
        const T b = t * Sf(K * (t * d) * (t * d)) / sfd;
        out.push_back(to_polar(K, Vec3<T>{dot2(a, P.w, b, Q.w), dot2(a, P.x, b, Q.x), dot2(a, P.y, b, Q.y)}));
    }
    out.push_back(q);
}

TEST(FastPaths, EdgePointsBitForBit) {
    std::mt19937 rng(2019);
    std::uniform_real_distribution<double> r01(0, 1);
    std::vector<geo::Polar<fixed>> a, b;
    for (double K : {-1.0, -0.7, -0.013, 0.0, 1e-4, 0.2, 0.5, 1.0})
        for (int i = 0; i < 600; ++i) {
            const double R = K > 0 ? 3.14159 / std::sqrt(K) : 3.14159;
            const geo::Polar<fixed> p{fixed(R * r01(rng)), fixed(6.28 * r01(rng) - 3.14)};
            const geo::Polar<fixed> q = i % 3 == 0 ? geo::Polar<fixed>{fixed(static_cast<double>(p.r) + 0.01 * r01(rng)), p.theta}
                                                   : geo::Polar<fixed>{fixed(R * r01(rng)), fixed(6.28 * r01(rng) - 3.14)};
            for (int n : {1, 2, 3, 7, 8, 16, 33}) {
                a.clear(), b.clear();
                old_edge_points(fixed(K), p, q, n, a);
                geo::edge_points(fixed(K), p, q, n, [&](int, geo::Polar<fixed> x) { b.push_back(x); });
                ASSERT_EQ(a.size(), b.size());
                for (std::size_t j = 0; j < a.size(); ++j) {
                    ASSERT_EQ(a[j].r.raw(), b[j].r.raw()) << K << " " << i << " " << n << " " << j;
                    ASSERT_EQ(a[j].theta.raw(), b[j].theta.raw()) << K << " " << i << " " << n << " " << j;
                }
            }
        }
}

// edge_projected against the polar path (edge_points, project, rho (cos, sin)) computed in
// double, in pixels of a 1080-px-high disk (limit radius pi = 540 px, as in the accuracy
// report; points within 2% of the rim left out where K > 0, as there). The same error is
// measured for the polar path in the same scalar (what the renderer drew before), and the fast
// path must be no worse: fixed within its worst + 0.01 px, double within 1e-6 px.
struct ProjErr {
    double fast = 0, polar = 0;
    int hidden_mismatch = 0;
};
template <class T>
ProjErr projected_error(geo::Projection proj) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> r01(0, 1);
    const double px = 540 / 3.14159265358979;
    ProjErr out;
    for (double K : {-1.0, -0.6, -0.01, 0.0, 0.01, 0.3, 1.0})
        for (int i = 0; i < 400; ++i) {
            const double R = K > 0 ? std::min(3.14159265358979, 0.98 * 3.14159265358979 / std::sqrt(K)) : 3.14159265358979;
            const geo::Polar<T> p{T(R * r01(rng)), T(6.28 * r01(rng) - 3.14)};
            const geo::Polar<T> q = i % 4 == 0 ? geo::Polar<T>{T(std::min(R, static_cast<double>(p.r) + 0.3 * r01(rng))), T(static_cast<double>(p.theta) + 0.2 * r01(rng))}
                                               : geo::Polar<T>{T(R * r01(rng)), T(6.28 * r01(rng) - 3.14)};
            const geo::Polar<double> pd{static_cast<double>(p.r), static_cast<double>(p.theta)};
            const geo::Polar<double> qd{static_cast<double>(q.r), static_cast<double>(q.theta)};
            std::vector<geo::ProjectedPoint<double>> ref;
            std::vector<geo::ProjectedPoint<T>> polar;
            std::vector<double> ref_r;
            geo::edge_points(K, pd, qd, 8, [&](int, geo::Polar<double> x) {
                ref.push_back(geo::project_polar(K, x, proj));
                ref_r.push_back(x.r);
            });
            geo::edge_points(T(K), p, q, 8, [&](int, geo::Polar<T> x) { polar.push_back(geo::project_polar(T(K), x, proj)); });
            int k = 0;
            geo::edge_projected(T(K), p, q, 8, proj, [&](int j, bool vis, T X, T Y) {
                EXPECT_EQ(j, k);
                const std::size_t u = static_cast<std::size_t>(k++);
                const auto& r = ref[u];
                if (K > 0 && ref_r[u] > 0.98 * 3.14159265358979 / std::sqrt(K)) return;
                if (vis != r.visible) {
                    ++out.hidden_mismatch;
                    return;
                }
                if (!vis) return;
                out.fast = std::max(out.fast, std::hypot(static_cast<double>(X) - r.X, static_cast<double>(Y) - r.Y) * px);
                if (polar[u].visible)
                    out.polar = std::max(out.polar, std::hypot(static_cast<double>(polar[u].X) - r.X,
                                                               static_cast<double>(polar[u].Y) - r.Y) * px);
            });
        }
    return out;
}

TEST(FastPaths, ProjectedEdgePointsMatchThePolarPath) {
    for (geo::Projection proj : geo::kProjections) {
        const ProjErr f = projected_error<fixed>(proj), l = projected_error<float>(proj), d = projected_error<double>(proj);
        ::noneuclid_test_record("edge_projected %-13s max px error (polar path before): fixed %.3g (%.3g), float %.3g (%.3g), double %.3g; "
                    "visibility differs %d\n",
                    geo::projection_name(proj), f.fast, f.polar, l.fast, l.polar, d.fast, f.hidden_mismatch + l.hidden_mismatch + d.hidden_mismatch);
        EXPECT_LE(f.fast, f.polar + 0.01) << geo::projection_name(proj);
        EXPECT_LE(l.fast, l.polar + 0.001) << geo::projection_name(proj);
        EXPECT_LE(d.fast, std::max(1e-6, 1.001 * d.polar)) << geo::projection_name(proj);
        EXPECT_LE(f.hidden_mismatch + l.hidden_mismatch + d.hidden_mismatch, 20);  // only on a visibility threshold
    }
}

TEST(FastPaths, WalkEndIsTheEndOfTheWalk) {
    std::mt19937 rng(53);
    std::uniform_real_distribution<double> r01(0, 1);
    for (double K : {-1.0, -0.3, 0.0, 0.4, 1.0})
        for (int i = 0; i < 5000; ++i) {
            const geo::Polar<fixed> p{fixed(3.1 * r01(rng)), fixed(6.28 * r01(rng) - 3.14)};
            const fixed h(6.28 * r01(rng) - 3.14), b(0.8 * r01(rng));
            const auto w = geo::walk(fixed(K), p, h, b).end;
            const auto e = geo::walk_end(fixed(K), p, h, b);
            ASSERT_EQ(w.r.raw(), e.r.raw());
            ASSERT_EQ(w.theta.raw(), e.theta.raw());
            // In double the same formulas may round differently where the compiler fuses a
            // product and a sum (aarch64 FMA; gcc contracts by default): a few ulps.
            const geo::Polar<double> pd{static_cast<double>(p.r), static_cast<double>(p.theta)};
            const auto wd = geo::walk(K, pd, static_cast<double>(h), static_cast<double>(b)).end;
            const auto ed = geo::walk_end(K, pd, static_cast<double>(h), static_cast<double>(b));
            ASSERT_NEAR(wd.r, ed.r, 1e-13);
            ASSERT_NEAR(std::remainder(wd.theta - ed.theta, 2 * 3.14159265358979), 0, 1e-13);
        }
}

// The draw's 3-vector path (body_screen_points: the shape cache's local 3-vectors and slerp
// weights cached per K, the body's motion as a matrix, project_vec for every point) against the
// polar path computed in double from the same state (walk_end vertices, edge_points,
// project_polar): screen points in px at 800x480, breaks where a point is hidden. The polar
// path in the same scalar (what the renderer drew before) is measured the same way, and the
// new path must be no worse: fixed within its worst + 0.02 px, float + 0.002 px, double 1e-6 px.
struct PathErr {
    double fast = 0, polar = 0;
    long points = 0;
    int mismatched = 0;  // bodies whose visibility breaks differ (a point on a threshold)
};
struct ScreenPt {
    bool brk;
    double x, y;
};
template <class T, class F>
std::vector<ScreenPt> polar_path(const world::World<T>& w, const world::Body<T>& b, double K, const render::ScreenMap<double>& m,
                                 geo::Projection proj, F&& vertex) {
    const std::size_t n = b.local.size(), edges = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
    std::vector<ScreenPt> out;
    bool open = false;
    auto add = [&](bool vis, double X, double Y) {
        if (!vis) {
            if (open) out.push_back({true, 0, 0}), open = false;
            return;
        }
        out.push_back({false, m.cx + m.scale * X, m.cy - m.scale * Y});
        open = true;
    };
    std::vector<geo::Polar<double>> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = vertex(i);
    if (edges == 0) {
        const auto pp = geo::project_polar(K, v[0], proj);
        add(pp.visible, pp.X, pp.Y);
    }
    for (std::size_t e = 0; e < edges; ++e)
        geo::edge_points(K, v[e], v[(e + 1) % n], b.desc->tessellation, [&](int k, geo::Polar<double> x) {
            if (k == 0 && e > 0) return;
            const auto pp = geo::project_polar(K, x, proj);
            add(pp.visible, pp.X, pp.Y);
        });
    (void)w;
    return out;
}
// Largest distance in px between two point lists with breaks in the same places; -1 if not.
template <class P>
double list_error(const std::vector<ScreenPt>& ref, const P* pts, std::size_t count) {
    if (count != ref.size()) return -1;
    double worst = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const bool brk = pts[i].x == render::kBreak.x && pts[i].y == render::kBreak.y;
        if (brk != ref[i].brk) return -1;
        if (!brk) {
            const double e = std::hypot(pts[i].x / 256.0 - ref[i].x, pts[i].y / 256.0 - ref[i].y);
            worst = std::max(worst, e);
        }
    }
    return worst;
}

template <class T>
PathErr body_path_error(const char* scene_name, double K0, geo::Projection proj) {
    world::Scene scene;
    EXPECT_TRUE(world::builtin_scene(scene_name, {40, 6, 5}, scene));
    scene.curvature = K0;
    world::World<T> w(scene);
    render::DrawScratch<T> s;
    s.prepare(w);
    render::DrawOptions o;
    o.projection = proj;
    PathErr out;
    std::vector<render::SubPoint> polar_pts(s.points.size());
    for (int frame = 0; frame < 12; ++frame) {
        w.step(T(0.1));
        const double K = static_cast<double>(w.K);
        const auto m = render::ScreenMap<T>::of(800, 480, w.R);
        const auto md = render::ScreenMap<double>::of(800, 480, static_cast<double>(w.R));
        for (std::size_t bi = 0; bi < w.bodies.size(); ++bi) {
            const auto& b = w.bodies[bi];
            const double c_r = static_cast<double>(b.centre.r), c_t = static_cast<double>(b.centre.theta);
            const double facing = static_cast<double>(b.facing);
            const std::vector<ScreenPt> ref = polar_path(w, b, K, md, proj, [&](std::size_t i) {
                return geo::vertex_position(K, geo::Polar<double>{c_r, c_t}, facing,
                                            geo::Polar<double>{static_cast<double>(b.local[i].r), static_cast<double>(b.local[i].theta)});
            });
            const std::size_t count =
                render::body_screen_points(w, b, s.shapes[bi], m, o, s.vertices.data(), s.vectors.data(), s.points.data());
            // The polar path in T, as the renderer drew before: walk_end vertices, edge_projected.
            std::size_t pc = 0;
            bool open = false;
            const std::size_t n = b.local.size(), edges = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
            std::vector<geo::Polar<T>> v(n);
            w.vertices(b, v.data());
            for (std::size_t e = 0; e < edges; ++e)
                geo::edge_projected(w.K, v[e], v[(e + 1) % n], b.desc->tessellation, proj, [&](int k, bool vis, T X, T Y) {
                    if (k == 0 && e > 0) return;
                    if (!vis) {
                        if (open) polar_pts[pc++] = render::kBreak, open = false;
                        return;
                    }
                    polar_pts[pc++] = render::to_pixels(geo::ScreenPoint<T>{m.cx + m.scale * X, m.cy - m.scale * Y});
                    open = true;
                });
            const double fast = list_error(ref, s.points.data(), count);
            const double polar = edges == 0 ? 0 : list_error(ref, polar_pts.data(), pc);
            if (fast < 0 || polar < 0) {
                ++out.mismatched;
                continue;
            }
            out.fast = std::max(out.fast, fast), out.polar = std::max(out.polar, polar);
            out.points += static_cast<long>(count);
        }
    }
    return out;
}

// render::ShapeCache, refreshed when K changes, holds what the direct computation gives, bit
// for bit: to_vec of each local vertex, and for each edge the weights of the direct form
// (t Sf(K (t d)^2) / Sf(K d^2), u likewise) or of the recurrence, with d = geo::distance of the
// local end points.
template <class T>
void shape_is_direct(const char* scene_name, double K0) {
    world::Scene scene;
    ASSERT_TRUE(world::builtin_scene(scene_name, {40, 6, 5}, scene));
    scene.curvature = K0;
    scene.curvature_rate = 0.3;
    world::World<T> w(scene);
    std::vector<render::ShapeCache<T>> caches;
    render::make_shape_caches(w, caches);
    for (int frame = 0; frame < 4; ++frame) {
        for (std::size_t bi = 0; bi < w.bodies.size(); ++bi) {
            const auto& b = w.bodies[bi];
            const render::ShapeCache<T>& c = caches[bi].refresh(w.K, b);
            ASSERT_TRUE(c.valid);
            ASSERT_EQ(c.K, w.K);
            const std::size_t n = b.local.size(), edges = c.antipodal.size();
            for (std::size_t i = 0; i < n; ++i) {
                const geo::Vec3<T> v = geo::to_vec(w.K, b.local[i]);
                ASSERT_EQ(c.local[i].w, v.w);
                ASSERT_EQ(c.local[i].x, v.x);
                ASSERT_EQ(c.local[i].y, v.y);
            }
            const int level = b.desc->tessellation;
            using geo::Sf;  // and fx::Sf by ADL
            bool any = false;
            for (std::size_t e = 0; e < edges; ++e) {
                const T d = geo::distance(w.K, b.local[e], b.local[(e + 1) % n]);
                const T sfd = Sf(w.K * d * d);
                ASSERT_EQ(c.antipodal[e] != 0, geo::antipodal_edge(w.K, d, sfd)) << scene_name << " edge " << e;
                any = any || c.antipodal[e];
                geo::SlerpWeights<T> rec;
                const bool recurrence = rec.prepare(w.K, d, level);
                for (int k = 1; k < level && !c.antipodal[e]; ++k) {
                    const T t = T(k) / T(level), u = T(level - k) / T(level);
                    const T a = recurrence ? rec.a(k) : u * Sf(w.K * (u * d) * (u * d)) / sfd;
                    const T bw = recurrence ? rec.b(k) : t * Sf(w.K * (t * d) * (t * d)) / sfd;
                    const T* ab = c.weights.data() + e * static_cast<std::size_t>(2 * (level - 1));
                    ASSERT_EQ(ab[2 * (k - 1)], a) << scene_name << " edge " << e << " k " << k;
                    ASSERT_EQ(ab[2 * (k - 1) + 1], bw) << scene_name << " edge " << e << " k " << k;
                }
            }
            ASSERT_EQ(c.any_antipodal, any) << scene_name;
        }
        w.press(world::Action::curvature_up);  // K changes: the next refresh recomputes
        w.step(T(0.1));
    }
}

TEST(FastPaths, ShapeCacheIsTheDirectComputation) {
    shape_is_direct<fixed>("kiosk", -0.6);
    shape_is_direct<fixed>("stress", -1.0);
    shape_is_direct<fixed>("fig17", 0.3);
    shape_is_direct<double>("kiosk", -0.6);
    shape_is_direct<double>("stress", 0.5);
    shape_is_direct<float>("kiosk", 0.8);
}

TEST(FastPaths, BodyPointsMatchThePolarPath) {
    struct Case {
        const char* scene;
        double K;
    } cases[] = {{"kiosk", 0.8}, {"kiosk", -0.6}, {"kiosk", 0.0}, {"stress", -1.0}, {"stress", 1.0}, {"fig17", 0.3}};
    for (const Case& c : cases)
        for (geo::Projection proj : geo::kProjections) {
            const PathErr f = body_path_error<fixed>(c.scene, c.K, proj), l = body_path_error<float>(c.scene, c.K, proj),
                          d = body_path_error<double>(c.scene, c.K, proj);
            ::noneuclid_test_record("%-6s K %4.1f %-13s max px error (polar path before): fixed %.3g (%.3g), float %.3g (%.3g), "
                        "double %.3g (%.3g); %ld points; breaks differ in %d bodies\n",
                        c.scene, c.K, geo::projection_name(proj), f.fast, f.polar, l.fast, l.polar, d.fast, d.polar, f.points,
                        f.mismatched + l.mismatched + d.mismatched);
            EXPECT_GT(f.points, 100);
            EXPECT_LE(f.fast, f.polar + 0.02) << c.scene << " " << c.K << " " << geo::projection_name(proj);
            // float near the gnomonic horizon, where the projection magnifies without bound, errs by
            // tens of pixels on either path (stress at K = 1): there the paths are compared relatively.
            EXPECT_LE(l.fast, std::max(l.polar + 0.002, 1.001 * l.polar))
                << c.scene << " " << c.K << " " << geo::projection_name(proj);
            EXPECT_LE(d.fast, std::max(1e-6, 1.001 * d.polar)) << c.scene << " " << c.K << " " << geo::projection_name(proj);
            EXPECT_LE(f.mismatched + l.mismatched + d.mismatched, 3);  // only on a visibility threshold
        }
}

}  // namespace
