// The sphere's lines for the earth scene (world/earth.cpp): unit 3-vectors, great-circle arcs and
// the distance from a point to one, and each line's Douglas-Peucker tree (geometry/detail.hpp),
// by which the view simplifies the line when it is drawn.
#pragma once

#include <vector>

#include "geometry/detail.hpp"
#include "world/scene.hpp"

namespace noneuclid::world {

struct V3 {
    double x, y, z;
};
// The unit vector of latitude lat and longitude lon (degrees).
V3 unit(double lat, double lon);
inline double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
// The angle between unit vectors a and b (atan2: exact for small and near-antipodal angles).
double arc(V3 a, V3 b);
// The angle from p to the great-circle arc from a to b (to its nearer end where p's foot on the
// circle lies outside the arc; to a where the arc is a point).
double arc_distance(V3 p, V3 a, V3 b);

// The tree of a line of vertices (world units about O on the sphere of the level, a place at
// angle rho / scale), deviations and rho in world units; a bracket longer than max_step is
// always split (closed: a ring, its last vertex joined to its first).
geo::DetailTree line_tree(const std::vector<SceneBody::Vertex>& v, bool closed, double scale, double max_step);

}  // namespace noneuclid::world
