// The paper's triangle solutions in polar coordinates, in forms that are exact for every
// curvature K, including 0, and never divide by zero (docs/design.md, "Where the paper's
// formulas break"). Written once, templated on the scalar: double (the reference engine),
// float, and fx::fixed (the device engine).
//
// Conventions
// - A position is polar (r, theta) about the screen centre O. theta runs counter-clockwise from
//   east as seen on screen (screen y grows downward: y_px = cy - rho sin theta).
// - Directions at a point P (a body's facing, its direction of travel, the heading of an edge)
//   are angles in the frame carried from O along the ray O->P by parallel transport. In that
//   frame the outward radial direction at P has angle theta_P, exactly as in the flat plane;
//   at r = 0 the carried frame is the global frame, so the convention is regular there.
// - A body's local vertex (rho, phi): distance rho from the centre, at angle phi measured
//   counter-clockwise from the body's facing. Its direction at the centre is facing + phi.
// - The paper measures the angle at the centre C from the direction toward O (its alpha). In
//   these terms alpha = heading - (theta_C + pi): the direction toward O has carried angle
//   theta_C + pi. The code below uses delta = heading - theta_C (from the outward radial),
//   so alpha = delta - pi.
// - Lengths are in world units; at K = +1 the whole sphere is r <= pi.
//
// The 3-vector model (docs/design.md): a point is p = (C_K(r), S_K(r) cos theta,
// S_K(r) sin theta) with <p, q> = w1 w2 + K (x1 x2 + y1 y2) = C_K(dist). Every solution is the
// polar reading of a small piece of that model, written without 1/sqrt|K| and without acos.
//
// The parts:
//   geometry/scalar.hpp      what the geometry needs of a double or float scalar (fixed point
//                            brings its own: fixed/math.hpp)
//   geometry/model.hpp       points and 3-vectors, S_K, C_K, their inverses, distance,
//                            slerp_point
//   geometry/walk.hpp        geodesic walks (walk, walk_end, bearing), a vertex's position, moving
//   geometry/motion.hpp      a rigid body's motion as a matrix (body_motion, MotionApply)
//   geometry/projection.hpp  the projections (project, project_polar, project_vec)
//   geometry/edges.hpp       the points along an edge (edge_points, edge_projected, slerp_weights)
#pragma once

#include "geometry/edges.hpp"
#include "geometry/model.hpp"
#include "geometry/motion.hpp"
#include "geometry/projection.hpp"
#include "geometry/scalar.hpp"
#include "geometry/walk.hpp"

#include <cstddef>

namespace noneuclid::geo {
// The alignment of what threads write side by side (a body, its shape cache): a cache line of
// its own, so that two threads never write one line; 8 bytes where the build has no threads
// (NONEUCLID_NO_THREADS: the firmware, where the padding would cost RAM).
#ifdef NONEUCLID_NO_THREADS
inline constexpr std::size_t kThreadAlign = 8;
#else
inline constexpr std::size_t kThreadAlign = 64;
#endif
}  // namespace noneuclid::geo
