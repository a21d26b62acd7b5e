// The 2D side of the collision and fill tests' independent reference: a body's gnomonic chart,
// where geodesics are straight lines, and PNPOLY (W. R. Franklin) in it, in long double.
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/reference.hpp"

namespace noneuclid::test {

// tan_K(x) = S_K(x) / C_K(x): a geodesic distance's length in the gnomonic chart.
inline double TK(double K, double x) { return geo::ref::S(K, x) / geo::ref::C(K, x); }

struct P2 {
    long double u, v;
};

// PNPOLY: whether p is inside the polygon, by the crossing count of a ray to +u.
inline bool pnpoly(const std::vector<P2>& poly, P2 p) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].v > p.v) != (poly[j].v > p.v) &&
            p.u < (poly[j].u - poly[i].u) * (p.v - poly[i].v) / (poly[j].v - poly[i].v) + poly[i].u)
            in = !in;
    return in;
}

}  // namespace noneuclid::test
