// The uneven world's metric and geodesics (src/uneven, docs/uneven.md): psi's derivatives
// against finite differences, the chart's curvature; with no bumps a body follows the closed
// form of the world of constant K (tests/uneven/constant_k_model.hpp, long double) within 1e-9
// after 10^4 steps; Gauss-Bonnet for geodesic triangles among bumps; Clairaut's invariant about
// a bump at O.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "constant_k_model.hpp"
#include "test_common.hpp"
#include "uneven/geodesic.hpp"

namespace {
namespace uneven_test {  // (a unity batch shares this file's scope with others)

using namespace noneuclid;
using uneven::Bump;
using uneven::BumpKind;
using uneven::Geodesic;
using uneven::Metric;
using uneven::Vec2;

constexpr double kPi = test::kPi;

double wrap(double a) { return std::remainder(a, 2 * kPi); }

Metric bumped(double K) {
    Metric m;
    m.K = K;
    m.bumps[0] = {BumpKind::hill, {0.4, 0.1}, 0.35, 0.6};
    m.bumps[1] = {BumpKind::hill, {-0.3, 0.35}, 0.3, -0.4};
    m.bumps[2] = {BumpKind::mass, {0.05, -0.45}, 0.2, 0.3};
    m.bump_count = 3;
    return m;
}

TEST(Uneven, PsisDerivativesAreItsFiniteDifferencesAndTheChartHasCurvatureK) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-0.9, 0.9);
    for (double K : {-1.0, -0.3, 0.0, 0.5, 1.0}) {
        const Metric plain{K};
        const Metric m = bumped(K);
        for (int i = 0; i < 200; ++i) {
            const Vec2 x{u(rng), u(rng)};
            EXPECT_NEAR(plain.curvature(x), K, 1e-12) << x.x << "," << x.y;
            const double h = 1e-4;
            const auto psi = [&m](Vec2 p) { return m.at(p).psi; };
            const uneven::MetricAt at = m.at(x);
            const double gx = (psi({x.x + h, x.y}) - psi({x.x - h, x.y})) / (2 * h);
            const double gy = (psi({x.x, x.y + h}) - psi({x.x, x.y - h})) / (2 * h);
            const double lap = (psi({x.x + h, x.y}) + psi({x.x - h, x.y}) + psi({x.x, x.y + h}) + psi({x.x, x.y - h})
                                - 4 * at.psi) / (h * h);
            EXPECT_NEAR(at.grad.x, gx, 1e-7);
            EXPECT_NEAR(at.grad.y, gy, 1e-7);
            EXPECT_NEAR(at.laplacian, lap, 2e-4 * (1 + std::fabs(lap)));
        }
    }
}

// With no bumps, 10^4 steps of 1/60 s: the chart point within 1e-9 world units of the closed
// form, the heading within 1e-9 radians. Speeds keep each path where the chart resolves it
// (K < 0: a few units from O; K > 0: round the sphere eight times, clear of the antipode).
TEST(Uneven, WithoutBumpsABodyFollowsTheClosedFormOfConstantK) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> angle(-kPi, kPi), radius(0.0, 0.8);
    double worst_x = 0, worst_phi = 0;
    for (double K : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
        const Metric m{K};
        for (int c = 0; c < 6; ++c) {
            const double th = angle(rng), r = K > 0 ? 0.9 / std::sqrt(K) : radius(rng);
            const double rho = uneven::chart_radius(K, r);
            // K > 0: at right angles to the radius, so the great circle keeps 0.9 R from the antipode.
            const double phi = K > 0 ? th + kPi / 2 : angle(rng);
            const double s = K > 0 ? 0.3 : 0.015;
            Geodesic g{{rho * std::cos(th), rho * std::sin(th)}, phi};
            const test::ModelGeodesic ref = test::ModelGeodesic::from_chart(K, g.x.x, g.x.y, phi);
            const int steps = 10000;
            for (int i = 0; i < steps; ++i) g = uneven::step(m, g, s, 1.0 / 60);
            long double x, y, p;
            ref.chart_at(static_cast<long double>(s) * steps / 60, x, y, p);
            // World distance of two nearby chart points: e^psi times their chart distance.
            const double world = std::exp(m.at(g.x).psi) * std::hypot(g.x.x - double(x), g.x.y - double(y));
            const double dphi = std::fabs(wrap(g.phi - double(p)));
            worst_x = std::max(worst_x, world), worst_phi = std::max(worst_phi, dphi);
            EXPECT_LE(world, 1e-9) << "K " << K << " case " << c;
            EXPECT_LE(dphi, 1e-9) << "K " << K << " case " << c;
        }
    }
    std::printf("uneven, no bumps, 10^4 steps: worst %.2g world units, %.2g rad from the closed form\n",
                            worst_x, worst_phi);
}

// A geodesic from `from` to `to` (shooting: Newton on the heading and the length), or false.
bool shoot(const Metric& m, Vec2 from, Vec2 to, double& phi, double& length) {
    const Vec2 d = to - from;
    phi = std::atan2(d.y, d.x);
    length = std::exp(m.at(0.5 * (from + to)).psi) * std::hypot(d.x, d.y);
    for (int it = 0; it < 30; ++it) {
        const Vec2 e = uneven::exp_map(m, from, phi, length).x - to;
        if (std::hypot(e.x, e.y) < 1e-13) return true;
        const double h = 1e-7;
        const Vec2 a = (1 / h) * (uneven::exp_map(m, from, phi + h, length).x - to - e);
        const Vec2 b = (1 / h) * (uneven::exp_map(m, from, phi, length + h).x - to - e);
        const double det = cross(a, b);  // [a b] (dphi, dlength) = -e
        // Damped: at most 0.2 rad and a fifth of the length a step, the length kept positive.
        const double dphi = -cross(e, b) / det, dlength = -cross(a, e) / det;
        const double k = std::min({1.0, 0.2 / std::fabs(dphi), 0.2 * length / std::fabs(dlength)});
        phi += k * dphi;
        length += k * dlength;
    }
    return false;
}

