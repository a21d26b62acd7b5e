// The 3D world's bodies (src/space/polyhedra.hpp): the Platonic solids' tables, the solids placed
// in curved space, and the 8-cell, against the tests' own: the flat solids' distances, Euler's
// formula, and the 4-vector embedding in long double (as tests/space/test_space.cpp's).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "embedding.hpp"
#include "space/polyhedra.hpp"

namespace {
namespace polyhedra_test {

using namespace noneuclid;
using namespace space_embedding;

// The distance in the embedding (flat: between r u and r' u').
LD dist(LD K, const Point<double>& p, const Point<double>& q) {
    const R4 P = embed(K, p), Q = embed(K, q);
    if (K == 0) return std::sqrt((P.x - Q.x) * (P.x - Q.x) + (P.y - Q.y) * (P.y - Q.y) + (P.z - Q.z) * (P.z - Q.z));
    return ref_distance(K, P, Q);
}

double flat_distance(const double* a, const double* b) { return std::hypot(a[0] - b[0], std::hypot(a[1] - b[1], a[2] - b[2])); }

TEST(Polyhedra, EachSolidsTableIsItsSolid) {
    ASSERT_EQ(space::kSolidCount, 5);
    for (const space::Solid& s : space::kSolids) {
        SCOPED_TRACE(s.name);
        EXPECT_EQ(s.vertex_count - s.edge_count + s.face_count, 2);  // Euler
        double least = 1e9;
        for (int i = 0; i < s.vertex_count; ++i) {
            EXPECT_NEAR(std::hypot(s.vertices[i][0], std::hypot(s.vertices[i][1], s.vertices[i][2])), 1, 1e-15);
            for (int j = i + 1; j < s.vertex_count; ++j) least = std::min(least, flat_distance(s.vertices[i], s.vertices[j]));
        }
        // The edges are exactly the pairs at the least distance, each vertex on 2E/V of them.
        int closest = 0;
        for (int i = 0; i < s.vertex_count; ++i)
            for (int j = i + 1; j < s.vertex_count; ++j) closest += flat_distance(s.vertices[i], s.vertices[j]) < least + 1e-9;
        EXPECT_EQ(closest, s.edge_count);
        std::vector<int> degree(static_cast<std::size_t>(s.vertex_count));
        for (int e = 0; e < s.edge_count; ++e) {
            EXPECT_NEAR(flat_distance(s.vertices[s.edges[e][0]], s.vertices[s.edges[e][1]]), least, 1e-12) << e;
            ++degree[s.edges[e][0]], ++degree[s.edges[e][1]];
        }
        for (int d : degree) EXPECT_EQ(d, 2 * s.edge_count / s.vertex_count);
    }
}

// Placed about a random centre in a random frame, at K = -1 .. 1: every vertex at the size from
// the centre and every edge of one length, in the embedding: the solid stays regular.
TEST(Polyhedra, ASolidPlacedInCurvedSpaceStaysRegular) {
    std::mt19937_64 rng(20261207);
    std::normal_distribution<double> n;
    auto direction = [&] { return space::unit(V3<double>{n(rng), n(rng), n(rng)}); };
    double worst = 0;
    for (const double K : {-1.0, -0.5, 0.0, 0.5, 1.0})
        for (const space::Solid& s : space::kSolids)
            for (int t = 0; t < 20; ++t) {
                const Point<double> c{2 * std::fabs(n(rng)) / (K > 0 ? 2 * std::sqrt(K) : 1), direction()};
                space::Frame<double> f;
                f.forward = direction();
                f.up = direction();
                f.up = space::unit(f.up - space::dot(f.up, f.forward) * f.forward);
                f.right = space::cross(f.forward, f.up);
                const double size = 0.5;
                std::vector<Point<double>> v;
                for (int i = 0; i < s.vertex_count; ++i) v.push_back(space::vertex_of(K, c, f, s, i, size));
                for (const Point<double>& p : v) worst = std::max(worst, static_cast<double>(std::fabs(dist(K, c, p) - size)));
                const LD edge = dist(K, v[s.edges[0][0]], v[s.edges[0][1]]);
                for (int e = 1; e < s.edge_count; ++e)
                    worst = std::max(worst, static_cast<double>(std::fabs(dist(K, v[s.edges[e][0]], v[s.edges[e][1]]) - edge)));
            }
    EXPECT_LT(worst, 1e-12);
}

// The 8-cell: its vertices are the embedding's (+-1/2, +-1/2, +-1/2, +-1/2) on the unit 3-sphere
// scaled to K, its 32 edges the pairs at the least distance, pi / 3 sqrt K, four at each vertex;
// its squares (the graph's 4-cycles) number 24; at the K closing_K gives an edge is that long.
TEST(Polyhedra, TheEightCellIsTheTesseractOfS3) {
    using E = space::EightCell;
    for (const double K : {0.5, 1.0, E::closing_K(0.7)}) {
        std::vector<Point<double>> v;
        for (int i = 0; i < E::kVertices; ++i) v.push_back(E::vertex<double>(K, i));
        for (const Point<double>& p : v) {
            const R4 P = embed(K, p);
            for (const LD c : {P.w, std::sqrt(K) * P.x, std::sqrt(K) * P.y, std::sqrt(K) * P.z})
                EXPECT_NEAR(static_cast<double>(std::fabs(c)), 0.5, 1e-15);
        }
        const double a = 3.14159265358979323846 / (3 * std::sqrt(K));
        int closest = 0;
        std::vector<std::vector<bool>> joined(16, std::vector<bool>(16, false));
        for (int i = 0; i < 16; ++i)
            for (int j = i + 1; j < 16; ++j) closest += std::fabs(static_cast<double>(dist(K, v[i], v[j])) - a) < 1e-12;
        EXPECT_EQ(closest, E::kEdges);
        for (int e = 0; e < E::kEdges; ++e) {
            int i = -1, j = -1;
            E::edge(e, i, j);
            ASSERT_GE(i, 0);
            EXPECT_NEAR(static_cast<double>(dist(K, v[i], v[j])), a, 1e-12);
            joined[i][j] = joined[j][i] = true;
        }
        int squares = 0;  // (each 4-cycle a-b-c-d counted 8 times: 4 starts, 2 ways)
        for (int p = 0; p < 16; ++p)
            for (int q = 0; q < 16; ++q)
                for (int r = 0; r < 16; ++r)
                    for (int s = 0; s < 16; ++s)
                        if (p != r && q != s && joined[p][q] && joined[q][r] && joined[r][s] && joined[s][p]) ++squares;
        EXPECT_EQ(squares / 8, E::kSquares);
    }
    EXPECT_NEAR(3.14159265358979323846 / (3 * std::sqrt(E::closing_K(0.7))), 0.7, 1e-15);
}

}  // namespace polyhedra_test
}  // namespace
