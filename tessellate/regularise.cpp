// Short-edge removal on the torus graph.
#include "tessellate/regularise.hpp"

#include <algorithm>
#include <tuple>

namespace grainmesh {

namespace {

Corner diff(const Corner& a, const Corner& b) { return Corner{0, b.i - a.i, b.j - a.j}; }

}  // namespace

std::vector<std::vector<int>> vertex_cells(const TorusGraph& g) {
  std::vector<std::vector<int>> out(g.vertices.size());
  for (int c = 0; c < static_cast<int>(g.rings.size()); ++c)
    for (const Corner& k : g.rings[c])
      if (out[k.v].empty() || out[k.v].back() != c) out[k.v].push_back(c);
  for (auto& cells : out) {
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  }
  return out;
}

EdgeRef twin_edge(const TorusGraph& g, const std::vector<std::vector<int>>& vc, EdgeRef e) {
  const auto& ring = g.rings[e.cell];
  const Corner& a = ring[e.at];
  const Corner& b = ring[(e.at + 1) % ring.size()];
  const Corner d = diff(a, b);
  for (int c : vc[b.v]) {
    const auto& r = g.rings[c];
    for (int k = 0; k < static_cast<int>(r.size()); ++k) {
      const Corner& p = r[k];
      const Corner& q = r[(k + 1) % r.size()];
      if (c == e.cell && k == e.at) continue;
      if (p.v == b.v && q.v == a.v && q.i - p.i == -d.i && q.j - p.j == -d.j) return {c, k};
    }
  }
  return {-1, -1};
}

std::vector<EdgeRef> unique_edges(const TorusGraph& g) {
  const auto vc = vertex_cells(g);
  std::vector<EdgeRef> out;
  for (int c = 0; c < static_cast<int>(g.rings.size()); ++c) {
    const auto& ring = g.rings[c];
    for (int k = 0; k < static_cast<int>(ring.size()); ++k) {
      const Corner& a = ring[k];
      const Corner& b = ring[(k + 1) % ring.size()];
      if (canonical_direction(a, b) || twin_edge(g, vc, {c, k}).cell < 0) out.push_back({c, k});
    }
  }
  return out;
}

namespace {

// Collapses the edge from corner a to the next corner b of one ring into its midpoint,
// or leaves everything as it was and returns false.
bool try_collapse(TorusGraph& g, std::vector<std::vector<int>>& vc, Corner a, Corner b, int* removed) {
  const int u = a.v, v = b.v;
  if (u == v) return false;  // an edge to its own image: the cell spans the torus
  const Corner d = diff(a, b);
  const Vec2 mid = g.point(a) + 0.5 * (g.point(b) - g.point(a));
  Corner k{};
  const Vec2 reduced = g.periodic ? reduce_periodic(mid, g.width, g.height, &k) : mid;
  // A corner of u or v keeps its side of the lattice: mid sits in the frame of a, whose
  // shift is (a.i, a.j); b's frame is a's plus d.
  auto moved = [&](Corner c) {
    if (c.v == u) return Corner{u, c.i + k.i - a.i, c.j + k.j - a.j};
    if (c.v == v) return Corner{u, c.i + k.i - a.i - d.i, c.j + k.j - a.j - d.j};
    return c;
  };
  std::vector<int> cells;
  std::set_union(vc[u].begin(), vc[u].end(), vc[v].begin(), vc[v].end(), std::back_inserter(cells));
  std::vector<std::vector<Corner>> saved;
  for (int c : cells) saved.push_back(g.rings[c]);
  const Vec2 saved_pos = g.vertices[u];
  g.vertices[u] = reduced;

  bool ok = true;
  std::vector<int> vanished;
  for (int c : cells) {
    std::vector<Corner> out;
    for (const Corner& c0 : g.rings[c]) {
      const Corner m = moved(c0);
      if (!out.empty() && out.back() == m) continue;
      out.push_back(m);
    }
    while (out.size() > 1 && out.front() == out.back()) out.pop_back();
    int count_u = 0;
    for (const Corner& m : out) count_u += m.v == u ? 1 : 0;
    g.rings[c] = out;
    if (out.size() == 2) {
      vanished.push_back(c);
      continue;
    }
    if (out.size() < 2 || count_u > 1) {
      ok = false;
      break;
    }
    const auto poly = g.polygon(c);
    if (!(polygon_area(poly) > 0.0) || !ring_is_simple(poly)) {
      ok = false;
      break;
    }
  }
  if (ok && static_cast<int>(vanished.size()) >= g.live_cells()) ok = false;
  if (!ok) {
    for (std::size_t n = 0; n < cells.size(); ++n) g.rings[cells[n]] = saved[n];
    g.vertices[u] = saved_pos;
    return false;
  }
  for (int c : vanished) g.rings[c].clear();
  *removed += static_cast<int>(vanished.size());
  // Incidence: v's cells now meet u; v is gone.
  std::vector<int> merged;
  for (int c : cells)
    if (!g.rings[c].empty()) merged.push_back(c);
  vc[u] = merged;
  vc[v].clear();
  for (int c : vanished)
    for (auto& list : vc) std::erase(list, c);
  return true;
}

}  // namespace

int collapse_short_edges(TorusGraph& g, double threshold, int* removed_cells) {
  *removed_cells = 0;
  auto vc = vertex_cells(g);
  int collapsed = 0;
  for (int pass = 0; pass < 100; ++pass) {
    // Short edges of this pass, shortest first; ties by vertex ids for determinism.
    std::vector<std::tuple<double, int, int, int, int>> shorts;
    for (const EdgeRef& e : unique_edges(g)) {
      const auto& ring = g.rings[e.cell];
      const Corner& a = ring[e.at];
      const Corner& b = ring[(e.at + 1) % ring.size()];
      const double len = norm(g.point(b) - g.point(a));
      if (len < threshold) shorts.emplace_back(len, a.v, b.v, b.i - a.i, b.j - a.j);
    }
    if (shorts.empty()) break;
    std::sort(shorts.begin(), shorts.end());
    int done = 0;
    for (const auto& [len, u, v, di, dj] : shorts) {
      // Find the edge again: earlier collapses may have moved or removed it.
      bool found = false;
      Corner a{}, b{};
      for (int c : vc[u]) {
        const auto& ring = g.rings[c];
        for (std::size_t k = 0; k < ring.size() && !found; ++k) {
          const Corner& p = ring[k];
          const Corner& q = ring[(k + 1) % ring.size()];
          if (p.v == u && q.v == v && q.i - p.i == di && q.j - p.j == dj) {
            a = p;
            b = q;
            found = true;
          }
        }
        if (found) break;
      }
      if (!found || !(norm(g.point(b) - g.point(a)) < threshold)) continue;
      if (try_collapse(g, vc, a, b, removed_cells)) ++done;
    }
    collapsed += done;
    if (done == 0) break;
  }
  return collapsed;
}

}  // namespace grainmesh
