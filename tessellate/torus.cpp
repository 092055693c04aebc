#include "tessellate/torus.hpp"

#include <cmath>
#include <numbers>

namespace grainmesh {

std::vector<Vec2> TorusGraph::polygon(int c) const {
  std::vector<Vec2> out;
  out.reserve(rings[c].size());
  for (const Corner& k : rings[c]) out.push_back(point(k));
  return out;
}

int TorusGraph::live_cells() const {
  int n = 0;
  for (const auto& r : rings) n += r.empty() ? 0 : 1;
  return n;
}

Vec2 reduce_periodic(Vec2 p, double width, double height, Corner* shift) {
  const int i = static_cast<int>(std::floor(p.x / width));
  const int j = static_cast<int>(std::floor(p.y / height));
  Vec2 r{p.x - i * width, p.y - j * height};
  // Rounding can land exactly on the far side; keep [0, W).
  int ii = i, jj = j;
  if (r.x >= width) { r.x -= width; ++ii; }
  if (r.x < 0.0) { r.x += width; --ii; }
  if (r.y >= height) { r.y -= height; ++jj; }
  if (r.y < 0.0) { r.y += height; --jj; }
  if (shift) *shift = Corner{0, ii, jj};
  return r;
}

double polygon_area(const std::vector<Vec2>& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return 0.0;
  double a2 = 0.0;
  const Vec2 o = ring[0];  // relative to a corner: no cancellation far from the origin
  for (std::size_t k = 1; k + 1 < n; ++k) a2 += cross(ring[k] - o, ring[k + 1] - o);
  return 0.5 * a2;
}

Vec2 polygon_centroid(const std::vector<Vec2>& ring) {
  const std::size_t n = ring.size();
  const Vec2 o = ring[0];
  double a2 = 0.0;
  Vec2 m{};
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const Vec2 a = ring[k] - o, b = ring[k + 1] - o;
    const double w = cross(a, b);
    a2 += w;
    m += w * (a + b);
  }
  if (a2 == 0.0) return o;
  return o + m / (3.0 * a2);
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

namespace {

int orient(Vec2 a, Vec2 b, Vec2 c) {
  const double s = signed_area2(a, b, c);
  return (s > 0.0) - (s < 0.0);
}

bool on_segment(Vec2 a, Vec2 b, Vec2 p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool segments_touch(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) || (o3 == 0 && on_segment(c, d, a)) ||
         (o4 == 0 && on_segment(c, d, b));
}

}  // namespace

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
  // Adjacent edges folding back onto each other.
  for (std::size_t a = 0; a < n; ++a) {
    const Vec2 p = ring[(a + n - 1) % n], q = ring[a], r = ring[(a + 1) % n];
    if (orient(p, q, r) == 0 && dot(q - p, r - q) < 0.0) return false;
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
