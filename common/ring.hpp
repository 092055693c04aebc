// Closed polygonal rings (the closing edge implied, the first vertex not repeated): area,
// centroid, clipping, simplicity, corners, and the exact segment and inside tests every
// stage uses on grain and domain polygons.
#pragma once

#include <cstddef>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

// Signed area (> 0 counter-clockwise) and centroid of the ring of n points at(0) ..
// at(n - 1), summed relative to the first, so no cancellation far from the origin. O(n).
// For rings held as point ids into a mesh (cell_mesh.hpp) without copying them.
template <typename At>
double ring_area(std::size_t n, At at) {
  if (n < 3) return 0.0;
  double a2 = 0.0;
  const Vec2 o = at(0);
  for (std::size_t k = 1; k + 1 < n; ++k) a2 += cross(at(k) - o, at(k + 1) - o);
  return 0.5 * a2;
}
template <typename At>
Vec2 ring_centroid(std::size_t n, At at) {
  const Vec2 o = at(0);
  double a2 = 0.0;
  Vec2 m{};
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const Vec2 a = at(k) - o, b = at(k + 1) - o;
    const double w = cross(a, b);
    a2 += w;
    m += w * (a + b);
  }
  if (a2 == 0.0) return o;
  return o + m / (3.0 * a2);
}

// The same of a ring of points.
double polygon_area(const std::vector<Vec2>& ring);
Vec2 polygon_centroid(const std::vector<Vec2>& ring);

// The part of a ring where dot(normal, p) >= offset (one Sutherland-Hodgman step; exact
// for convex rings up to the rounding of the new vertices).
std::vector<Vec2> clip_half_plane(const std::vector<Vec2>& poly, Vec2 normal, double offset);

// Whether the closed segments pq and rs share a point. Exact.
bool segments_touch(Vec2 p, Vec2 q, Vec2 r, Vec2 s);

// Crossing-number parity of p against the ring: true when p is inside. Exact for p off
// the ring; p on an edge may go either way. O(n).
bool inside_ring(const std::vector<Vec2>& ring, Vec2 p);

// True when no two non-adjacent edges touch, no two consecutive points coincide and no
// two consecutive edges fold back onto each other. Exact. O(n^2), for the small rings of
// grains.
bool ring_is_simple(const std::vector<Vec2>& ring);

// The smallest angle on the left of the ring's walk (the interior of a counter-clockwise
// ring), radians.
double sharpest_corner(const std::vector<Vec2>& ring);

}  // namespace grainmesh
