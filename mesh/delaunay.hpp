// Delaunay triangulation of a point set, computed by CGAL with exact predicates
// (delaunay.cpp is the only file that sees CGAL's triangulation headers).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

// Triangles of the Delaunay triangulation of `points`, as counter-clockwise triples of
// indices into `points`. Of coincident points only one appears. Deterministic: the same
// input gives the same triangles in the same order. Throws GeometryError on non-finite
// input or when CGAL fails.
std::vector<std::array<int, 3>> delaunay_triangulation(std::span<const Vec2> points);

// The constrained Delaunay triangulation of `points` in which every segment of
// `constraints` (pairs of indices into `points`) is a union of edges (a segment through
// another point is split there). When the constraints are closed rings bounding a
// domain, the triangles inside it: those separated from the outside by an odd number of
// constraints (so holes stay empty). Counter-clockwise, deterministic. Throws
// GeometryError as above.
std::vector<std::array<int, 3>> constrained_delaunay_triangulation(std::span<const Vec2> points,
                                                                   std::span<const std::array<int, 2>> constraints);

}  // namespace grainmesh
