// Honeycombs of cubes (docs/space.md): space filled with equal cubes, `cells` of them round every
// edge. Whether they fit depends on K: a cube of edge a has its dihedral angle theta(K) (90
// degrees in flat space, more in S³, less in H³), and `cells` cubes close round an edge only
// where cells * theta = 360 degrees. The 8-cell (three round an edge) closes in S³, the cubic
// honeycomb (four) in flat space, the order-5 cubic honeycomb {4,3,5} (five) in H³.
//
// Built at the current K the paper's way, by walking: the first cube centred at O, and each
// further cube the one across a face of a cube already there (its centre twice the inradius
// along the face's normal, its frame carried), to a depth of face steps; cubes whose centres
// meet are one. Where K fits, the cubes meet face to face (the 8-cell's 37 walked cubes fall on
// its 8); elsewhere their faces gape or cross, the 3D form of the 2D grid's gaps and overlaps.
// Rebuilt when K changes, into fixed storage: nothing is allocated.
#pragma once

#include <array>
#include <cmath>

#include "space/polyhedra.hpp"

namespace noneuclid::space {

// A cube of edge a at curvature K: its circumradius (S_K(rho) = sqrt 3 S_K(a / 2)), its inradius
// (T_K(h) = T_K(rho) / sqrt 3, the right triangle centre - face centre - vertex) and its
// dihedral angle (cos theta = cos alpha / (1 + cos alpha), alpha the square face's angle,
// cos(alpha / 2) = T_K(a / 2) / T_K(rho_f), S_K(rho_f) = sqrt 2 S_K(a / 2)). False when no such
// cube exists (in S³ too large for its K).
struct CubeShape {
    double circumradius = 0, inradius = 0, dihedral = 0;
};
inline bool cube_shape(double K, double a, CubeShape& out) {
    const double half = geo::S_K(K, a / 2), s = std::sqrt(3.0) * half, sf = std::sqrt(2.0) * half;
    if (K > 0 && K * s * s >= 1) return false;
    const double rho = geo::AS_K(K, s), rho_f = geo::AS_K(K, sf);
    const double t_rho = geo::S_K(K, rho) / geo::C_K(K, rho), t_f = geo::S_K(K, rho_f) / geo::C_K(K, rho_f);
    const double cos_half = (geo::S_K(K, a / 2) / geo::C_K(K, a / 2)) / t_f, cos_alpha = 2 * cos_half * cos_half - 1;
    out = {rho, geo::AT_K(K, t_rho / std::sqrt(3.0)), std::acos(cos_alpha / (1 + cos_alpha))};
    return true;
}

// The curvature at which `cells` cubes of edge a close round an edge (theta = 2 pi / cells), by
// bisection on [-1, 1] (theta grows with K); NaN when none there does.
inline double closing_curvature(int cells, double a) {
    const double want = 2 * 3.14159265358979323846 / cells;
    const auto theta = [&](double K) {
        CubeShape c;
        return cube_shape(K, a, c) ? c.dihedral : 3.14159265358979323846;
    };
    double lo = -1, hi = 1;
    if (theta(lo) > want + 1e-12 || theta(hi) < want - 1e-12) return std::nan("");  // (a hair: the ends may be it)
    for (int i = 0; i < 60; ++i) ((theta((lo + hi) / 2) < want) ? lo : hi) = (lo + hi) / 2;
    return (lo + hi) / 2;
}

// One of the built-in honeycombs: its name, cubes round an edge, edge length, and how deep the
// walk goes.
struct HoneycombKind {
    const char* name;
    int cells;
    double edge;
    int depth;
};
inline constexpr HoneycombKind kEightCell{"8-cell", 3, 3.14159265358979323846 / 3, 2};  // closes at K = +1
inline constexpr HoneycombKind kOrder5Cubic{"{4,3,5}", 5, 1.6169216675118863, 2};  // closes at K = -1

class Honeycomb {
public:
    static constexpr int kMaxCells = 64;  // depth 2: 1 + 6 + 30

    struct Cell {
        Point<double> centre;
        Frame<double> frame;
    };

    const HoneycombKind* kind = nullptr;
    double closing_K = 0;  // where it fits
    CubeShape shape;
    bool exists = false;   // the cube exists at this K (in S³ it may be too large)

    void set(const HoneycombKind& k) {
        kind = &k, closing_K = closing_curvature(k.cells, k.edge), built_K_ = std::nan("");
    }
    // Rebuilds the cells for curvature K (when it changed).
    void build(double K) {
        if (!kind || K == built_K_) return;
        built_K_ = K, count_ = 0;
        exists = cube_shape(K, kind->edge, shape);
        if (!exists) return;
        cells_[count_++] = {};
        int begin = 0;
        for (int level = 0; level < kind->depth; ++level) {
            const int end = count_;
            for (int i = begin; i < end; ++i)
                for (int face = 0; face < 6; ++face) add(K, cells_[i], face);
            begin = end;
        }
    }
    int count() const { return count_; }
    const Cell& cell(int i) const { return cells_[i]; }
    // Vertex v (0-7) of cell i, at the K it was built for.
    Point<double> vertex(int i, int v) const {
        return vertex_of(built_K_, cells_[i].centre, cells_[i].frame, kSolids[1], v, shape.circumradius);
    }
    // The angle cells * theta falls short of a full turn (negative: the cubes overlap), radians.
    double gap() const { return exists ? 2 * 3.14159265358979323846 - kind->cells * shape.dihedral : 0; }

private:
    void add(double K, const Cell& from, int face) {
        if (count_ == kMaxCells) return;
        const V3<double> normals[3] = {from.frame.forward, from.frame.up, from.frame.right};
        const V3<double> n = (face & 1 ? -1.0 : 1.0) * normals[face / 2];
        const Walk<double> w = walk(K, from.centre, n, 2 * shape.inradius);
        for (int i = 0; i < count_; ++i)
            if (distance(K, cells_[i].centre, w.end) < 1e-6) return;  // (already there)
        cells_[count_++] = {w.end, orthonormal(Frame<double>{carry(w, from.frame.forward), carry(w, from.frame.up),
                                                             carry(w, from.frame.right)})};
    }

    std::array<Cell, kMaxCells> cells_{};
    int count_ = 0;
    double built_K_ = std::nan("");
};

}  // namespace noneuclid::space
