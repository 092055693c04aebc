// The points of a periodic cell's sides paired with their images across the cell, by
// index, one list per axis, 2D and 3D alike: axis[0] holds (left, right) with right =
// left + the cell's width along x, axis[1] (bottom, top) along y, axis[2] (back, front)
// along z (empty in 2D); every other coordinate bit for bit the same. The cut makes them
// for the tessellation's vertices; the mesh stage extends them to the points it copies
// across; the export pairs the cyclic faces with them.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

struct PeriodicPairs {
  std::array<std::vector<std::pair<int, int>>, 3> axis;

  friend bool operator==(const PeriodicPairs&, const PeriodicPairs&) = default;
};

// The pairs of the points on the sides of `cell`, found by their exact coordinates (a
// point on a side carries the side's coordinate; its image the same other coordinate),
// in the order of the low side's points. Throws GeometryError naming a side point without
// its image. For points with no other record of their pairing (a mesh read from a file).
PeriodicPairs pair_by_position(const std::vector<Vec2>& points, const Box& cell);

}  // namespace grainmesh
