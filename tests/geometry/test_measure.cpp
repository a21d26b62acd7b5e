// The instruments' readings (geometry/measure.hpp) against the tests' own geometry in long
// double, by another route: points as 3-vectors on the unit sphere (K > 0) or the unit
// hyperboloid (K < 0), lengths from chords, angles from unit tangent vectors, a triangle's area
// from the determinant of its vertices (tan(E/2) = |det| / (1 + cos a + cos b + cos c) on the
// sphere, with cosh on the hyperboloid), the parallels walked as explicit geodesics and the
// polygons built vertex by vertex. Within 1e-9 (degrees, world units, world units squared) for
// |K| >= 1e-3, where the embedding keeps its digits; at K = 0 the plane's answers; between, the
// readings are finite and Gauss-Bonnet holds to 1e-9 degrees.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/measure.hpp"
#include "test_common.hpp"

namespace noneuclid {
namespace {

using geo::Polar;
using LD = long double;
constexpr LD kPiL = 3.141592653589793238462643383279502884L;
constexpr double kTol = 1e-9;

struct V3 {
    LD w, x, y;
};
V3 operator-(V3 a, V3 b) { return {a.w - b.w, a.x - b.x, a.y - b.y}; }
V3 operator+(V3 a, V3 b) { return {a.w + b.w, a.x + b.x, a.y + b.y}; }
V3 operator*(LD s, V3 a) { return {s * a.w, s * a.x, s * a.y}; }

// The model of curvature K (K != 0): the unit sphere or hyperboloid, lengths scaled by k = sqrt|K|.
struct Model {
    LD K, k;
    bool sphere;
    explicit Model(double K_) : K(K_), k(std::sqrt(std::fabs(static_cast<LD>(K_)))), sphere(K_ > 0) {}
    LD S(LD x) const { return sphere ? std::sin(x) : std::sinh(x); }
    LD C(LD x) const { return sphere ? std::cos(x) : std::cosh(x); }
    LD dot(V3 a, V3 b) const { return (sphere ? a.w * b.w : -a.w * b.w) + a.x * b.x + a.y * b.y; }
    V3 point(Polar<double> p) const {
        const LD rho = k * p.r, t = p.theta;
        return {C(rho), S(rho) * std::cos(t), S(rho) * std::sin(t)};
    }
    // The geodesic distance, from the chord (stable at any length short of the antipode).
    LD distance(V3 a, V3 b) const {
        const LD chord = std::sqrt(std::fabs(dot(a - b, a - b)));
        return 2 * (sphere ? std::asin(std::min<LD>(chord / 2, 1)) : std::asinh(chord / 2)) / k;
    }
    // The unit tangent at a toward b.
    V3 toward(V3 a, V3 b) const {
        const V3 t = b - (dot(a, b) / dot(a, a)) * a;
        return (1 / std::sqrt(dot(t, t))) * t;
    }
    // The angle at a between the directions toward b and c.
    LD angle(V3 a, V3 b, V3 c) const {
        const V3 u = toward(a, b), v = toward(a, c);
        const V3 d = u - v, s = u + v;
        return 2 * std::atan2(std::sqrt(std::fabs(dot(d, d))), std::sqrt(std::fabs(dot(s, s))));
    }
    // A triangle's area from its vertices' determinant.
    LD area(V3 a, V3 b, V3 c) const {
        const LD det = a.w * (b.x * c.y - b.y * c.x) - a.x * (b.w * c.y - b.y * c.w) + a.y * (b.w * c.x - b.x * c.w);
        const LD ca = sphere ? dot(a, b) + dot(b, c) + dot(c, a) : -(dot(a, b) + dot(b, c) + dot(c, a));
        return 2 * std::atan2(std::fabs(det), 1 + ca) / (k * k);
    }
};

LD deg(LD rad) { return rad * 180 / kPiL; }

// The triangles: marks (r, theta in degrees) in the limit circle of radius pi.
const std::vector<std::vector<Polar<double>>> kTriangles = {
    {{1, test::deg(90)}, {1, test::deg(210)}, {1, test::deg(330)}},
    {{0, 0}, {0.5, 0}, {0.7, test::deg(80)}},
    {{0.3, test::deg(10)}, {1.9, test::deg(-40)}, {1.2, test::deg(150)}},
    {{2.2, test::deg(0)}, {2.0, test::deg(120)}, {2.4, test::deg(240)}},  // large: on the sphere, past a hemisphere's worth
    {{0.01, 0}, {0.02, test::deg(90)}, {0.015, test::deg(200)}},           // small
};
const double kCurvatures[] = {-1, -0.5, -0.1, -0.01, -1e-3, 1e-3, 0.01, 0.1, 0.5, 1};

TEST(Measure, TriangleAgreesWithTheEmbeddingsAnglesAndDeterminantArea) {
    for (double K : kCurvatures)
        for (const auto& tri : kTriangles) {
            geo::TriangleReading t;
            ASSERT_EQ(geo::measure_triangle(K, tri.data(), test::kPi, t), geo::MeasureError::none) << K;
            const Model m(K);
            const V3 v[3] = {m.point(tri[0]), m.point(tri[1]), m.point(tri[2])};
            LD sum = 0;
            for (int i = 0; i < 3; ++i) {
                const LD side = m.distance(v[(i + 1) % 3], v[(i + 2) % 3]);
                const LD angle = deg(m.angle(v[i], v[(i + 1) % 3], v[(i + 2) % 3]));
                EXPECT_NEAR(t.side[i], static_cast<double>(side), kTol) << "K " << K << " side " << i;
                EXPECT_NEAR(t.angle_deg[i], static_cast<double>(angle), kTol) << "K " << K << " angle " << i;
                sum += angle;
            }
            EXPECT_NEAR(t.sum_deg, static_cast<double>(sum), kTol) << K;
            EXPECT_NEAR(t.excess_deg, static_cast<double>(sum - 180), kTol) << K;
            const LD area = m.area(v[0], v[1], v[2]);
            EXPECT_NEAR(t.area, static_cast<double>(area), kTol * std::max<double>(1, static_cast<double>(area))) << K;
            EXPECT_NEAR(t.k_area_deg, t.excess_deg, kTol) << K;  // Gauss-Bonnet, by the two routes
        }
}

TEST(Measure, TriangleAtKZeroIsThePlanesAndGaussBonnetHoldsThroughIt) {
    for (const auto& tri : kTriangles) {
        geo::TriangleReading t;
        ASSERT_EQ(geo::measure_triangle(0, tri.data(), test::kPi, t), geo::MeasureError::none);
        LD x[3], y[3];
        for (int i = 0; i < 3; ++i) x[i] = tri[i].r * std::cos(static_cast<LD>(tri[i].theta)), y[i] = tri[i].r * std::sin(static_cast<LD>(tri[i].theta));
        const LD area = std::fabs((x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0])) / 2;
        EXPECT_NEAR(t.area, static_cast<double>(area), kTol);
        EXPECT_NEAR(t.sum_deg, 180, kTol);
        EXPECT_EQ(t.k_area_deg, 0);
        // Towards 0 from either side: finite, continuous, and excess = K area.
        for (double K : {1e-300, -1e-300, 1e-15, -1e-15, 1e-9, -1e-9, 1e-6, -1e-6}) {
            geo::TriangleReading s;
            ASSERT_EQ(geo::measure_triangle(K, tri.data(), test::kPi, s), geo::MeasureError::none) << K;
            EXPECT_TRUE(std::isfinite(s.area) && std::isfinite(s.excess_deg)) << K;
            EXPECT_NEAR(s.area, t.area, 1e-5 * std::fabs(K) / 1e-6 + 1e-12) << K;
            EXPECT_NEAR(s.k_area_deg, s.excess_deg, kTol) << K;
        }
    }
}

TEST(Measure, CircleAgreesWithTheTestsOwnTrigonometry) {
    for (double K : kCurvatures)
        for (double rho : {0.1, 0.5, 1.0, 2.0, 3.0}) {
            geo::CircleReading c;
            ASSERT_EQ(geo::measure_circle(K, {0.5, 1}, rho, test::kPi, c), geo::MeasureError::none) << K << " " << rho;
            const Model m(K);
            const LD x = m.k * rho;
            const LD circ = 2 * kPiL * m.S(x) / m.k;
            const LD area = 2 * kPiL * (m.sphere ? 1 - std::cos(x) : std::cosh(x) - 1) / (m.k * m.k);  // the cap's area
            EXPECT_NEAR(c.circumference, static_cast<double>(circ), kTol * std::max<double>(1, c.circumference)) << K << " " << rho;
            EXPECT_NEAR(c.area, static_cast<double>(area), kTol * std::max<double>(1, c.area)) << K << " " << rho;
            EXPECT_NEAR(c.circumference_ratio, static_cast<double>(circ / (2 * kPiL * rho)), kTol) << K;
            EXPECT_NEAR(c.area_ratio, static_cast<double>(area / (kPiL * rho * rho)), kTol) << K;
            EXPECT_EQ(c.circumference_ratio < 1, K > 0) << K;  // short of 2 pi rho on the sphere, past it in H
        }
    geo::CircleReading flat;
    ASSERT_EQ(geo::measure_circle(0, {0, 0}, 1.5, test::kPi, flat), geo::MeasureError::none);
    EXPECT_DOUBLE_EQ(flat.circumference, 2 * test::kPi * 1.5);
    EXPECT_DOUBLE_EQ(flat.area, test::kPi * 2.25);
}

// Two geodesics leaving the common perpendicular through O (marks at (d/2, +-90 degrees)) in
// the direction of +x, walked explicitly: P(s) = C(ks) A + S(ks) T.
TEST(Measure, ParallelsAgreeWithTwoGeodesicsWalkedInTheEmbedding) {
    for (double K : kCurvatures)
        for (double d : {0.2, 0.5, 1.0})
            for (double s : {0.0, 0.5, 1.0, 1.5, 2.5}) {
                geo::ParallelsReading p;
                ASSERT_EQ(geo::measure_parallels(K, d, s, p), geo::MeasureError::none) << K;
                const Model m(K);
                const V3 A = m.point({d / 2, test::kPi / 2}), B = m.point({d / 2, -test::kPi / 2}), T{0, 1, 0};
                const LD ks = m.k * s;
                const V3 PA = m.C(ks) * A + m.S(ks) * T, PB = m.C(ks) * B + m.S(ks) * T;
                const LD apart = m.distance(PA, PB);
                EXPECT_NEAR(p.distance, static_cast<double>(apart), kTol * std::max<double>(1, p.distance)) << K << " " << d << " " << s;
                if (s > 0.1) {
                    EXPECT_EQ(p.distance < d, K > 0) << K;  // closer on the sphere, apart in H
                }
            }
    geo::ParallelsReading flat;
    ASSERT_EQ(geo::measure_parallels(0, 0.5, 2, flat), geo::MeasureError::none);
    EXPECT_DOUBLE_EQ(flat.distance, 0.5);
    geo::ParallelsReading meet;
    ASSERT_EQ(geo::measure_parallels(1, 0.5, test::kPi / 2, meet), geo::MeasureError::none);
    EXPECT_NEAR(meet.distance, 0, 1e-12);
    EXPECT_NEAR(meet.meet_at, test::kPi / 2, 1e-15);
}

// A regular p-gon of side a about O, built in the embedding: its circumradius found by bisection
// on the side, its interior angle from the tangents at a vertex.
LD polygon_angle(const Model& m, int p, LD a) {
    auto vertex = [&](LD rho, int i) { return m.point({static_cast<double>(rho), 2 * test::kPi * i / p}); };
    LD lo = 0, hi = m.sphere ? kPiL / m.k : 50;
    for (int it = 0; it < 200; ++it) {
        const LD mid = (lo + hi) / 2;
        (m.distance(vertex(mid, 0), vertex(mid, 1)) < a ? lo : hi) = mid;
    }
    const LD rho = (lo + hi) / 2;
    return deg(m.angle(vertex(rho, 0), vertex(rho, 1), vertex(rho, p - 1)));
}

TEST(Measure, PolygonsAgreeWithPolygonsBuiltVertexByVertex) {
    struct Case {
        int p, q;
        double a;
    };
    for (const Case c : {Case{3, 7, 1.2}, Case{3, 5, 1.2}, Case{4, 5, 1.0}, Case{5, 4, 1.0}, Case{3, 6, 1.0}, Case{6, 3, 0.8}})
        for (double K : kCurvatures) {
            geo::PolygonReading r;
            const geo::MeasureError e = geo::measure_polygon(K, c.p, c.q, c.a, r);
            if (e == geo::MeasureError::polygon) continue;  // too large a polygon for that sphere
            // (Those that close at no K in [-1, 1] are refused, with their angle and gap read.)
            ASSERT_TRUE(e == geo::MeasureError::none || e == geo::MeasureError::never_closes) << c.p << " " << c.q << " K " << K;
            const Model m(K);
            const LD angle = polygon_angle(m, c.p, c.a);
            EXPECT_NEAR(r.angle_deg, static_cast<double>(angle), kTol) << c.p << " " << c.q << " K " << K;
            EXPECT_NEAR(r.gap_deg, static_cast<double>(360 - c.q * angle), 10 * kTol) << c.p << " " << c.q << " K " << K;
        }
    // The closing K, found by bisection on the built polygons' gap (the flat tilings close at 0).
    for (const Case c : {Case{3, 7, 1.2}, Case{3, 5, 1.2}, Case{4, 5, 1.6}, Case{3, 6, 1.0}, Case{4, 4, 1.0}}) {
        geo::PolygonReading r;
        ASSERT_EQ(geo::measure_polygon(0.3, c.p, c.q, c.a, r), geo::MeasureError::none) << c.p << " " << c.q;
        auto gap = [&](LD K) {
            if (std::fabs(K) < 1e-30L) return 360 - c.q * 180 * (1 - 2.0L / c.p);
            return 360 - c.q * polygon_angle(Model(static_cast<double>(K)), c.p, c.a);
        };
        LD lo = -1, hi = 1;  // the gap falls as K rises (angles grow on the sphere)
        for (int it = 0; it < 80; ++it) {
            const LD mid = (lo + hi) / 2;
            (gap(mid) > 0 ? lo : hi) = mid;
        }
        EXPECT_NEAR(r.closing_K, static_cast<double>((lo + hi) / 2), 1e-9) << c.p << " " << c.q;
        EXPECT_EQ(r.closing_K < -1e-12, c.p * c.q > 2 * (c.p + c.q)) << c.p << " " << c.q;  // hyperbolic exactly when 1/p + 1/q < 1/2
    }
}

TEST(Measure, BadConstructionsAreErrorsNeverNaN) {
    const Polar<double> same[3] = {{1, 0}, {1, 0}, {0.5, 1}};
    const Polar<double> line[3] = {{0.5, 0}, {1, 0}, {1.5, 0}};
    const Polar<double> out[3] = {{0.5, 0}, {4, 0}, {1.5, 1}};
    geo::TriangleReading t;
    EXPECT_EQ(geo::measure_triangle(0.5, same, test::kPi, t), geo::MeasureError::coincident);
    EXPECT_EQ(geo::measure_triangle(-0.5, line, test::kPi, t), geo::MeasureError::collinear);
    EXPECT_EQ(geo::measure_triangle(0, out, test::kPi, t), geo::MeasureError::outside);
    geo::CircleReading c;
    EXPECT_EQ(geo::measure_circle(0, {0, 0}, -1, test::kPi, c), geo::MeasureError::radius);
    EXPECT_EQ(geo::measure_circle(1, {0, 0}, 3.5, test::kPi, c), geo::MeasureError::radius);  // past the antipode
    EXPECT_EQ(geo::measure_circle(1, {0, 0}, NAN, test::kPi, c), geo::MeasureError::radius);
    geo::ParallelsReading p;
    EXPECT_EQ(geo::measure_parallels(0, 0, 1, p), geo::MeasureError::radius);
    geo::PolygonReading r;
    EXPECT_EQ(geo::measure_polygon(0, 3, 7, 0.1, r), geo::MeasureError::never_closes);  // closes near K = -100
    EXPECT_EQ(geo::measure_polygon(0, 2, 7, 1, r), geo::MeasureError::polygon);
    for (const char* s : {geo::measure_error_sentence(geo::MeasureError::outside),
                          geo::measure_error_sentence(geo::MeasureError::never_closes)})
        EXPECT_GT(std::string(s).size(), 20u);
}

}  // namespace
}  // namespace noneuclid
