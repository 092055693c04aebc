// Polygons with holes: validation, area, exact inside test and distance.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "common/geometry.hpp"
#include "common/spatial_grid.hpp"

namespace grainmesh {

// rings[0] is the outer boundary, rings[1..] are holes; vertices in either orientation,
// the closing edge implied (do not repeat the first vertex).
using PolygonRings = std::vector<std::vector<Vec2>>;

// Throws GeometryError unless the rings form a simple polygon with holes: every ring has
// at least 3 finite vertices and no zero-length edge; no two edges cross or touch except
// consecutive edges of a ring at their common vertex (and those do not fold back); every
// hole lies inside the outer ring and outside the other holes. Exact predicates.
void validate_polygon(const PolygonRings& rings);

// Area of the outer ring minus the areas of the holes (> 0 for a valid polygon).
double polygon_area(const PolygonRings& rings);

// Signed distance to a validated polygon: exact distance to the nearest edge, negative
// inside. The sign comes from the nearest boundary point, with exact predicates: the side
// of its edge, or at a vertex the corner's wedge (inside a convex corner is left of both
// edges, inside a reflex one left of either); within rounding of the boundary, or where
// two edges are as near to rounding, from the exact crossing test: right however close
// p is to an edge.
// Edges are binned in a grid for large polygons, so a query looks at the few near p.
class PolygonDistance {
 public:
  explicit PolygonDistance(const PolygonRings& rings);

  double operator()(Vec2 p) const;
  // True when p is strictly inside (not on an edge), by an exact crossing-number test
  // independent of the distance.
  bool contains(Vec2 p) const;
  // Unsigned distance to the nearest edge.
  double unsigned_distance(Vec2 p) const { return std::sqrt(nearest(p).d2); }
  const Box& bounds() const { return bounds_; }

 private:
  struct Nearest {
    double d2;
    std::size_t edge;
    double t;  // where along the edge its nearest point lies (segment_parameter)
    // False when another edge with another nearest point is as near to rounding (a needle
    // thinner than rounding, two edges nearly touching): the edge's side cannot tell.
    bool certain;
  };
  Nearest nearest(Vec2 p) const;
  // Whether p, whose nearest boundary point `n` found, is strictly inside.
  bool inside_by_nearest(Vec2 p, const Nearest& n) const;

  // Edge e runs from a[e] to b[e] as its ring was given; stored flat for the hot loop.
  // next_[e] is the edge after e in its ring, prev_[e] the one before; inside_[e] is +1
  // when the polygon's inside lies left of e, -1 when right.
  std::vector<Vec2> a_, b_;
  std::vector<std::size_t> next_, prev_;
  std::vector<signed char> inside_;
  Box bounds_;
  double extent_ = 0.0;  // the larger side of bounds_
  // Large polygons (a binder matrix) bin their edges in a uniform grid: every cell an
  // edge's box touches lists it. Empty for small polygons.
  GridFrame grid_;
  CellLists cells_;
  CellLists rows_;  // the same by rows, for the crossing test
};

}  // namespace grainmesh
