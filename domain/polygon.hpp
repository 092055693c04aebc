// Polygons with holes: validation, area, exact inside test and distance.
#pragma once

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
// inside. Inside-ness is decided by an exact crossing-number test, so the sign is right
// however close p is to an edge. O(edges) per query.
class PolygonDistance {
 public:
  explicit PolygonDistance(const PolygonRings& rings);

  double operator()(Vec2 p) const;
  // True when p is strictly inside (not on an edge).
  bool contains(Vec2 p) const;
  // Unsigned distance to the nearest edge.
  double unsigned_distance(Vec2 p) const;
  const Box& bounds() const { return bounds_; }

 private:
  // Edge e runs from a[e] to b[e]; stored flat for the hot loop.
  std::vector<Vec2> a_, b_;
  Box bounds_;
  // Large polygons (a binder matrix) bin their edges in a uniform grid: every cell an
  // edge's box touches lists it. Empty for small polygons.
  GridFrame grid_;
  CellLists cells_;
  CellLists rows_;  // the same by rows, for the inside test

};

}  // namespace grainmesh
