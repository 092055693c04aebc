// Delaunay triangulation of a point set, computed by CGAL with exact predicates
// (delaunay.cpp is the only file that sees CGAL's triangulation headers).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

// A triangulation as flat arrays: counter-clockwise triples of indices into the points,
// and for each corner the triangle across the edge opposite it, -1 where there is none
// (the convex hull, or the boundary of the region kept).
struct Triangulation {
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<int, 3>> neighbours;
};

// The Delaunay triangulation of `points`. Of coincident points only one appears.
// Deterministic: the same input gives the same triangles in the same order. Throws
// GeometryError on non-finite input or when CGAL fails.
Triangulation delaunay_triangulation(std::span<const Vec2> points);

// The constrained Delaunay triangulation of `points` in which every segment of
// `constraints` (pairs of indices into `points`) is a union of edges (a segment through
// another point is split there). When the constraints are closed rings bounding a
// domain, the triangles inside it: those separated from the outside by an odd number of
// constraints (so holes stay empty, and every constraint has -1 on one side).
// Deterministic. Throws GeometryError as above.
Triangulation constrained_delaunay_triangulation(std::span<const Vec2> points,
                                                 std::span<const std::array<int, 2>> constraints);

// Makes `t` Delaunay again after its points moved, by edge flips (Lawson's algorithm,
// exact predicates): an edge between two triangles is flipped while the far corner of one
// lies inside the circumcircle of the other. Edges with -1 on a side never change, so a
// constrained triangulation keeps its constraints. Returns false, and leaves `t` to be
// rebuilt, when the moves turned a triangle over or flattened it (flips cannot mend
// that); with hull_may_shrink, such triangles on the hull are removed instead where they
// can be (the hull then need not stay convex, and a point may be left in no triangle).
// Linear in the triangles plus the flips made, counted in *flips when given.
bool restore_delaunay(Triangulation& t, std::span<const Vec2> points, std::size_t* flips = nullptr,
                      bool hull_may_shrink = false);

// Adds points[v] to the Delaunay triangulation `t` (whose triangles use other points
// only), walking to it from triangle `hint`: inside a triangle it splits that triangle in
// three; beyond a single hull edge it gets one new triangle on that edge; flips then make
// `t` Delaunay again. Returns false, and leaves `t` to be rebuilt, when the point lies on
// an edge or a corner, sees more than one hull edge, or the walk gets lost.
bool insert_point(Triangulation& t, std::span<const Vec2> points, int v, int hint);

}  // namespace grainmesh
