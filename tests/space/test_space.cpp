// src/space against the tests' own model in long double (tests/space/embedding.hpp), and flat
// E³ at K = 0 with straight lines. The engine runs in double.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "embedding.hpp"
#include "space/view.hpp"

namespace {
namespace space_test {  // (a unity batch shares this file's scope with others)

using namespace noneuclid;
using namespace space_embedding;

// Random points within `reach` of O and random unit vectors, the same each run.
struct Draw {
    std::mt19937_64 rng{20261207};
    V3<double> direction() {
        std::normal_distribution<double> n;
        return space::unit(V3<double>{n(rng), n(rng), n(rng)});
    }
    Point<double> point(double reach) { return {std::uniform_real_distribution<double>(0, reach)(rng), direction()}; }
};

constexpr double kCurved[] = {-1, -0.5, 0.5, 1};

TEST(Space, TheModelRoundTripsAndItsDistanceIsTheEmbeddings) {
    Draw d;
    double worst = 0;
    for (const double K : kCurved)
        for (int i = 0; i < 2000; ++i) {
            const Point<double> p = d.point(K > 0 ? 3.0 / std::sqrt(K) : 3), q = d.point(K > 0 ? 3.0 / std::sqrt(K) : 3);
            const Point<double> back = space::to_point(K, space::to_v4(K, p));
            EXPECT_NEAR(back.r, p.r, 1e-12);
            const LD ref = ref_distance(K, embed(K, p), embed(K, q));
            if (ref < 1e-3) continue;  // (acos and acosh lose digits there: the next test's)
            worst = std::max(worst, static_cast<double>(std::fabs(space::distance(K, p, q) - ref)));
        }
    EXPECT_LT(worst, 1e-12);
    char figure[32];
    std::snprintf(figure, sizeof figure, "%.3g", worst);
    RecordProperty("worst_distance_error", figure);
}

// Short distances, where the haversine form keeps its digits: against the flat distance of two
// points close together, scaled by the embedding's own (the chord's length in the form).
TEST(Space, ShortDistancesAndKThroughZero) {
    Draw d;
    for (int i = 0; i < 500; ++i) {
        const Point<double> p = d.point(2);
        const V3<double> v = d.direction();
        const space::Walk<double> w = space::walk(0.0, p, v, 1e-6);
        // Flat: the straight line's end is p + 1e-6 v exactly.
        const V3<double> end = space::map_position(w.end), start = space::map_position(p);
        EXPECT_LT(space::norm(end - (start + 1e-6 * v)), 1e-15);
        for (const double K : kCurved)  // (to 1e-9 of itself: the points' coordinates are near 1)
            EXPECT_NEAR(space::distance(K, p, space::walk(K, p, v, 1e-6).end), 1e-6, 1e-14);
        // K = +-1e-9 is K = 0 within 1e-8.
        const Point<double> q = d.point(2);
        for (const double K : {1e-9, -1e-9}) EXPECT_NEAR(space::distance(K, p, q), space::distance(0.0, p, q), 1e-8);
    }
}

// A walk's end, direction of travel and a carried frame against the embedding's geodesic and its
// parallel transport: F(t) = F - g(F, V) V + g(F, V) V', V' = -K S(t) P + C(t) V.
TEST(Space, AWalkAndItsCarriedFrameAreTheEmbeddingsGeodesicAndTransport) {
    Draw d;
    double worst_end = 0, worst_dir = 0, worst_frame = 0;
    for (const double K : kCurved)
        for (int i = 0; i < 2000; ++i) {
            const Point<double> p = d.point(2.5);
            const V3<double> v = d.direction(), f = d.direction();
            const double s = std::uniform_real_distribution<double>(0, 2.5)(d.rng);
            const space::Walk<double> w = space::walk(K, p, v, s);
            const R4 P = embed(K, p), V = tangent(K, p, v), F = tangent(K, p, f);
            const R4 Q = C(K, s) * P + S(K, s) * V;
            const R4 Vq = (-K * S(K, s)) * P + C(K, s) * V;
            const LD along = g(K, F, V);
            const R4 Fq = F + (-along) * V + along * Vq;
            const R4 E = embed(K, w.end);
            const LD dw = E.w - Q.w, dx = E.x - Q.x, dy = E.y - Q.y, dz = E.z - Q.z;
            // (relative to the point's size: far out in H³ the embedding's coordinates grow as cosh r)
            worst_end = std::max(worst_end, static_cast<double>(std::sqrt(dw * dw + dx * dx + dy * dy + dz * dz) / std::sqrt(Q.w * Q.w + Q.x * Q.x + Q.y * Q.y + Q.z * Q.z)));
            if (std::sqrt(Q.x * Q.x + Q.y * Q.y + Q.z * Q.z) < 1e-3) continue;  // (at O the carried frame is any)
            worst_dir = std::max(worst_dir, static_cast<double>(gap(carried(K, Q, Vq), w.heading)));
            worst_frame = std::max(worst_frame, static_cast<double>(gap(carried(K, Q, Fq), space::carry(w, f))));
        }
    EXPECT_LT(worst_end, 1e-13);
    EXPECT_LT(worst_dir, 1e-11);
    EXPECT_LT(worst_frame, 1e-11);
    char figure[32];
    std::snprintf(figure, sizeof figure, "%.3g", worst_end);
    RecordProperty("worst_end", figure);
}

// A body flown for 10^4 steps keeps an orthonormal, right-handed frame; on S³ (K = 1) a flight of
// 2 pi comes back to its start, facing as it did; in flat space it flies straight.
TEST(Space, ALongFlightKeepsItsFrameAndCloses) {
    for (const double K : {-1.0, 0.0, 1.0}) {
        Point<double> p{0.7, space::unit(V3<double>{1, 2, 3})};
        space::Frame<double> f = space::orthonormal(space::Frame<double>{space::unit(V3<double>{0.3, -1, 0.2}), {0, 0, 1}, {}});
        const Point<double> start = p;
        const space::Frame<double> f0 = f;
        const int steps = 10000;
        const double step = 2 * 3.14159265358979323846 / steps;
        V3<double> travel = f.forward;  // (it travels where it faces)
        for (int i = 0; i < steps; ++i) space::fly(K, p, travel, f, step);
        EXPECT_NEAR(space::dot(f.forward, f.up), 0, 1e-14);
        EXPECT_NEAR(space::norm(f.forward), 1, 1e-14);
        EXPECT_NEAR(space::dot(space::cross(f.forward, f.up), f.right), 1, 1e-14);
        if (K == 1) {
            EXPECT_LT(space::distance(K, p, start), 1e-9) << "a great circle closes";
            EXPECT_LT(space::norm(f.forward - f0.forward), 1e-8);
            EXPECT_LT(space::norm(f.up - f0.up), 1e-8);
        }
        if (K == 0) {
            const V3<double> end = space::map_position(p), expect = space::map_position(start) + 2 * 3.14159265358979323846 * f0.forward;
            EXPECT_LT(space::norm(end - expect), 1e-9);  // (8.7e-11 measured: 10^4 steps' rounding)
        }
    }
}

// The inhabitant's view: the bearing toward q, walked for the distance, reaches q; in S³ the
// opposite bearing, walked the rest of the great circle, reaches q too; in H³ a segment of length
// L across the line of sight at distance D subtends tan(a) = tanh(L) / sinh(D) (the right
// triangle's law), so its size falls by e per unit of distance far away.
TEST(Space, TheInhabitantSeesAlongGeodesics) {
    Draw d;
    for (const double K : {-1.0, -0.5, 0.0, 0.5, 1.0})
        for (int i = 0; i < 300; ++i) {
            const Point<double> p = d.point(1.2), q = d.point(1.2);
            const double dist = space::distance(K, p, q);
            if (dist < 1e-3) continue;
            const V3<double> b = space::bearing(K, p, q);
            EXPECT_LT(space::distance(K, space::walk(K, p, b, dist).end, q), 1e-11);
            if (K > 0) {
                const double rest = 2 * 3.14159265358979323846 / std::sqrt(K) - dist;
                EXPECT_LT(space::distance(K, space::walk(K, p, -1.0 * b, rest).end, q), 1e-10);
            }
        }
    const Point<double> eye{0, {1, 0, 0}};
    const space::Frame<double> f;  // forward +x, up +z
    auto size_at = [&](double D) {
        const Point<double> centre{D, {1, 0, 0}};
        const space::Walk<double> w = space::walk(-1.0, centre, V3<double>{0, 0, 1}, 1.0);  // up by L = 1
        const space::Sight<double> s = space::sight(-1.0, eye, f, w.end);
        EXPECT_TRUE(s.front);
        EXPECT_NEAR(s.y, std::tanh(1.0L) / std::sinh(static_cast<LD>(D)), 1e-12);
        return s.y;
    };
    EXPECT_NEAR(size_at(6) / size_at(5), std::exp(-1.0), 0.01 * std::exp(-1.0));
    // S³: q straight ahead is seen ahead, and again behind, at the rest of the circle.
    const Point<double> ahead{1.0, {1, 0, 0}};
    const space::Sight<double> direct = space::sight(1.0, eye, f, ahead), around = space::sight_around(1.0, eye, f, ahead);
    EXPECT_TRUE(direct.front);
    EXPECT_FALSE(around.front);
    EXPECT_NEAR(around.depth, 2 * 3.14159265358979323846 - 1, 1e-12);
    EXPECT_FALSE(space::sight_around(-1.0, eye, f, ahead).front);
}

}  // namespace space_test
}  // namespace
