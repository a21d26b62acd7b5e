// The bodies of the three-dimensional world (docs/space.md): the five Platonic solids as
// constant tables of vertices (in their own frame, circumradius 1) and edges, a body's vertices
// placed in the world about its centre, and the 8-cell, the tiling of S³ by eight cubes.
//
// A regular polyhedron keeps its shape in a space of constant curvature: the space looks the
// same from every point in every direction, so its vertices walked out from the centre along the
// directions of the flat one, each the same distance, are again all alike (its edges are equal,
// its faces regular); only the edge's length for a given circumradius, and the angles, change
// with K. The geodesic between two vertices is the edge.
#pragma once

#include <cstdint>

#include "space/motion.hpp"

namespace noneuclid::space {

struct Solid {
    const char* name;
    int vertex_count, edge_count, face_count;
    const double (*vertices)[3];  // unit vectors in the body's frame (x forward, y left, z up)
    const uint8_t (*edges)[2];
    const double* lengths = nullptr;  // each vertex's distance from the centre (null: all 1)
};

namespace solids_data {
// (1/sqrt 3 and the golden ratio's forms, each vertex scaled to length 1.)
inline constexpr double s3 = 0.57735026918962576;  // 1 / sqrt 3
inline constexpr double tetra[4][3] = {{s3, s3, s3}, {s3, -s3, -s3}, {-s3, s3, -s3}, {-s3, -s3, s3}};
inline constexpr uint8_t tetra_edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
inline constexpr double cube[8][3] = {{-s3, -s3, -s3}, {s3, -s3, -s3}, {s3, s3, -s3}, {-s3, s3, -s3},
                                      {-s3, -s3, s3},  {s3, -s3, s3},  {s3, s3, s3},  {-s3, s3, s3}};
inline constexpr uint8_t cube_edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                              {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
inline constexpr double octa[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
inline constexpr uint8_t octa_edges[12][2] = {{0, 2}, {0, 3}, {0, 4}, {0, 5}, {1, 2}, {1, 3},
                                              {1, 4}, {1, 5}, {2, 4}, {2, 5}, {3, 4}, {3, 5}};
// The icosahedron: (0, +-1, +-phi) and its cyclic turns, over sqrt(1 + phi^2).
inline constexpr double ia = 0.52573111211913361, ib = 0.85065080835203993;  // 1, phi over sqrt(1 + phi^2)
inline constexpr double icosa[12][3] = {{0, ia, ib},  {0, -ia, ib},  {0, ia, -ib},  {0, -ia, -ib},
                                        {ia, ib, 0},  {-ia, ib, 0},  {ia, -ib, 0},  {-ia, -ib, 0},
                                        {ib, 0, ia},  {ib, 0, -ia},  {-ib, 0, ia},  {-ib, 0, -ia}};
inline constexpr uint8_t icosa_edges[30][2] = {
    {0, 1},  {0, 4},  {0, 5},  {0, 8},  {0, 10}, {1, 6},  {1, 7},  {1, 8},  {1, 10}, {2, 3},
    {2, 4},  {2, 5},  {2, 9},  {2, 11}, {3, 6},  {3, 7},  {3, 9},  {3, 11}, {4, 5},  {4, 8},
    {4, 9},  {5, 10}, {5, 11}, {6, 7},  {6, 8},  {6, 9},  {7, 10}, {7, 11}, {8, 9},  {10, 11}};
// The dodecahedron: (+-1, +-1, +-1), (0, +-1/phi, +-phi) and its cyclic turns, over sqrt 3.
inline constexpr double da = s3, db = 0.35682208977308993, dc = 0.93417235896271570;  // 1, 1/phi, phi over sqrt 3
inline constexpr double dodeca[20][3] = {
    {da, da, da},   {da, da, -da},   {da, -da, da},   {da, -da, -da},  {-da, da, da},
    {-da, da, -da}, {-da, -da, da},  {-da, -da, -da}, {0, db, dc},     {0, db, -dc},
    {0, -db, dc},   {0, -db, -dc},   {db, dc, 0},     {db, -dc, 0},    {-db, dc, 0},
    {-db, -dc, 0},  {dc, 0, db},     {dc, 0, -db},    {-dc, 0, db},    {-dc, 0, -db}};
inline constexpr uint8_t dodeca_edges[30][2] = {
    {0, 8},   {0, 12},  {0, 16},  {1, 9},   {1, 12},  {1, 17},  {2, 10},  {2, 13},  {2, 16},  {3, 11},
    {3, 13},  {3, 17},  {4, 8},   {4, 14},  {4, 18},  {5, 9},   {5, 14},  {5, 19},  {6, 10},  {6, 15},
    {6, 18},  {7, 11},  {7, 15},  {7, 19},  {8, 10},  {9, 11},  {12, 14}, {13, 15}, {16, 17}, {18, 19}};
}  // namespace solids_data

inline constexpr Solid kSolids[] = {
    {"tetrahedron", 4, 6, 4, solids_data::tetra, solids_data::tetra_edges},
    {"cube", 8, 12, 6, solids_data::cube, solids_data::cube_edges},
    {"octahedron", 6, 12, 8, solids_data::octa, solids_data::octa_edges},
    {"dodecahedron", 20, 30, 12, solids_data::dodeca, solids_data::dodeca_edges},
    {"icosahedron", 12, 30, 20, solids_data::icosa, solids_data::icosa_edges},
};
inline constexpr int kSolidCount = static_cast<int>(sizeof kSolids / sizeof kSolids[0]);

// Vertex i of a body of circumradius `size` centred at c, its frame f: walked from c along the
// flat solid's direction turned into the frame (by its length times size, for a solid of its own).
template <class T>
Point<T> vertex_of(T K, const Point<T>& c, const Frame<T>& f, const Solid& s, int i, T size) {
    const double* v = s.vertices[i];
    const V3<T> d = T(v[0]) * f.forward + T(v[2]) * f.up - T(v[1]) * f.right;  // (y is left: -right)
    return walk(K, c, d, s.lengths ? size * T(s.lengths[i]) : size).end;
}

// The 8-cell (the tesseract) in S³ of curvature K, one of its cubes centred at O with its faces
// toward the axes: its 16 vertices are the points (1/2, +-1/2, +-1/2, +-1/2) and (-1/2, ...) of the
// unit 3-sphere, scaled to K: at distance pi / 3 sqrt K from O (and 2 pi / 3 sqrt K) in the
// directions (+-1, +-1, +-1) / sqrt 3; its 32 edges join the vertices that differ in one sign, of
// length pi / 3 sqrt K. It closes (fills S³ exactly, three cubes about each edge) at every K > 0
// at that size: an edge a fits it at K = (pi / 3a)^2.
struct EightCell {
    static constexpr int kVertices = 16, kEdges = 32, kSquares = 24, kCubes = 8;
    // Vertex i: bit 3 the sign of w (1: negative), bits 0-2 the signs of x, y, z.
    template <class T>
    static Point<T> vertex(T K, int i) {
        using std::sqrt;
        const T k = T(0.57735026918962576);  // 1 / sqrt 3
        const V3<T> u{i & 1 ? -k : k, i & 2 ? -k : k, i & 4 ? -k : k};
        const T third = geo::pi_v<T> / (T(3) * sqrt(K));
        return {i & 8 ? T(2) * third : third, u};
    }
    // Edge e's two vertices: those that differ in exactly one of the four signs.
    static void edge(int e, int& a, int& b) {
        int n = 0;
        for (int i = 0; i < kVertices; ++i)
            for (int bit = 0; bit < 4; ++bit)
                if (const int j = i ^ (1 << bit); j > i && n++ == e) {
                    a = i, b = j;
                    return;
                }
    }
    // The curvature at which edges of length a close it.
    static double closing_K(double a) {
        const double t = 3.14159265358979323846 / (3 * a);
        return t * t;
    }
};

}  // namespace noneuclid::space
