#include "domain/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/predicates.hpp"
#include "common/ring.hpp"

namespace grainmesh {

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
    if (!inside_ring(rings[0], v))
      throw GeometryError("polygon hole " + std::to_string(r) + " at " + to_text(v, 9) +
                          " is not inside the outer ring");
    for (std::size_t s = 1; s < rings.size(); ++s)
      if (s != r && inside_ring(rings[s], v))
        throw GeometryError("polygon hole " + std::to_string(r) + " lies inside hole " +
                            std::to_string(s));
  }
}

double polygon_area(const PolygonRings& rings) {
  if (rings.empty()) return 0.0;
  double area = std::abs(polygon_area(rings[0]));
  for (std::size_t r = 1; r < rings.size(); ++r) area -= std::abs(polygon_area(rings[r]));
  return area;
}

namespace {

// Polygons with more edges than this get a grid.
constexpr std::size_t kGridEdges = 64;
// Closer to the boundary than this times the polygon's extent, the sign is the crossing
// test's: there the distances are rounding, and which edge is nearest a guess.
constexpr double kNearBoundary = 1e-9;
// Two distances closer than this times the extent are a tie (rounding is 1e-16 of it).
constexpr double kTie = 1e-12;

// True when the ring runs counterclockwise: its lowest (then leftmost) vertex is a strictly
// convex corner of it, so the turn there says, exactly.
bool counterclockwise(const std::vector<Vec2>& ring) {
  const std::size_t n = ring.size();
  std::size_t low = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (ring[i].y < ring[low].y || (ring[i].y == ring[low].y && ring[i].x < ring[low].x)) low = i;
  return orient2d(ring[(low + n - 1) % n], ring[low], ring[(low + 1) % n]) > 0;
}

}  // namespace

PolygonDistance::PolygonDistance(const PolygonRings& rings) {
  validate_polygon(rings);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const std::vector<Vec2>& ring = rings[r];
    // The inside lies left of the edges of a counterclockwise outer ring or a clockwise hole.
    const int inside = counterclockwise(ring) == (r == 0) ? 1 : -1;
    const std::size_t first = a_.size(), n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      a_.push_back(ring[i]);
      b_.push_back(ring[(i + 1) % n]);
      next_.push_back(first + (i + 1) % n);
      prev_.push_back(first + (i + n - 1) % n);
      inside_.push_back(static_cast<signed char>(inside));
      bounds_.extend(ring[i]);
    }
  }
  extent_ = std::max(bounds_.width(), bounds_.height());
  if (a_.size() <= kGridEdges) return;
  // About two edges per cell.
  const int n = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(a_.size()) / 2.0)), 1, 2048);
  const double cell = extent_ / n;
  grid_ = GridFrame{.lo = bounds_.lo,
                    .cell = cell,
                    .nx = std::max(1, static_cast<int>(std::ceil(bounds_.width() / cell))),
                    .ny = std::max(1, static_cast<int>(std::ceil(bounds_.height() / cell)))};
  auto rows_of = [&](std::size_t e) {
    return std::pair{grid_.clamped_row(std::min(a_[e].y, b_[e].y)), grid_.clamped_row(std::max(a_[e].y, b_[e].y))};
  };
  cells_ = CellLists(grid_.cells(), a_.size(), [&](std::size_t e, auto&& emit) {
    const int x0 = grid_.clamped_column(std::min(a_[e].x, b_[e].x)), x1 = grid_.clamped_column(std::max(a_[e].x, b_[e].x));
    const auto [y0, y1] = rows_of(e);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) emit(grid_.index(x, y));
  });
  rows_ = CellLists(static_cast<std::size_t>(grid_.ny), a_.size(), [&](std::size_t e, auto&& emit) {
    const auto [y0, y1] = rows_of(e);
    for (int y = y0; y <= y1; ++y) emit(static_cast<std::size_t>(y));
  });
}

