// How a face of a 3D tessellation is taken once short-edge collapses have bent it: planar,
// or split into planar triangles without new points (regularise_3d.cpp).
#pragma once

#include <array>
#include <vector>

#include "common/vec3.hpp"

namespace grainmesh {

// The box sides a point lies on: bit 2a for coordinate a = 0, bit 2a + 1 for = box[a].
// Exact: points on a side carry its coordinate.
int side_mask(Vec3 p, Vec3 box);

// Planar (within `flat`, its own plane), or the triangulation of its ring without new
// points that makes the smallest angle largest, every triangle turning with the ring and
// no diagonal joining two points on one side of the box (it would lie in that side, where
// the box's own face is); `valid` false when none does.
struct FaceShape {
  bool planar = true;
  bool valid = true;
  std::vector<std::array<int, 3>> triangles;  // point ids; empty when planar
};
FaceShape face_shape(const std::vector<Vec3>& points, const std::vector<int>& ring, double flat, Vec3 box);

}  // namespace grainmesh
