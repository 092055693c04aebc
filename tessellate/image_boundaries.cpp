#include "tessellate/image_boundaries.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "common/predicates.hpp"
#include "common/ring.hpp"
#include "common/spatial_grid.hpp"

namespace grainmesh {

namespace {

constexpr std::array<int, 4> kDx{1, 0, -1, 0}, kDy{0, 1, 0, -1};

// Douglas-Peucker on points[a .. b]: marks the points kept between them.
void simplify(const std::vector<Vec2>& pts, int a, int b, double tol, std::vector<char>& keep) {
  std::vector<std::pair<int, int>> todo{{a, b}};
  while (!todo.empty()) {
    const auto [s, e] = todo.back();
    todo.pop_back();
    int far = -1;
    double worst = tol * tol;
    for (int k = s + 1; k < e; ++k) {
      const double d = segment_distance2(pts[k], pts[s], pts[e]);
      if (d > worst) worst = d, far = k;
    }
    if (far < 0) continue;
    keep[far] = 1;
    todo.push_back({s, far});
    todo.push_back({far, e});
  }
}

// The point of points[a .. b] farthest from the chord, strictly between; -1 when none.
int farthest(const std::vector<Vec2>& pts, int a, int b) {
  int far = -1;
  double worst = -1.0;
  for (int k = a + 1; k < b; ++k) {
    const double d = segment_distance2(pts[k], pts[a], pts[b]);
    if (d > worst) worst = d, far = k;
  }
  return far;
}

// The chain's kept points at its tolerance: a closed chain keeps at least three corners,
// one sharing both ends with another chain at least one point between them.
void keep_points(Chain& c, bool shares_ends) {
  const auto& pts = c.points;
  const int n = static_cast<int>(pts.size());
  std::vector<char> keep(n, 0);
  keep[0] = keep[n - 1] = 1;
  if (c.first == c.last) {
    int far = 1;
    for (int k = 1; k < n - 1; ++k)
      if (norm2(pts[k] - pts[0]) > norm2(pts[far] - pts[0])) far = k;
    keep[far] = 1;
    simplify(pts, 0, far, c.tolerance, keep);
    simplify(pts, far, n - 1, c.tolerance, keep);
    if (std::count(keep.begin(), keep.end(), 1) < 4) {
      const int a = farthest(pts, 0, far), b = farthest(pts, far, n - 1);
      const double da = a < 0 ? -1 : segment_distance2(pts[a], pts[0], pts[far]);
      const double db = b < 0 ? -1 : segment_distance2(pts[b], pts[far], pts[n - 1]);
      keep[da >= db ? a : b] = 1;
    }
  } else {
    simplify(pts, 0, n - 1, c.tolerance, keep);
    if (shares_ends && n > 2 && std::count(keep.begin(), keep.end(), 1) == 2) keep[farthest(pts, 0, n - 1)] = 1;
  }
  c.kept.clear();
  for (int k = 0; k < n; ++k)
    if (keep[k]) c.kept.push_back(k);
}

// Whether the kept segments s = pq and t = ru meet anywhere but at an end they share.
bool conflict(Vec2 p, Vec2 q, Vec2 r, Vec2 u) {
  const bool pr = p == r, pu = p == u, qr = q == r, qu = q == u;
  if ((pr && qu) || (pu && qr)) return true;  // the same segment twice
  auto overlaps = [](Vec2 o, Vec2 a, Vec2 b) { return orient2d(o, a, b) == 0 && dot(a - o, b - o) > 0.0; };
  if (pr) return overlaps(p, q, u);
  if (pu) return overlaps(p, q, r);
  if (qr) return overlaps(q, p, u);
  if (qu) return overlaps(q, p, r);
  return segments_touch(p, q, r, u);
}

// Marks the chains whose kept form changes the boundaries' topology: a kept segment
// meeting another, or passing over a kept point of any chain (the area between a segment
// and the points it replaces holds it). Returns whether any was marked.
bool mark_conflicts(const std::vector<Chain>& chains, int nx, int ny, std::vector<char>& bad) {
  struct Segment {
    int chain, a, b;  // kept points a < b of it
  };
  std::vector<Segment> segs;
  for (int c = 0; c < static_cast<int>(chains.size()); ++c)
    for (std::size_t k = 0; k + 1 < chains[c].kept.size(); ++k)
      segs.push_back({c, chains[c].kept[k], chains[c].kept[k + 1]});
  auto end_a = [&](const Segment& s) { return chains[s.chain].points[s.a]; };
  auto end_b = [&](const Segment& s) { return chains[s.chain].points[s.b]; };
  GridFrame frame{.lo = {-1.0, -1.0}, .cell = 16.0, .nx = nx / 16 + 2, .ny = ny / 16 + 2};
  auto cells = [&](std::size_t k, auto emit) {
    const Vec2 p = end_a(segs[k]), q = end_b(segs[k]);
    for (int y = frame.row(std::min(p.y, q.y)); y <= frame.row(std::max(p.y, q.y)); ++y)
      for (int x = frame.column(std::min(p.x, q.x)); x <= frame.column(std::max(p.x, q.x)); ++x)
        emit(frame.index(x, y));
  };
  const CellLists lists(frame.cells(), segs.size(), cells);
  bool any = false;
  auto mark = [&](int c) { any = true, bad[c] = 1; };
  for (std::size_t cell = 0; cell < frame.cells(); ++cell) {
    const auto here = lists[cell];
    for (std::size_t x = 0; x < here.size(); ++x)
      for (std::size_t y = x + 1; y < here.size(); ++y) {
        const Segment &s = segs[here[x]], &t = segs[here[y]];
        if (conflict(end_a(s), end_b(s), end_a(t), end_b(t))) mark(s.chain), mark(t.chain);
      }
  }
  // Kept points inside the area a segment sweeps from the points it replaces.
  for (const Chain& c : chains)
    for (int k : c.kept) {
      const Vec2 p = c.points[k];
      const auto near = lists[frame.index(frame.column(p.x), frame.row(p.y))];
      for (int id : near) {
        const Segment& s = segs[id];
        if (s.b - s.a < 2) continue;
        const Vec2 a = end_a(s), b = end_b(s);
        if (p == a || p == b || p.x < std::min(a.x, b.x) - 1 || p.x > std::max(a.x, b.x) + 1 ||
            p.y < std::min(a.y, b.y) - 1 || p.y > std::max(a.y, b.y) + 1)
          continue;
        const auto& pts = chains[s.chain].points;
        const std::vector<Vec2> swept(pts.begin() + s.a, pts.begin() + s.b + 1);
        if (inside_ring(swept, p)) mark(s.chain);
      }
    }
  return any;
}

}  // namespace

std::vector<Chain> trace(const Lattice& L) {
  std::vector<Chain> chains;
  std::vector<char> seen(L.edges(), 0);
  auto walk = [&](int i, int j, int d) {
    Chain c;
    c.first = L.vertex(i, j);
    std::tie(c.left, c.right) = L.sides(i, j, d);
    c.points.push_back({static_cast<double>(i), static_cast<double>(j)});
    for (;;) {
      seen[L.edge(i, j, d)] = 1;
      i += kDx[d], j += kDy[d];
      const int back = (d + 2) % 4;
      if (L.junction(i, j)) break;
      Vec2 here{static_cast<double>(i), static_cast<double>(j)};
      int next = -1;
      if (L.pinch(i, j)) {
        here = L.pinch_corner(i, j, back);
        next = L.partner(i, j, back);
      } else {
        for (int e = 0; e < 4; ++e)
          if (e != back && L.boundary(i, j, e)) next = e;
      }
      if (seen[L.edge(i, j, next)]) break;  // round a closed boundary to where it began
      c.points.push_back(here);
      d = next;
    }
    c.points.push_back({static_cast<double>(i), static_cast<double>(j)});
    c.last = L.vertex(i, j);
    chains.push_back(std::move(c));
  };
  for (int j = 0; j <= L.ny; ++j)
    for (int i = 0; i <= L.nx; ++i)
      if (L.degree(i, j) > 0 && L.junction(i, j))
        for (int d = 0; d < 4; ++d)
          if (L.boundary(i, j, d) && !seen[L.edge(i, j, d)]) walk(i, j, d);
  // What is left are closed boundaries with no junction: each begun at a corner of it that
  // is not a pinch (the end of its first edge found).
  for (int j = 0; j <= L.ny; ++j)
    for (int i = 0; i <= L.nx; ++i)
      if (L.degree(i, j) == 2 && !L.pinch(i, j))
        for (int d = 0; d < 4; ++d)
          if (L.boundary(i, j, d) && !seen[L.edge(i, j, d)]) walk(i, j, d);
  return chains;
}

// Every chain kept at the tolerance, or finer where that changed the topology: a chain in
// conflict halves its tolerance until none is (at zero each chain is as traced).
void simplify_chains(std::vector<Chain>& chains, double tolerance, int nx, int ny) {
  std::map<std::pair<long long, long long>, int> ends;
  for (const Chain& c : chains) ++ends[std::minmax(c.first, c.last)];
  auto shares = [&](const Chain& c) { return ends[std::minmax(c.first, c.last)] > 1; };
  for (Chain& c : chains) {
    c.tolerance = tolerance;
    keep_points(c, shares(c));
  }
  std::vector<char> bad(chains.size(), 0);
  for (int round = 0; mark_conflicts(chains, nx, ny, bad); ++round) {
    if (round > 40)
      throw GeometryError("the traced boundaries could not be simplified without crossing (a grainmesh bug)");
    for (std::size_t c = 0; c < chains.size(); ++c)
      if (bad[c]) {
        chains[c].tolerance = chains[c].tolerance < 0.05 ? 0.0 : 0.5 * chains[c].tolerance;
        keep_points(chains[c], shares(chains[c]));
        bad[c] = 0;
      }
  }
}

}  // namespace grainmesh
