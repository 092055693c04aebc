// Closed polygonal rings (the closing edge implied, the first vertex not repeated): area,
// centroid, clipping, simplicity, corners, and the exact segment and inside tests every
// stage uses on grain and domain polygons.
#pragma once

#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

// Signed area (> 0 counter-clockwise) and centroid of a ring. Summed relative to the first
// vertex, so no cancellation far from the origin. O(n).
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
