// Lawson's edge flips on the flat Triangulation, and point insertion by a walk (no CGAL
// here: the exact predicates come from common/predicates).
#include <algorithm>
#include <utility>
#include <vector>

#include "common/predicates.hpp"
#include "mesh/delaunay.hpp"

namespace grainmesh {
namespace {

using Check = std::pair<int, int>;  // (triangle, corner): the edge opposite that corner

// Triangle n (none when < 0) had `from` across one edge; now it has `to` there.
void repoint(Triangulation& t, int n, int from, int to) {
  if (n < 0) return;
  for (int& k : t.neighbours[n])
    if (k == from) {
      k = to;
      return;
    }
}

// Flips the edges on `stack`, and those that each flip exposes, until all are locally
// Delaunay. Returns the flips made.
std::size_t flip_until_delaunay(Triangulation& t, std::span<const Vec2> p, std::vector<Check>& stack) {
  auto& tri = t.triangles;
  auto& nb = t.neighbours;
  std::size_t count = 0;
  while (!stack.empty()) {
    const auto [s, i] = stack.back();
    stack.pop_back();
    const int u = nb[s][i];
    if (u < 0) continue;
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    const int j = nb[u][0] == s ? 0 : (nb[u][1] == s ? 1 : 2);
    const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    const int a = tri[s][i], b = tri[s][i1], c = tri[s][i2], d = tri[u][j];
    if (incircle(p[a], p[b], p[c], p[d]) <= 0) continue;
    // s = (a, b, c) and u = (d, c, b) become s = (a, b, d) and u = (d, c, a).
    const int n_ca = nb[s][i1], n_ab = nb[s][i2], n_bd = nb[u][j1], n_dc = nb[u][j2];
    tri[s] = {a, b, d};
    nb[s] = {n_bd, u, n_ab};
    tri[u] = {d, c, a};
    nb[u] = {n_ca, s, n_dc};
    repoint(t, n_bd, u, s);
    repoint(t, n_ca, s, u);
    ++count;
    stack.insert(stack.end(), {{s, 0}, {s, 2}, {u, 0}, {u, 2}});
  }
  return count;
}


// Removes the turned-over triangles on the hull (and those that become hull triangles as
// they go); false when a turned-over triangle is left.
bool trim_hull(Triangulation& t, std::vector<int> turned) {
  auto& tri = t.triangles;
  auto& nb = t.neighbours;
  std::vector<char> dead(tri.size(), 0);
  for (bool progress = true; progress && !turned.empty();) {
    progress = false;
    std::erase_if(turned, [&](int s) {
      if (std::find(nb[s].begin(), nb[s].end(), -1) == nb[s].end()) return false;
      for (int u : nb[s]) repoint(t, u, s, -1);
      dead[s] = 1;
      return progress = true;
    });
  }
  if (!turned.empty()) return false;
  std::vector<int> index(tri.size(), -1);
  int kept = 0;
  for (std::size_t s = 0; s < tri.size(); ++s)
    if (!dead[s]) index[s] = kept++;
  for (std::size_t s = 0; s < tri.size(); ++s) {
    if (dead[s]) continue;
    for (int& u : nb[s]) u = u < 0 ? -1 : index[u];
    tri[index[s]] = tri[s];
    nb[index[s]] = nb[s];
  }
  tri.resize(kept);
  nb.resize(kept);
  return true;
}

}  // namespace

bool restore_delaunay(Triangulation& t, std::span<const Vec2> p, std::size_t* flips, bool hull_may_shrink) {
  const auto& tri = t.triangles;
  const auto& nb = t.neighbours;
  std::vector<int> turned;
  for (std::size_t s = 0; s < tri.size(); ++s)
    if (orient2d(p[tri[s][0]], p[tri[s][1]], p[tri[s][2]]) <= 0) turned.push_back(static_cast<int>(s));
  if (!turned.empty() && !(hull_may_shrink && trim_hull(t, std::move(turned)))) return false;
  std::size_t count = 0;
  std::vector<Check> stack;
  const int n = static_cast<int>(tri.size());
  for (int s = 0; s < n; ++s)
    for (int i = 0; i < 3; ++i) {
      const int u = nb[s][i];
      if (u <= s) continue;  // each edge once, from its lower triangle
      const int d = tri[u][0] + tri[u][1] + tri[u][2] - tri[s][(i + 1) % 3] - tri[s][(i + 2) % 3];
      if (incircle(p[tri[s][0]], p[tri[s][1]], p[tri[s][2]], p[d]) <= 0) continue;
      stack.emplace_back(s, i);
      count += flip_until_delaunay(t, p, stack);
    }
  if (flips) *flips += count;
  return true;
}

bool insert_point(Triangulation& t, std::span<const Vec2> p, int v, int hint) {
  auto& tri = t.triangles;
  auto& nb = t.neighbours;
  const Vec2 q = p[v];
  const int n = static_cast<int>(tri.size());
  if (hint < 0 || hint >= n) return false;
  // Walk towards q, crossing an edge that has q beyond it, for at most n steps.
  int s = hint;
  for (int step = 0;; ++step) {
    if (step > n) return false;
    int beyond = -1, on_edge = 0, beyond_count = 0;
    for (int i = 0; i < 3; ++i) {
      const int o = orient2d(p[tri[s][(i + 1) % 3]], p[tri[s][(i + 2) % 3]], q);
      if (o < 0 && (beyond < 0 || nb[s][beyond] < 0)) beyond = i;  // an edge with a triangle beyond first
      beyond_count += o < 0;
      on_edge += o == 0;
    }
    if (beyond >= 0 && nb[s][beyond] >= 0) {
      s = nb[s][beyond];
      continue;
    }
    if (on_edge > 0) return false;  // on an edge or a corner: let a new triangulation decide
    std::vector<Check> stack;
    if (beyond < 0) {  // inside s: split it in three around v
      const auto [v0, v1, v2] = tri[s];
      const auto [n0, n1, n2] = nb[s];
      const int a = n, b = n + 1;
      tri[s] = {v0, v1, v};
      nb[s] = {a, b, n2};
      tri.push_back({v1, v2, v});
      nb.push_back({b, s, n0});
      tri.push_back({v2, v0, v});
      nb.push_back({s, a, n1});
      repoint(t, n0, s, a);
      repoint(t, n1, s, b);
      stack = {{s, 2}, {a, 2}, {b, 2}};
    } else {  // beyond the hull edge opposite corner `beyond` of s, and no other: one triangle on it
      if (beyond_count != 1) return false;
      const int a = tri[s][(beyond + 1) % 3], b = tri[s][(beyond + 2) % 3];
      nb[s][beyond] = n;
      tri.push_back({b, a, v});
      nb.push_back({-1, -1, s});
      stack = {{n, 2}};
    }
    flip_until_delaunay(t, p, stack);
    return true;
  }
}

}  // namespace grainmesh
