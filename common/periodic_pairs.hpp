// The points of a periodic cell's sides paired with their images across the cell, by
// index: x holds (left, right) with right = left + (W, 0), y holds (bottom, top) with
// top = bottom + (0, H). The cut makes them for the tessellation's vertices; the mesh
// stage extends them to the edge seeds it copies across; the export pairs the cyclic
// faces with them.
#pragma once

#include <utility>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

struct PeriodicPairs {
  std::vector<std::pair<int, int>> x, y;

  friend bool operator==(const PeriodicPairs&, const PeriodicPairs&) = default;
};

// The pairs of the points on the sides of `cell`, found by their exact coordinates (a
// point on a side carries the side's coordinate; its image the same other coordinate),
// in the order of the low side's points. Throws GeometryError naming a side point without
// its image. For points with no other record of their pairing (a mesh read from a file).
PeriodicPairs pair_by_position(const std::vector<Vec2>& points, const Box& cell);

}  // namespace grainmesh