PolygonDistance::Nearest PolygonDistance::nearest(Vec2 p) const {
  Nearest best{std::numeric_limits<double>::infinity(), 0, 0.0, true};
  // Distances within `tie` of the best are equal to rounding: if such an edge's nearest
  // point is another than the best's (not the same corner), which edge is nearest is
  // uncertain. `slack` is that band in squared distances.
  const double tie = kTie * extent_;
  double slack = 0.0;
  Vec2 best_point{};
  auto consider = [&](std::size_t e) {
    const Vec2 a = a_[e], b = b_[e];
    const double t = segment_parameter(p, a, b), d2 = segment_distance2(p, a, b, t);
    if (d2 > best.d2 + slack) return;
    const bool clearly_nearer = d2 < best.d2 - slack;
    const Vec2 q = t == 0.0 ? a : (t == 1.0 ? b : a + t * (b - a));
    if (!clearly_nearer && !(q == best_point)) best.certain = false;
    if (clearly_nearer || d2 < best.d2) {
      best = {d2, e, t, clearly_nearer || best.certain};
      best_point = q;
      slack = tie * (2.0 * std::sqrt(d2) + tie);
    }
  };
  if (grid_.empty()) {
    for (std::size_t e = 0; e < a_.size(); ++e) consider(e);
    return best;
  }
  // Square rings of cells around p's (clamped) cell, until the ring is farther than the
  // best distance found: every edge in a nearer cell has been seen.
  const int qx = grid_.clamped_column(p.x), qy = grid_.clamped_row(p.y);
  // How far p lies outside the grid along each axis: rings count from the clamped cell.
  const double out_x = std::max(0.0, std::max(bounds_.lo.x - p.x, p.x - bounds_.hi.x));
  const double out_y = std::max(0.0, std::max(bounds_.lo.y - p.y, p.y - bounds_.hi.y));
  const int rings = std::max(grid_.nx, grid_.ny);
  for (int r = 0; r <= rings; ++r) {
    // A cell of ring r is r columns or r rows from the clamped cell: along that axis at
    // least (r - 1) cells plus p's distance outside, along the other p's distance outside.
    const double step = std::max(0, r - 1) * grid_.cell;
    const double reach = std::min(std::hypot(out_x + step, out_y), std::hypot(out_x, out_y + step));
    if (r > 0 && reach > 0.0 && reach * reach > best.d2) break;
    grid_.for_ring(qx, qy, r, [&](int x, int y) {
      for (int e : cells_[grid_.index(x, y)]) consider(static_cast<std::size_t>(e));
    });
  }
  return best;
}

bool PolygonDistance::inside_by_nearest(Vec2 p, const Nearest& n) const {
  const std::size_t e = n.edge;
  const int side = inside_[e];  // orientations times this: > 0 toward the inside
  // The nearest point an end of e (a corner), or between (then e's side decides).
  std::size_t first = e, second = e;  // the corner's edges, into and out of it
  if (n.t == 0.0) first = prev_[e];
  else if (n.t == 1.0) second = next_[e];
  else return side * orient2d(a_[e], b_[e], p) > 0;
  // The corner at the vertex first's end = second's start: inside a convex corner is on
  // the inner side of both edges, inside a reflex one on the inner side of either.
  const Vec2 u = a_[first], v = a_[second], w = b_[second];
  const bool in_first = side * orient2d(u, v, p) > 0, in_second = side * orient2d(v, w, p) > 0;
  return side * orient2d(u, v, w) > 0 ? in_first && in_second : in_first || in_second;
}

bool PolygonDistance::contains(Vec2 p) const {
  if (!bounds_.contains(p)) return false;
  bool odd = false;
  auto crosses = [&](std::size_t e) {  // false: p lies on the edge
    const Vec2 a = a_[e], b = b_[e];
    if ((a.y > p.y) != (b.y > p.y)) {
      const int o = orient2d(a, b, p);
      if (o == 0) return false;  // on the edge
      if (b.y > a.y ? o > 0 : o < 0) odd = !odd;
    } else if ((a.y == p.y || b.y == p.y) && p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) &&
               orient2d(a, b, p) == 0) {
      return false;  // on an edge the crossing test does not see: horizontal, or at a vertex
    }
    return true;
  };
  if (grid_.empty()) {
    for (std::size_t e = 0; e < a_.size(); ++e)
      if (!crosses(e)) return false;
  } else {
    for (int e : rows_[static_cast<std::size_t>(grid_.clamped_row(p.y))])
      if (!crosses(static_cast<std::size_t>(e))) return false;
  }
  return odd;
}

double PolygonDistance::operator()(Vec2 p) const {
  const Nearest n = nearest(p);
  const double d = std::sqrt(n.d2);
  if (!bounds_.contains(p)) return d;
  // Within rounding of the boundary, or where another edge is as near to rounding (a
  // needle thinner than rounding), the nearest edge is not certain: the crossing test decides.
  if (d <= kNearBoundary * extent_ || !n.certain) return contains(p) ? -d : d;
  return inside_by_nearest(p, n) ? -d : d;
}

}  // namespace grainmesh
