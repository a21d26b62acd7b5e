// The geometry's fast paths against the arithmetic they replaced: geo::edge_points in fixed
// point bit for bit against the loop it replaced (t = T(k)/T(n), a = u Sf / sfd); walk_end the
// end of walk; the shape cache (geo::ShapeCache) bit for bit the direct computation; the
// adaptive tessellation's halving weight against std::. (How close the drawn curves come to
// the truth: tests/render/test_curves.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "record.hpp"
#include "render/draw_world.hpp"
#include "test_common.hpp"


namespace {

using namespace noneuclid;
using fx::fixed;
using test::kPi;

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
            ASSERT_NEAR(std::remainder(wd.theta - ed.theta, 2 * kPi), 0, 1e-13);
        }
}

// geo::ShapeCache, refreshed when K changes, holds what the direct computation gives, bit
// for bit: to_vec of each local vertex, and for each edge geo::distance of its local end points
// (for ends on one line through the centre, as a grid line's, the difference or sum of their
// distances from it: exact), u = K (d/2)^2 and the halving weight h = SlerpMath::half(u), and
// whether it is walked.
template <class T>
void shape_is_direct(const char* scene_name, double K0) {
    using Math = geo::SlerpMath<T>;
    world::Scene scene;
    ASSERT_TRUE(world::builtin_scene(scene_name, {40, 6, 5}, scene));
    scene.curvature = K0;
    scene.curvature_rate = 0.3;
    world::World<T> w(scene);
    std::vector<geo::ShapeCache<T>> caches;
    render::make_shape_caches(w, caches);
    for (int frame = 0; frame < 4; ++frame) {
        for (std::size_t bi = 0; bi < w.bodies.size(); ++bi) {
            const auto& b = w.bodies[bi];
            const geo::ShapeCache<T>& c = caches[bi].refresh(w.K, b);
            ASSERT_TRUE(c.valid);
            ASSERT_EQ(c.K, w.K);
            const std::size_t n = b.local.size(), edges = c.walked.size();
            for (std::size_t i = 0; i < n; ++i) {
                const geo::Vec3<T> v = geo::to_vec(w.K, b.local[i]);
                ASSERT_EQ(c.local[i].w, v.w);
                ASSERT_EQ(c.local[i].x, v.x);
                ASSERT_EQ(c.local[i].y, v.y);
            }
            using geo::Sf;  // and fx::Sf by ADL
            for (std::size_t e = 0; e < edges; ++e) {
                const geo::Polar<T>&p = b.local[e], &q = b.local[(e + 1) % n];
                const double dp = static_cast<double>(p.theta) - static_cast<double>(q.theta);
                const bool same = p.theta == q.theta && p.r != T(0) && q.r != T(0);
                const bool opposite = p.r == T(0) || q.r == T(0) || std::fabs(dp) == static_cast<double>(geo::pi_v<T>);
                // Along a line through the centre: exactly; else geo::distance, bit for bit.
                const T d = same ? (p.r > q.r ? p.r - q.r : q.r - p.r) : opposite ? p.r + q.r : geo::distance(w.K, p, q);
                ASSERT_EQ(c.length[e], d) << scene_name << " edge " << e;
                ASSERT_EQ(c.u[e], Math::u_of(w.K, d)) << scene_name << " edge " << e;
                const bool walked = Math::too_long(c.u[e]) || geo::antipodal_edge(w.K, d, Sf(w.K * d * d));
                ASSERT_EQ(c.walked[e] != 0, walked) << scene_name << " edge " << e;
                if (!walked) {
                    ASSERT_EQ(c.h[e], Math::half(c.u[e])) << scene_name << " edge " << e;
                }
            }
        }
        w.press(world::Action::curvature_up);  // K changes: the next refresh recomputes
        w.step(0.1);
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

// The halving weight h(u) = 1 / (2 Cf(u)) (SlerpMath::half: the secant's series near 0, the
// cosine's series and a division beyond) against std:: in long double, over the u the cache
// gives it (|u| up to the walked limit), relative: fixed within 2e-8 (a few units of its Q30,
// times the condition of 1 / Cf where Cf nears 1/8), float within 1e-6 (cos near pi/2 / 1.1),
// double within 1e-15.
TEST(FastPaths, HalvingWeightIsTheSecant) {
    double worst_fixed = 0, worst_float = 0, worst_double = 0;
    for (int i = -2200; i <= 2080; ++i) {
        const double u = i / 1000.0;
        const long double s = std::sqrt(std::fabs(static_cast<long double>(u)));
        const long double want = 0.5L / (u >= 0 ? std::cos(s) : std::cosh(s));
        const int64_t uq = std::llround(u * 1073741824.0);
        const double fx_h = static_cast<double>(geo::SlerpMath<fixed>::half(uq)) / 1073741824.0;
        const long double exact_q = 0.5L / (uq >= 0 ? std::cos(std::sqrt(uq / 1073741824.0L)) : std::cosh(std::sqrt(-uq / 1073741824.0L)));
        worst_fixed = std::max(worst_fixed, static_cast<double>(std::fabs(fx_h - exact_q) / exact_q));
        worst_float = std::max(worst_float, static_cast<double>(std::fabs(geo::SlerpMath<float>::half(static_cast<float>(u)) - want) / want));
        worst_double = std::max(worst_double, static_cast<double>(std::fabs(geo::SlerpMath<double>::half(u) - want) / want));
    }
    ::noneuclid_test_record("halving weight, worst relative error: fixed %.3g, float %.3g, double %.3g\n", worst_fixed,
                            worst_float, worst_double);
    EXPECT_LE(worst_fixed, 2e-8);
    EXPECT_LE(worst_float, 1e-6);
    EXPECT_LE(worst_double, 1e-15);
}

}  // namespace
