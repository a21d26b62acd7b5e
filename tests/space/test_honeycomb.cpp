// Honeycombs of cubes (src/space/honeycomb.hpp) against the embedding (tests/space/embedding.hpp):
// a cube's edge and dihedral angle measured on its embedded vertices in long double at K = -1 ...
// 1; the K at which three, four and five cubes close round an edge; the 8-cell walked at K = 1
// lands on its 16 vertices (1/2, +-1/2, +-1/2, +-1/2) and nowhere else, and the {4,3,5}'s cubes
// meet face to face at K = -1 and not a little off it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "embedding.hpp"
#include "space/honeycomb.hpp"
#include "space/view.hpp"

namespace {
namespace honeycomb_test {

using namespace noneuclid;
using namespace space_embedding;

constexpr LD kPi = 3.14159265358979323846264338327950288L;

// A point's embedding as a plain 4-vector (at K = 0 the flat position, w = 1).
R4 at(LD K, const Point<double>& p) {
    if (K != 0) return embed(K, p);
    const V3<double> x = space::map_position(p);
    return {1, x.x, x.y, x.z};
}
// The tangent at P toward Q (K != 0: Q less its part along P; flat: Q - P), and the metric.
R4 toward(LD K, R4 P, R4 Q) { return K != 0 ? Q - form(K, P, Q) * P : Q - P; }
LD metric(LD K, R4 a, R4 b) { return K != 0 ? g(K, a, b) : a.x * b.x + a.y * b.y + a.z * b.z; }

// The angle between the faces (A, B, C) and (A, B, D) along the edge A-B, at A.
LD dihedral(LD K, R4 A, R4 B, R4 C, R4 D) {
    const R4 b = toward(K, A, B);
    auto across = [&](R4 v) { return v - (metric(K, v, b) / metric(K, b, b)) * b; };
    const R4 c = across(toward(K, A, C)), d = across(toward(K, A, D));
    return std::acos(metric(K, c, d) / std::sqrt(metric(K, c, c) * metric(K, d, d)));
}

TEST(Honeycomb, ACubesEdgeAndDihedralAngleAreTheEmbeddingsAtEveryK) {
    const space::Solid& cube = space::kSolids[1];
    for (const double a : {space::kEightCell.edge, space::kOrder5Cubic.edge, 0.5})
        for (const double K : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
            space::CubeShape shape;
            if (!space::cube_shape(K, a, shape)) {
                // (Only in S³, where sqrt 3 S_K(a / 2) would pass 1 / sqrt K.)
                EXPECT_GT(K * 3 * std::pow(std::sin(std::sqrt(K) * a / 2) / std::sqrt(K), 2), 1.0) << a << " " << K;
                continue;
            }
            std::vector<R4> v;
            for (int i = 0; i < 8; ++i)
                v.push_back(at(K, space::vertex_of(K, Point<double>{}, space::Frame<double>{}, cube, i, shape.circumradius)));
            // Vertex 0's three neighbours, by the table's edges.
            std::vector<int> next;
            for (int e = 0; e < cube.edge_count; ++e) {
                if (cube.edges[e][0] == 0) next.push_back(cube.edges[e][1]);
                if (cube.edges[e][1] == 0) next.push_back(cube.edges[e][0]);
            }
            ASSERT_EQ(next.size(), 3u);
            for (int n : next) {
                const LD d = K != 0 ? ref_distance(K, v[0], v[n]) : std::sqrt(metric(0, v[n] - v[0], v[n] - v[0]));
                EXPECT_NEAR(d, a, 1e-12) << "K = " << K;
            }
            EXPECT_NEAR(dihedral(K, v[0], v[next[0]], v[next[1]], v[next[2]]), shape.dihedral, 1e-12) << "K = " << K;
            // The inradius: the face centre (the embedded face's mean, put back on the quadric) from O.
            R4 f{0, 0, 0, 0};
            for (int i = 0; i < 8; ++i)
                if (space::kSolids[1].vertices[i][0] > 0) f = f + 0.25L * v[i];
            const LD h = K != 0 ? ref_distance(K, at(K, Point<double>{}), (1 / std::sqrt(form(K, f, f))) * f)
                                : std::sqrt(metric(0, f - R4{1, 0, 0, 0}, f - R4{1, 0, 0, 0}));
            EXPECT_NEAR(h, shape.inradius, 1e-12) << "K = " << K;
        }
}

TEST(Honeycomb, ThreeFourAndFiveCubesCloseInS3FlatSpaceAndH3) {
    EXPECT_NEAR(space::closing_curvature(3, static_cast<double>(kPi / 3)), 1.0, 1e-12);
    EXPECT_NEAR(space::closing_curvature(4, 0.7), 0.0, 1e-12);
    EXPECT_NEAR(space::closing_curvature(5, space::kOrder5Cubic.edge), -1.0, 1e-12);
    space::CubeShape c;
    ASSERT_TRUE(space::cube_shape(-1, space::kOrder5Cubic.edge, c));
    EXPECT_NEAR(c.dihedral, static_cast<double>(2 * kPi / 5), 1e-12);  // 72 degrees
}

// The 8-cell, walked at K = 1: its 37 face steps fall on 8 cubes, whose vertices are the 16 of
// the tesseract; at K = 0.9 the cubes do not meet (37 of them).
TEST(Honeycomb, TheEightCellWalkedAtKOneIsTheTesseract) {
    space::Honeycomb h;
    h.set(space::kEightCell);
    EXPECT_NEAR(h.closing_K, 1.0, 1e-12);
    h.build(1.0);
    EXPECT_EQ(h.count(), 8);
    EXPECT_NEAR(h.gap(), 0.0, 1e-12);
    std::vector<int> hits(16);
    LD worst = 0;
    for (int c = 0; c < h.count(); ++c)
        for (int v = 0; v < 8; ++v) {
            const R4 p = at(1, h.vertex(c, v));
            LD best = 1;
            int which = -1;
            for (int i = 0; i < 16; ++i) {  // (1/2, +-1/2, ...), the sign of w in bit 3, of x, y, z in bits 0-2
                const R4 q{i & 8 ? -0.5L : 0.5L, i & 1 ? -0.5L : 0.5L, i & 2 ? -0.5L : 0.5L, i & 4 ? -0.5L : 0.5L};
                const LD d = near_distance(1, p, q);
                if (d < best) best = d, which = i;
            }
            worst = std::max(worst, best);
            ++hits[which];
        }
    EXPECT_LT(worst, 1e-9);
    for (int i = 0; i < 16; ++i) EXPECT_EQ(hits[i], 4) << "vertex " << i;  // (four cubes at each vertex)
    h.build(0.9);
    EXPECT_EQ(h.count(), 37);
    EXPECT_GT(h.gap(), 0.05);  // three cubes leave a wedge
}

// How many pairs of the second ring's cubes share a face (four vertices within 1e-9).
int faces_shared(const space::Honeycomb& h, LD K) {
    int pairs = 0;
    for (int i = 7; i < h.count(); ++i)
        for (int j = i + 1; j < h.count(); ++j) {
            int shared = 0;
            for (int a = 0; a < 8; ++a)
                for (int b = 0; b < 8; ++b) shared += near_distance(K, at(K, h.vertex(i, a)), at(K, h.vertex(j, b))) < 1e-9;
            pairs += shared == 4;
        }
    return pairs;
}

// {4,3,5} at K = -1: round each of the first cube's 12 edges, the two second-ring cubes meet face
// to face (five cubes closing the turn); at K = -0.9 none do: their faces cross.
TEST(Honeycomb, TheOrderFiveCubicHoneycombClosesAtKMinusOne) {
    space::Honeycomb h;
    h.set(space::kOrder5Cubic);
    h.build(-1.0);
    EXPECT_EQ(h.count(), 37);
    EXPECT_EQ(faces_shared(h, -1), 12);
    h.build(-0.9);
    EXPECT_EQ(faces_shared(h, -0.9), 0);
    EXPECT_LT(h.gap(), -0.01);  // (a larger K, a larger dihedral angle: five overlap)
}

}  // namespace honeycomb_test
}  // namespace
