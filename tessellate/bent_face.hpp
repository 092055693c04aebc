// How a face of a 3D tessellation is taken once short-edge collapses have bent it: planar,
// or split into planar triangles, without new points or about one new centre point
// (regularise_3d.cpp).
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

// The other split of a bent face: a new point at its vertices' centroid, joined to every
// edge, when each of the fan's triangles turns with the ring; the smallest angle of its
// triangles. A face of many points bent a little by a collapse gets thin triangles from
// diagonals alone (its slices), where the fan's are about as wide as the face.
struct CentreFan {
  bool valid = false;
  Vec3 centre;
  double smallest_angle = 0.0;  // radians
};
CentreFan centre_fan(const std::vector<Vec3>& points, const std::vector<int>& ring);

// The smallest angle (radians) of the triangles (point ids).
double smallest_angle(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles);

}  // namespace grainmesh
