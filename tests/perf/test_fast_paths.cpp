// The performance paths compute what the plain arithmetic computes, bit for bit,
// - fx::fixed's operator/ on 32-bit targets (a reciprocal instead of __aeabi_ldivmod) and the
//   per-divisor reciprocal fx::divisor against plain 64-bit integer division, rounded to
//   nearest with ties away from zero, as fixed.hpp specifies;
// - geo::Fractions<fixed> against T(k) / T(n);
// - geo::edge_points in fixed point against the loop it replaced (t = T(k)/T(n), a = u Sf / sfd);
// - the backdrop written as spans against Canvas::clear + shade_outside_circle;
// and where the arithmetic differs on purpose, no less accurate than the path it replaced:
// - the draw's 3-vector path (cached shape, body motion) against the polar path, in pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "render/draw_world.hpp"

namespace {

using namespace noneuclid;
using fx::fixed;

// x / d in Q16.16 from the definition: (x 2^16) / d rounded half away from zero, saturated.
int32_t reference_div(int32_t x, int32_t d) {
    if (d == 0) return x > 0 ? INT32_MAX : (x < 0 ? INT32_MIN : 0);
    int64_t n = int64_t{x} * 65536, dd = d;
    if (dd < 0) n = -n, dd = -dd;
    const int64_t q = n >= 0 ? (n + dd / 2) / dd : -((-n + dd / 2) / dd);
    return q > INT32_MAX ? INT32_MAX : (q < INT32_MIN ? INT32_MIN : static_cast<int32_t>(q));
}

std::vector<int32_t> interesting() {
    std::vector<int32_t> v = {0, 1, -1, 2, -2, 3, 7, 255, 256, 65535, 65536, -65536, 65537, 98304, 1 << 20,
                              INT32_MAX, INT32_MIN, INT32_MIN + 1, INT32_MAX - 1, 1 << 30, -(1 << 30)};
    std::mt19937 rng(8);
    for (int i = 0; i < 300; ++i) {
        const int bits = static_cast<int>(rng() % 32);
        const int32_t x = static_cast<int32_t>(rng() >> (31 - bits % 31));
        v.push_back(x), v.push_back(-x);
    }
    return v;
}

TEST(FastPaths, OperatorDivideMatchesTheDefinition) {
    const auto vals = interesting();
    for (int32_t x : vals)
        for (int32_t d : vals) ASSERT_EQ((fixed::from_raw(x) / fixed::from_raw(d)).raw(), reference_div(x, d)) << x << " / " << d;
}

TEST(FastPaths, PortableDivisionMatchesTheDefinition) {
    const auto vals = interesting();
    for (int32_t x : vals)
        for (int32_t d : vals) {
            if (d == 0) continue;
            const int64_t n = int64_t{x} * 65536;
            const uint32_t ad = d < 0 ? 0u - static_cast<uint32_t>(d) : static_cast<uint32_t>(d);
            const int64_t q = fx::detail::div_round_portable(d < 0 ? -n : n, ad);
            const int32_t s = q > INT32_MAX ? INT32_MAX : (q < INT32_MIN ? INT32_MIN : static_cast<int32_t>(q));
            ASSERT_EQ(s, reference_div(x, d)) << x << " / " << d;
        }
}

template <bool Native>
void divisor_matches() {
    const auto vals = interesting();
    for (int32_t d : vals) {
        const fx::detail::Divisor<Native> div(d);
        for (int32_t x : vals) ASSERT_EQ(div.quotient_q16(x), reference_div(x, d)) << x << " / " << d;
    }
    // Divisors the geometry meets (Sf of an edge: about 0.3 .. 4), dense numerators.
    std::mt19937 rng(88);
    for (int i = 0; i < 2000; ++i) {
        const int32_t d = static_cast<int32_t>(rng() % (4 << 16)) + 1;
        const fx::detail::Divisor<Native> div(d);
        for (int j = 0; j < 200; ++j) {
            const int32_t x = static_cast<int32_t>(rng() % (8 << 16)) - (4 << 16);
            ASSERT_EQ(div.quotient_q16(x), reference_div(x, d)) << x << " / " << d;
        }
    }
}
TEST(FastPaths, DivisorNative) { divisor_matches<true>(); }
TEST(FastPaths, DivisorReciprocal) { divisor_matches<false>(); }
TEST(FastPaths, DivisorOfFixed) {
    for (int32_t d : interesting())
        for (int32_t x : {0, 1, -1, 12345, -98765, INT32_MAX, INT32_MIN})
            ASSERT_EQ(fx::divisor(fixed::from_raw(d))(fixed::from_raw(x)).raw(), reference_div(x, d));
}

TEST(FastPaths, QuotientAndQuarterAreOperatorDivide) {
    const auto vals = interesting();
    for (int32_t x : vals) {
        ASSERT_EQ(fx::quarter(fixed::from_raw(x)).raw(), reference_div(x, 4 << 16)) << x;
        for (int32_t d : vals) ASSERT_EQ(fx::quotient(fixed::from_raw(x), fixed::from_raw(d)).raw(), reference_div(x, d));
    }
}

// atan2's tangent num 2^32 / den (num <= den) and the like: the reciprocal gives the floor.
TEST(FastPaths, FloorDivisionByReciprocal) {
    std::mt19937_64 rng(32);
    for (int i = 0; i < 400000; ++i) {
        uint32_t den = static_cast<uint32_t>(rng() >> (32 + rng() % 32));
        if (den == 0) den = 1;
        const uint32_t num = static_cast<uint32_t>(rng() % (uint64_t{den} + 1));
        const uint64_t n = uint64_t{num} << 32;
        ASSERT_EQ(fx::detail::udiv_floor_reciprocal(n, den), n / den) << num << " / " << den;
    }
    for (uint32_t den : {1u, 2u, 3u, 0xFFFFFFFFu, 0x80000000u, 0x7FFFFFFFu, 65536u})
        for (uint32_t num : {0u, 1u, den / 2, den - 1, den}) {
            const uint64_t n = uint64_t{num} << 32;
            ASSERT_EQ(fx::detail::udiv_floor_reciprocal(n, den), n / den) << num << " / " << den;
        }
}

TEST(FastPaths, FractionsAreTheQuotients) {
    for (int n = 1; n < 3000; n += (n < 300 ? 1 : 37)) {
        geo::Fractions<fixed> f(n);
        for (int k = 1; k < n; ++k) {
            f.next();
            ASSERT_EQ(f.t(k).raw(), (fixed(k) / fixed(n)).raw()) << k << "/" << n;
            ASSERT_EQ(f.u(k).raw(), (fixed(n - k) / fixed(n)).raw()) << n - k << "/" << n;
        }
    }
}

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
        std::printf("edge_projected %-13s max px error (polar path before): fixed %.3g (%.3g), float %.3g (%.3g), double %.3g; "
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

TEST(FastPaths, BackdropSpansAreClearPlusShade) {
    for (render::PixelFormat f : {render::PixelFormat::rgb565(), render::PixelFormat::xrgb8888(), render::PixelFormat::rgb888()})
        for (auto [w, h] : {std::pair{800, 480}, std::pair{33, 97}, std::pair{1, 1}, std::pair{480, 480}, std::pair{101, 40}})
            for (double R : {3.14159265358979, 1.0, 0.3})
                for (bool shade : {true, false}) {
                    const std::size_t stride = static_cast<std::size_t>(w * f.bytes_per_pixel() + 8);
                    std::vector<uint8_t> x(stride * static_cast<std::size_t>(h), 0xAB), y = x;
                    const render::Canvas cx(x.data(), w, h, static_cast<std::ptrdiff_t>(stride), f);
                    const render::Canvas cy(y.data(), w, h, static_cast<std::ptrdiff_t>(stride), f);
                    render::DrawOptions o;
                    o.shade_outside = shade;
                    const auto m = render::ScreenMap<double>::of(cx, R);
                    render::draw_backdrop(cx, m, R, o);
                    cy.clear(o.background);
                    if (shade) render::shade_outside_circle(cy, m.cx, m.cy, m.scale * R, o.outside);
                    ASSERT_EQ(x, y) << w << "x" << h << " R " << R << " shade " << shade;
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
            std::printf("%-6s K %4.1f %-13s max px error (polar path before): fixed %.3g (%.3g), float %.3g (%.3g), "
                        "double %.3g (%.3g); %ld points; breaks differ in %d bodies\n",
                        c.scene, c.K, geo::projection_name(proj), f.fast, f.polar, l.fast, l.polar, d.fast, d.polar, f.points,
                        f.mismatched + l.mismatched + d.mismatched);
            EXPECT_GT(f.points, 100);
            EXPECT_LE(f.fast, f.polar + 0.02) << c.scene << " " << c.K << " " << geo::projection_name(proj);
            EXPECT_LE(l.fast, l.polar + 0.002) << c.scene << " " << c.K << " " << geo::projection_name(proj);
            EXPECT_LE(d.fast, std::max(1e-6, 1.001 * d.polar)) << c.scene << " " << c.K << " " << geo::projection_name(proj);
            EXPECT_LE(f.mismatched + l.mismatched + d.mismatched, 3);  // only on a visibility threshold
        }
}

// ---- the fixed engine's equidistant inner loop ----------------------------------------------

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
            std::printf("K %5.2f %dx%d: worst %.4f px over %ld points (%ld past the equator; %ld left to the general "
                        "path)\n", K, size.first, size.second, worst, shown, south_points, left);
            if (K > 0) {
                EXPECT_GT(south_points, 10000) << K;
            }
            EXPECT_GT(shown, 50000);
            EXPECT_LE(worst, 0.012) << K;
            if (K != 0) {
                EXPECT_GT(left, 0) << K;  // the domain's edge was reached
            } else {
                std::printf("K  0.00 %dx%d, the plane's path: worst %.4f px over %ld points\n", size.first, size.second,
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
TEST(FastPaths, FixedEquidistantPointsAreTheGeneralPath) {
    struct Case {
        const char* scene;
        double K;
        int level = 5;  // stress's; the other scenes have their own
    } cases[] = {{"stress", 1.0},     {"kiosk", 0.8},     {"stress", -1.0},   {"kiosk", -0.6},  {"kiosk", 0.0},
                 {"fig17", 0.3},      {"antipodal", 1.0}, {"stress", 1.0, 1}, {"stress", 0.0, 1}, {"stress", 1.0, 3}};
    for (const Case& c : cases) {
        world::Scene scene;
        if (std::string(c.scene) == "antipodal") {
            // Bodies with an edge between antipodal points of the unit sphere (local vertices at
            // rho = pi/2 on opposite sides: antipodal_points walks it) as the first, a middle
            // and the last edge, open and closed, at level 1, 2 (level2_run) and 8.
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
        } else {
            ASSERT_TRUE(world::builtin_scene(c.scene, {40, 6, c.level}, scene));
        }
        scene.curvature = c.K;
        world::World<fixed> w(scene);
        render::DrawScratch<fixed> s;
        s.prepare(w);
        const render::DrawOptions o;  // equidistant
        std::vector<render::SubPoint> ref(s.points.size());
        std::vector<geo::Vec3<fixed>> vecs(s.vectors.size());
        double worst = 0;
        long points = 0, outside = 0, antipodal = 0, vertices_outside = 0, breaks = 0;
        for (int frame = 0; frame < 12; ++frame) {
            w.step(fixed(0.1));
            const auto m = render::ScreenMap<fixed>::of(800, 480, w.R);
            for (std::size_t bi = 0; bi < w.bodies.size(); ++bi) {
                const auto& b = w.bodies[bi];
                const std::size_t count =
                    render::body_screen_points(w, b, s.shapes[bi], m, o, s.vertices.data(), s.vectors.data(), s.points.data());
                const render::ShapeCache<fixed>& sh = s.shapes[bi];
                const geo::Motion<fixed> M = geo::body_motion(w.K, b.centre, b.facing);
                const std::size_t n = b.local.size(), edges = n < 2 ? 0 : (b.desc->closed ? n : n - 1);
                for (std::size_t i = 0; i < n; ++i) {
                    vecs[i] = M(sh.local[i]);
                    vertices_outside += vecs[i].w < fixed(-0.5);
                }
                render::detail::Cursor cur;
                auto emit = [&](int, bool vis, fixed X, fixed Y) { render::detail::put_point(ref.data(), cur, m, vis, X, Y); };
                if (edges == 0) {
                    const auto pp = geo::project_vec(w.K, vecs[0], o.projection);
                    emit(0, pp.visible, pp.X, pp.Y);
                }
                for (std::size_t e = 0; e < edges; ++e) {
                    const std::size_t f = (e + 1) % n;
                    if (!sh.antipodal[e]) {
                        geo::edge_projected(w.K, vecs[e], vecs[f], sh.weights_of(e), b.desc->tessellation, o.projection, e == 0, emit);
                        const fixed* ab = sh.weights_of(e);
                        for (int k = 1; k < b.desc->tessellation; ++k, ab += 2)
                            outside += dot2(ab[0], vecs[e].w, ab[1], vecs[f].w) < fixed(-0.5);
                    } else {
                        ++antipodal;
                        const auto p = geo::to_polar(w.K, vecs[e]), q = geo::to_polar(w.K, vecs[f]);
                        geo::edge_projected(w.K, p, q, vecs[e], vecs[f], b.desc->tessellation, o.projection, e == 0, emit);
                    }
                }
                ASSERT_EQ(count, cur.count) << c.scene << " " << c.K;
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
        std::printf("%-16s K %4.1f: worst %.4f px from the general path over %ld points; %ld slerp points "
                    "and %ld vertices below w = -1/2, %ld breaks\n", name.c_str(), c.K, worst, points, outside, vertices_outside, breaks);
        EXPECT_LE(worst, 0.03) << c.scene << " " << c.K;
        if (c.K >= 0.8) {  // the general path was taken inside an edge, or (level 1) at vertices
            EXPECT_GT(c.level == 1 ? vertices_outside : outside, 100) << c.scene << " level " << c.level;
        }
        if (std::string(c.scene) == "antipodal") {
            EXPECT_GE(antipodal, 12 * 12);  // every body's antipodal edge, every frame
        }
    }
}

// ---- the rasteriser's 32-bit paths and the backdrop's spans ---------------------------------

// What draw_polyline writes, built from visit_polyline's pixels: the generic 64-bit loop (no
// byte offsets, no 32-bit error terms, no skipped checks), each pixel set or blended through
// the Canvas's own word access.
// (XRGB8888's fast blend (raster.cpp, CanvasSink::mix8) adds q = (src - dst) a 257 / 2^16 per
// channel as floor(q + 1/2) when q >= 0 and floor(q - 1/2) when q < 0, which is not always
// Canvas::blend's rounding of (src - dst) a / 255: that format's blend is redone here from that
// definition, in double.)
struct VisitInto {
    const render::Canvas* c;
    render::Rgb color;
};
void put_visited(int x, int y, int alpha, void* ctx) {
    const auto& v = *static_cast<VisitInto*>(ctx);
    if (alpha >= 255) return v.c->set(x, y, v.color);
    if (!v.c->format().is_xrgb8888()) return v.c->blend(x, y, v.color, alpha);
    const uint32_t d = v.c->get_word(x, y);
    auto mix = [alpha](int s, int t) {
        const double q = (s - t) * alpha * 257 / 65536.0;
        return static_cast<uint32_t>(t + static_cast<int>(q >= 0 ? std::floor(q + 0.5) : std::floor(q - 0.5)));
    };
    const uint32_t r = mix(v.color.r, static_cast<int>(d >> 16 & 0xFF)), g = mix(v.color.g, static_cast<int>(d >> 8 & 0xFF)),
                   b = mix(v.color.b, static_cast<int>(d & 0xFF));
    v.c->set_word(x, y, (d & 0xFF000000u) | r << 16 | g << 8 | b);
}

// A sub-pixel coordinate along one axis of a canvas `side` px long: mostly on it, often near or
// over its borders, sometimes far off or at the ends of the int32 range.
int32_t random_coordinate(std::mt19937& rng, int side) {
    const uint32_t kind = rng() % 16;
    const int32_t s = side * 256;
    if (kind < 8) return static_cast<int32_t>(rng() % static_cast<uint32_t>(s));
    if (kind < 12) return static_cast<int32_t>(rng() % 2048) - 1024 + (rng() % 2 ? 0 : s);  // a border, +-4 px
    if (kind == 12) return static_cast<int32_t>(rng() % (8u << 20)) - (4 << 20);               // +-16384 px
    if (kind == 13) return static_cast<int32_t>(rng());                                          // anywhere in int32
    if (kind == 14) return rng() % 2 ? INT32_MAX : INT32_MIN + 1;
    return (rng() % 2 ? 1 : -1) * (1 << 30);  // to_sub's saturation
}

TEST(FastPaths, RasterIntoACanvasIsTheGenericLoop) {
    const render::PixelFormat formats[] = {render::PixelFormat::rgb565(), render::PixelFormat::bgr565(),
                                           render::PixelFormat::xrgb8888(), render::PixelFormat::xbgr8888(),
                                           render::PixelFormat::rgb888(), render::PixelFormat::bgr888()};
    // Small canvases (the 32-bit paths) and ones over 8192 px on a side (the 64-bit ones).
    const std::pair<int, int> sizes[] = {{61, 37}, {203, 120}, {5, 300}, {9000, 3}, {2, 8300}};
    const render::LineStyle styles[] = {{false, 256}, {false, 100}, {true, 256}, {false, 700}, {true, 600}};
    std::mt19937 rng(7);
    long lines = 0;
    for (const auto& f : formats)
        for (auto [w, h] : sizes) {
            const int bpp = f.bytes_per_pixel();
            const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(w) * bpp + 5;  // odd spare bytes
            // Random bytes under the lines (blends see them) and around the canvas; the lines pile up.
            std::vector<uint8_t> a(static_cast<std::size_t>(stride) * static_cast<std::size_t>(h) + 64);
            for (auto& x : a) x = static_cast<uint8_t>(rng());
            std::vector<uint8_t> b = a;
            const render::Canvas ca(a.data() + 32, w, h, stride, f), cb(b.data() + 32, w, h, stride, f);
            for (int k = 0; k < 300; ++k) {
                const int n = 1 + static_cast<int>(rng() % 6);
                const bool near = rng() % 3 == 0;  // short segments: a polyline on a curve
                render::SubPoint pts[6];
                for (int i = 0; i < n; ++i) {
                    pts[i] = {random_coordinate(rng, w), random_coordinate(rng, h)};
                    if (near && i > 0)
                        pts[i] = {static_cast<int32_t>(std::clamp<int64_t>(int64_t{pts[i - 1].x} + static_cast<int>(rng() % 4096) - 2048, INT32_MIN + 1, INT32_MAX)),
                                  static_cast<int32_t>(std::clamp<int64_t>(int64_t{pts[i - 1].y} + static_cast<int>(rng() % 4096) - 2048, INT32_MIN + 1, INT32_MAX))};
                }
                // Half the polylines on a grid of half pixels: lines through pixel corners and
                // centres, where the error term meets its bound exactly (ties).
                if (rng() % 2)
                    for (int i = 0; i < n; ++i) pts[i].x &= ~127, pts[i].y &= ~127;
                const render::LineStyle style = styles[rng() % 5];
                const bool closed = rng() % 4 == 0;
                const render::Rgb color{static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng())};
                const bool as_line = n == 2 && rng() % 2 == 0;  // with its end point: the open polyline
                // Two lines in three into a row band (a thread's share of draw_world): thin lines
                // past its edges take the 32-bit loop, visit_polyline cuts them exactly in 64 bits.
                render::RowRange rows;
                if (rng() % 3 != 0) {
                    const int a0 = static_cast<int>(rng() % static_cast<uint32_t>(h + 6)) - 3,
                              a1 = static_cast<int>(rng() % static_cast<uint32_t>(h + 6)) - 3;
                    rows = {std::min(a0, a1), std::max(a0, a1) + (rng() % 4 == 0 ? 1 : 0)};
                }
                if (as_line)
                    render::draw_line(ca, pts[0], pts[1], color, style, true, rows);
                else
                    render::draw_polyline(ca, pts, n, closed, color, style, rows);
                VisitInto v{&cb, color};
                render::visit_polyline(w, h, pts, n, closed && !as_line, style, put_visited, &v, rows);
                ASSERT_EQ(a, b) << f.name << " " << w << "x" << h << " line " << k << " n " << n << " (" << pts[0].x << ","
                                << pts[0].y << ") -> (" << pts[n > 1 ? 1 : 0].x << "," << pts[n > 1 ? 1 : 0].y
                                << ") aa " << style.antialias << " width " << style.width << " rows " << rows.y0
                                << ".." << rows.y1;
                ++lines;
            }
        }
    EXPECT_EQ(lines, 6 * 5 * 300);
}

TEST(FastPaths, SpansAreThePixelsOneByOne) {
    std::mt19937 rng(48);
    for (const auto& f : {render::PixelFormat::rgb565(), render::PixelFormat::rgb888(), render::PixelFormat::xrgb8888()}) {
        const int bpp = f.bytes_per_pixel();
        for (int n = 0; n <= 200; ++n)
            for (int start : {0, 1, 3}) {
                const uint32_t word = f.pack({static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng())});
                const int w = start + n + 2;
                std::vector<uint8_t> x(static_cast<std::size_t>(w * bpp), 0x5A), y = x;
                const render::Canvas cy(y.data(), w, 1, w * bpp, f);
                render::detail::fill_span(x.data() + start * bpp, n, render::detail::SpanPattern(word, bpp));
                for (int i = start; i < start + n; ++i) cy.set_word(i, 0, word);
                ASSERT_EQ(x, y) << f.name << " n " << n << " from " << start;
            }
    }
}

}  // namespace