// The chart points of a geodesic, n + 1 of them, and its heading at the end.
std::vector<Vec2> trace(const Metric& m, Vec2 from, double phi, double length, int n, double& end_phi) {
    std::vector<Vec2> out{from};
    Geodesic g{from, phi};
    for (int i = 0; i < n; ++i) out.push_back((g = uneven::step(m, g, 1.0, length / n)).x);
    end_phi = g.phi;
    return out;
}

// Gauss-Bonnet: a geodesic triangle's angle sum less pi is the curvature it holds, which is
// -(the flux of grad psi out through its edge) by the divergence theorem, summed along the traced
// sides. The angles come from the headings the integrator carries, the flux from where it puts
// the points: a wrong turning rate (a sign, a factor) breaks the equality.
TEST(Uneven, AGeodesicTrianglesAngleExcessIsTheCurvatureItHolds) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-0.5, 0.5), a(-kPi, kPi), len(0.3, 0.8), open(0.6, 2.2);
    int checked = 0;
    double worst = 0, largest = 0;
    for (double K : {-0.6, 0.0, 0.4})
        for (int c = 0; c < 8; ++c) {
            const Metric m = bumped(K);
            const Vec2 A{u(rng), u(rng)};
            const double t1 = a(rng), t2 = t1 + open(rng);  // counter-clockwise: A, B, C
            const double lAB = len(rng), lAC = len(rng);
            const Vec2 B = uneven::exp_map(m, A, t1, lAB).x, C = uneven::exp_map(m, A, t2, lAC).x;
            double tBC, lBC;
            ASSERT_TRUE(shoot(m, B, C, tBC, lBC)) << "K " << K << " case " << c;
            const int n = 4000;
            double endAB, endBC, endCA;
            const std::vector<Vec2> ab = trace(m, A, t1, lAB, n, endAB);
            const std::vector<Vec2> bc = trace(m, B, tBC, lBC, n, endBC);
            double tCA, lCA;
            ASSERT_TRUE(shoot(m, C, A, tCA, lCA));
            const std::vector<Vec2> ca = trace(m, C, tCA, lCA, n, endCA);
            // Interior angles: between the side leaving a vertex and the reverse of the one arriving.
            const double angA = std::fabs(wrap(t2 - t1));
            const double angB = std::fabs(wrap(tBC - (endAB + kPi)));
            const double angC = std::fabs(wrap(tCA - (endBC + kPi)));
            const double excess = angA + angB + angC - kPi;
            // The flux, by the trapezoid rule on each side (counter-clockwise: the outward normal
            // is the tangent turned clockwise).
            double flux = 0;
            for (const std::vector<Vec2>* side : {&ab, &bc, &ca})
                for (std::size_t i = 0; i + 1 < side->size(); ++i) {
                    const Vec2 p = (*side)[i], q = (*side)[i + 1], d = q - p;
                    const Vec2 g = 0.5 * (m.at(p).grad + m.at(q).grad);
                    flux += g.x * d.y - g.y * d.x;  // grad psi . (d turned clockwise)
                }
            const double holds = -flux;
            worst = std::max(worst, std::fabs(excess - holds));
            largest = std::max(largest, std::fabs(holds));
            EXPECT_NEAR(excess, holds, 1e-6) << "K " << K << " case " << c;
            ++checked;
        }
    EXPECT_GT(largest, 0.1);  // (not vacuous: the triangles hold curvature)
    std::printf("uneven, Gauss-Bonnet over %d triangles among bumps: worst |excess - integral of K| %.2g "
                            "(the largest integral %.3f)\n", checked, worst, largest);
}

// Clairaut: about a metric symmetric about O, a geodesic keeps e^psi (x cross its direction).
TEST(Uneven, ClairautsInvariantHoldsAboutABumpAtO) {
    for (double K : {-0.5, 0.0, 0.5}) {
        Metric m;
        m.K = K;
        m.bumps[0] = {BumpKind::hill, {0, 0}, 0.4, 0.5};
        m.bumps[1] = {BumpKind::mass, {0, 0}, 0.25, 0.2};
        m.bump_count = 2;
        Geodesic g{{0.6, -0.1}, 2.0};
        const auto invariant = [&m](const Geodesic& b) {
            return std::exp(m.at(b.x).psi) * cross(b.x, Vec2{std::cos(b.phi), std::sin(b.phi)});
        };
        const double L0 = invariant(g);
        double worst = 0;
        for (int i = 0; i < 10000; ++i) {
            g = uneven::step(m, g, 0.05, 1.0 / 60);
            worst = std::max(worst, std::fabs(invariant(g) - L0));
        }
        EXPECT_LE(worst, 1e-9) << "K " << K;
        EXPECT_GT(std::fabs(L0), 0.05);  // (not vacuous: the geodesic misses O)
    }
}

}  // namespace uneven_test
}  // namespace
