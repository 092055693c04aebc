#include "mesh/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/predicates.hpp"

namespace grainmesh {
namespace {

// True when q, known to be collinear with segment ab, lies on the closed segment.
bool on_collinear_segment(Vec2 a, Vec2 b, Vec2 q) {
  return std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y &&
         q.y <= std::max(a.y, b.y);
}

// Whether closed segments pq and rs share at least one point. Exact.
bool segments_touch(Vec2 p, Vec2 q, Vec2 r, Vec2 s) {
  const int o1 = orient2d(p, q, r), o2 = orient2d(p, q, s);
  const int o3 = orient2d(r, s, p), o4 = orient2d(r, s, q);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_collinear_segment(p, q, r)) || (o2 == 0 && on_collinear_segment(p, q, s)) ||
         (o3 == 0 && on_collinear_segment(r, s, p)) || (o4 == 0 && on_collinear_segment(r, s, q));
}

// Crossing-number parity of p against one ring; exact (p on an edge may go either way).
bool crosses_odd(const std::vector<Vec2>& ring, Vec2 p) {
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

double ring_signed_area(const std::vector<Vec2>& ring) {
  double s = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) s += cross(ring[i], ring[(i + 1) % n]);
  return 0.5 * s;
}

}  // namespace

void validate_polygon(const PolygonRings& rings) {
  if (rings.empty()) throw GeometryError("polygon: no vertices");
  struct Edge {
    Vec2 a, b;
    std::size_t ring, index;
  };
  std::vector<Edge> edges;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = rings[r];
    const std::string what = r == 0 ? "polygon outer ring" : "polygon hole " + std::to_string(r);
    if (ring.size() < 3)
      throw GeometryError(what + ": needs at least 3 vertices, has " + std::to_string(ring.size()));
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      if (!is_finite(a)) throw GeometryError(what + ": vertex " + to_text(a, 9) + " is not finite");
      if (a == b) throw GeometryError(what + ": repeated vertex " + to_text(a, 9));
      edges.push_back({a, b, r, i});
    }
  }

  // Consecutive edges share a vertex; they must not fold back onto each other.
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = rings[r];
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Vec2 prev = ring[(i + n - 1) % n], v = ring[i], next = ring[(i + 1) % n];
      if (orient2d(prev, v, next) == 0 && dot(v - prev, next - v) < 0)
        throw GeometryError("polygon: edges fold back at vertex " + to_text(v, 9));
    }
  }

  // No other pair of edges may touch. Sweep over x so that typical inputs stay near linear.
  std::vector<std::size_t> order(edges.size());
  std::iota(order.begin(), order.end(), 0);
  auto xmin = [&](std::size_t e) { return std::min(edges[e].a.x, edges[e].b.x); };
  auto xmax = [&](std::size_t e) { return std::max(edges[e].a.x, edges[e].b.x); };
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return xmin(i) < xmin(j); });
  for (std::size_t oi = 0; oi < order.size(); ++oi) {
    const Edge& e = edges[order[oi]];
    const double e_xmax = xmax(order[oi]);
    for (std::size_t oj = oi + 1; oj < order.size() && xmin(order[oj]) <= e_xmax; ++oj) {
      const Edge& f = edges[order[oj]];
      if (e.ring == f.ring) {
        const std::size_t n = rings[e.ring].size();
        // Consecutive edges meet at their shared vertex; folds were rejected above.
        if ((e.index + 1) % n == f.index || (f.index + 1) % n == e.index) continue;
      }
      if (segments_touch(e.a, e.b, f.a, f.b))
        throw GeometryError("polygon: edges " + to_text(e.a, 9) + "-" + to_text(e.b, 9) + " and " +
                            to_text(f.a, 9) + "-" + to_text(f.b, 9) + " intersect");
    }
  }

  // With no edges touching, one vertex decides where a whole hole lies.
  for (std::size_t r = 1; r < rings.size(); ++r) {
    const Vec2 v = rings[r][0];
    if (!crosses_odd(rings[0], v))
      throw GeometryError("polygon hole " + std::to_string(r) + " at " + to_text(v, 9) +
                          " is not inside the outer ring");
    for (std::size_t s = 1; s < rings.size(); ++s)
      if (s != r && crosses_odd(rings[s], v))
        throw GeometryError("polygon hole " + std::to_string(r) + " lies inside hole " +
                            std::to_string(s));
  }
}

double polygon_area(const PolygonRings& rings) {
  if (rings.empty()) return 0.0;
  double area = std::abs(ring_signed_area(rings[0]));
  for (std::size_t r = 1; r < rings.size(); ++r) area -= std::abs(ring_signed_area(rings[r]));
  return area;
}

PolygonDistance::PolygonDistance(const PolygonRings& rings) {
  validate_polygon(rings);
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      a_.push_back(ring[i]);
      b_.push_back(ring[(i + 1) % ring.size()]);
      bounds_.extend(ring[i]);
    }
}

double PolygonDistance::unsigned_distance(Vec2 p) const {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < a_.size(); ++e) {
    const Vec2 ab = b_[e] - a_[e], ap = p - a_[e];
    const double t = std::clamp(dot(ap, ab) / norm2(ab), 0.0, 1.0);
    best = std::min(best, norm2(ap - t * ab));
  }
  return std::sqrt(best);
}

bool PolygonDistance::contains(Vec2 p) const {
  bool odd = false;
  for (std::size_t e = 0; e < a_.size(); ++e) {
    const Vec2 a = a_[e], b = b_[e];
    if ((a.y > p.y) != (b.y > p.y)) {
      const int o = orient2d(a, b, p);
      if (o == 0) return false;  // on the edge
      if (b.y > a.y ? o > 0 : o < 0) odd = !odd;
    }
  }
  return odd;
}

double PolygonDistance::operator()(Vec2 p) const {
  const double d = unsigned_distance(p);
  return contains(p) ? -d : d;
}

}  // namespace grainmesh
