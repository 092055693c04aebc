// Convex polyhedra in CGAL's exact kernel: clipped by the box's planes, and split into a
// core and frustums for binder mode. Internal to the 3D tessellation's CGAL files
// (laguerre_3d.cpp, exact_polyhedron.cpp): it shows CGAL's types.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <vector>

namespace grainmesh {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;

// A convex polyhedron in exact coordinates, faces counter-clockwise seen from outside.
struct ExactPolyhedron {
  std::vector<EK::Point_3> points;
  std::vector<std::vector<int>> faces;
};

inline EK::FT coord(const EK::Point_3& p, int axis) { return axis == 0 ? p.x() : axis == 1 ? p.y() : p.z(); }

// The part of `poly` on the side coord(axis) >= c (keep_above) or <= c, closed by a new
// face in the plane. Empty when nothing of positive volume is left.
ExactPolyhedron clip(const ExactPolyhedron& poly, int axis, const EK::FT& c, bool keep_above);

// The core of `poly` (it scaled by `scale` about `centre`, which lies inside) and then, for
// each face k, the frustum between face k and the core's copy of it: its faces the outer
// face, the inner one and a side per edge, which the frustum on the neighbouring face
// shares with the same points (binder_3d.hpp).
std::vector<ExactPolyhedron> core_and_frustums(const ExactPolyhedron& poly, const EK::Point_3& centre,
                                               const EK::FT& scale);

}  // namespace grainmesh
