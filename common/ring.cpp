#include "common/ring.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/predicates.hpp"

namespace grainmesh {
namespace {

// True when q, known to be collinear with segment ab, lies on the closed segment.
bool on_collinear_segment(Vec2 a, Vec2 b, Vec2 q) {
  return std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y &&
         q.y <= std::max(a.y, b.y);
}

}  // namespace

double polygon_area(const std::vector<Vec2>& ring) {
  return ring_area(ring.size(), [&](std::size_t k) { return ring[k]; });
}

Vec2 polygon_centroid(const std::vector<Vec2>& ring) {
  return ring_centroid(ring.size(), [&](std::size_t k) { return ring[k]; });
}

std::vector<Vec2> clip_half_plane(const std::vector<Vec2>& poly, Vec2 normal, double offset) {
  std::vector<Vec2> out;
  for (std::size_t n = 0; n < poly.size(); ++n) {
    const Vec2 p = poly[n], q = poly[(n + 1) % poly.size()];
    const double dp = dot(normal, p) - offset, dq = dot(normal, q) - offset;
    if (dp >= 0.0) out.push_back(p);
    if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + (dp / (dp - dq)) * (q - p));
  }
  return out;
}

bool segments_touch(Vec2 p, Vec2 q, Vec2 r, Vec2 s) {
  const int o1 = orient2d(p, q, r), o2 = orient2d(p, q, s);
  const int o3 = orient2d(r, s, p), o4 = orient2d(r, s, q);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_collinear_segment(p, q, r)) || (o2 == 0 && on_collinear_segment(p, q, s)) ||
         (o3 == 0 && on_collinear_segment(r, s, p)) || (o4 == 0 && on_collinear_segment(r, s, q));
}

bool inside_ring(const std::vector<Vec2>& ring, Vec2 p) {
  bool odd = false;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % n];
    if ((a.y > p.y) != (b.y > p.y)) {
      const int o = orient2d(a, b, p);
      if (b.y > a.y ? o > 0 : o < 0) odd = !odd;
    }
  }
  return odd;
}

bool ring_is_simple(const std::vector<Vec2>& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  for (std::size_t a = 0; a < n; ++a)
    if (ring[a] == ring[(a + 1) % n]) return false;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      if (b == a + 1 || (a == 0 && b == n - 1)) continue;  // adjacent edges share a corner
      if (segments_touch(ring[a], ring[(a + 1) % n], ring[b], ring[(b + 1) % n])) return false;
    }
  for (std::size_t a = 0; a < n; ++a) {
    const Vec2 p = ring[(a + n - 1) % n], q = ring[a], r = ring[(a + 1) % n];
    if (orient2d(p, q, r) == 0 && dot(q - p, r - q) < 0.0) return false;
  }
  return true;
}

double sharpest_corner(const std::vector<Vec2>& ring) {
  const std::size_t n = ring.size();
  double sharpest = std::numbers::pi * 2.0;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = ring[(k + n - 1) % n] - ring[k];
    const Vec2 b = ring[(k + 1) % n] - ring[k];
    // Interior angle of a CCW ring: from b round to a, counter-clockwise.
    double ang = std::atan2(cross(b, a), dot(b, a));
    if (ang < 0.0) ang += 2.0 * std::numbers::pi;
    sharpest = std::min(sharpest, ang);
  }
  return sharpest;
}

}  // namespace grainmesh
