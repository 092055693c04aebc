#include "mesh/dual_mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>

#include "common/errors.hpp"
#include "common/ring.hpp"
#include "mesh/conforming_delaunay.hpp"
#include "mesh/directed_edges.hpp"

namespace grainmesh {

namespace {

// Two neighbours' circumcentres closer than this times their shared edge are one point
// (four nodes on a circle): the face between would have no length.
constexpr double kSameCentre = 1e-9;
// A circumcentre this close to an edge bounding its label (in barycentric coordinates)
// would leave a face of no length along that edge: the centroid instead.
constexpr double kBoundaryMargin = 0.02;

// Two mesh edges from a node continue each other when the sine of their angle is below
// this: nodes placed on a straight grain boundary or side are on it up to rounding.
constexpr double kStraight = 1e-9;

using mesh_detail::edge_key;

Vec2 circumcentre(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 ab = b - a, ac = c - a;
  const double d = 2.0 * cross(ab, ac);
  return a + Vec2{(ac.y * norm2(ab) - ab.y * norm2(ac)) / d, (ab.x * norm2(ac) - ac.x * norm2(ab)) / d};
}

// The dual's candidate points: node v is v, the midpoint of edge e is N + e, the centre
// of triangle t is N + E + t; only those some cell uses are kept, in this order.
class DualBuilder {
 public:
  // The conforming copy of a valid mesh is valid (midpoint splits, exact flips): not
  // validated again; the dual is, at the end.
  explicit DualBuilder(ConformingMesh conforming) : in_(std::move(conforming)), mesh_(in_.mesh), label_(in_.label) {
    const int nt = static_cast<int>(mesh_.triangles.size());
    edges_ = mesh_edges(mesh_);
    for (int e = 0; e < static_cast<int>(edges_.size()); ++e) {
      edge_id_[edge_key(std::min(edges_[e].a, edges_[e].b), std::max(edges_[e].a, edges_[e].b))] = e;
    }
    at_node_.resize(mesh_.points.size());
    for (int t = 0; t < nt; ++t) {
      const auto& v = mesh_.triangles[t];
      for (int k = 0; k < 3; ++k) {
        at_node_[v[k]].push_back(t);
      }
      triangle_of_.enter(v, t);
    }
    choose_centres();
  }

  DualMesh build() {
    std::vector<Cell> cells = all_cells();
    // A cell that is not a simple polygon (a circumcentre past a neighbour that took its
    // centroid, say): its triangles take their centroids, until every cell is simple.
    for (bool again = true; again;) {
      again = false;
      for (const Cell& cell : cells)
        if (!sound(cell.ring))
          for (int t : cell.triangles) again |= std::exchange(use_circumcentre_[t], 0) != 0;
      if (again) {
        settle_centres();
        cells = all_cells();
      }
    }
    return assemble(cells);
  }

 private:
  struct Cell {
    std::vector<int> ring;  // candidate ids
    std::vector<int> triangles;
    int node = -1;
  };

  int other(int t, int v, int offset) const {  // the corner `offset` places after v in t
    const auto& c = mesh_.triangles[t];
    const int k = c[0] == v ? 0 : (c[1] == v ? 1 : 2);
    return c[(k + offset) % 3];
  }
  // The triangle holding the directed edge a -> b, or -1.
  int holding(int a, int b) const { return triangle_of_.holding(a, b); }
  // The triangle across t's edge a -> b when it has t's label, else -1.
  int same_label_across(int t, int a, int b) const {
    const int u = holding(b, a);
    return u >= 0 && label_[u] == label_[t] ? u : -1;
  }
  int midpoint(int a, int b) const {
    return static_cast<int>(mesh_.points.size()) + edge_id_.at(edge_key(std::min(a, b), std::max(a, b)));
  }
  int centre(int t) const { return static_cast<int>(mesh_.points.size() + edges_.size()) + same_[t]; }
  Vec2 position(std::size_t p) const {
    const std::size_t n = mesh_.points.size(), ne = edges_.size();
    if (p < n) return mesh_.points[p];
    if (p < n + ne) return 0.5 * (mesh_.points[edges_[p - n].a] + mesh_.points[edges_[p - n].b]);
    const int t = static_cast<int>(p - n - ne);
    if (use_circumcentre_[t]) return circumcentre_[t];
    const auto& v = mesh_.triangles[t];
    return (mesh_.points[v[0]] + mesh_.points[v[1]] + mesh_.points[v[2]]) / 3.0;
  }

  // Every triangle takes its circumcentre, except one whose circumcentre lies beyond (or
  // on) an edge bounding its label, and then one whose circumcentre lies beyond an edge to
  // a neighbour that does not take its own (the Voronoi face across that edge would fold).
  void choose_centres() {
    const int nt = static_cast<int>(mesh_.triangles.size());
    circumcentre_.resize(nt);
    use_circumcentre_.assign(nt, 1);
    beyond_.assign(nt, -1);
    for (int t = 0; t < nt; ++t) {
      const auto& v = mesh_.triangles[t];
      const Vec2 a = mesh_.points[v[0]], b = mesh_.points[v[1]], c = mesh_.points[v[2]];
      circumcentre_[t] = circumcentre(a, b, c);
      const double area2 = signed_area2(a, b, c);
      const Vec2 cc = circumcentre_[t];
      const double lambda[3] = {signed_area2(cc, b, c) / area2, signed_area2(a, cc, c) / area2,
                                signed_area2(a, b, cc) / area2};
      for (int k = 0; k < 3; ++k) {
        const int u = same_label_across(t, v[(k + 1) % 3], v[(k + 2) % 3]);
        if (u < 0 && lambda[k] < kBoundaryMargin) use_circumcentre_[t] = 0;
        if (u >= 0 && lambda[k] < 0.0) beyond_[t] = u;
      }
    }
    settle_centres();
  }
  void settle_centres() {
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t t = 0; t < beyond_.size(); ++t)
        if (use_circumcentre_[t] && beyond_[t] >= 0 && !use_circumcentre_[beyond_[t]]) {
          use_circumcentre_[t] = 0;
          changed = true;
        }
    }
    // Neighbours' circumcentres that coincide become one point (the lower triangle's).
    same_.resize(mesh_.triangles.size());
    std::iota(same_.begin(), same_.end(), 0);
    for (const MeshEdge& e : edges_) {
      const int t = e.left, u = e.right;
      if (u < 0 || label_[t] != label_[u] || !use_circumcentre_[t] || !use_circumcentre_[u]) continue;
      const double tolerance = kSameCentre * std::sqrt(norm2(mesh_.points[e.a] - mesh_.points[e.b]));
      if (norm2(circumcentre_[t] - circumcentre_[u]) <= tolerance * tolerance) {
        const int rt = root(t), ru = root(u);
        same_[std::max(rt, ru)] = std::min(rt, ru);
      }
    }
    for (std::size_t t = 0; t < same_.size(); ++t) same_[t] = root(static_cast<int>(t));
  }
  int root(int t) const {
    while (same_[t] != t) t = same_[t];
    return t;
  }

  bool sound(const std::vector<int>& ring) const {
    std::vector<Vec2> points;
    for (int p : ring) points.push_back(position(p));
    return ring.size() >= 3 && polygon_area(points) > 0.0 && ring_is_simple(points);
  }

  // The triangles around v counter-clockwise, from one after the boundary (if v is on it);
  // true when they close round v.
  std::pair<std::vector<int>, bool> fan(int v) const {
    const std::vector<int>& all = at_node_[v];
    int first = *std::min_element(all.begin(), all.end());
    bool closed = true;
    for (int t : all)
      if (holding(other(t, v, 1), v) < 0) {  // nothing before t: v's fan starts here
        first = t;
        closed = false;
        break;
      }
    std::vector<int> order{first};
    for (int t = holding(v, other(first, v, 2)); t >= 0 && t != first; t = holding(v, other(t, v, 2)))
      order.push_back(t);
    if (order.size() != all.size())
      throw GeometryError("dual mesh: the triangles around node " + std::to_string(v) + " do not form one fan");
    return {order, closed};
  }

  // The mesh edges v -> a and v -> b continue each other (a, v, b on one line, up to rounding).
  bool straight_through(int v, int a, int b) const {
    const Vec2 va = mesh_.points[a] - mesh_.points[v], vb = mesh_.points[b] - mesh_.points[v];
    return dot(va, vb) < 0.0 && std::abs(cross(va, vb)) <= kStraight * std::sqrt(norm2(va) * norm2(vb));
  }

  std::vector<Cell> all_cells() const {
    std::vector<Cell> cells;
    for (int v = 0; v < static_cast<int>(mesh_.points.size()); ++v)
      for (Cell& cell : cells_around(v)) cells.push_back(std::move(cell));
    return cells;
  }

  // v's cells: one for each run of equal labels in its fan.
  std::vector<Cell> cells_around(int v) const {
    auto [order, closed] = fan(v);
    const bool open_fan = !closed;
    const std::size_t k = order.size();
    // A closed fan of several labels starts where the label changes.
    if (closed) {
      for (std::size_t i = 0; i < k; ++i)
        if (label_[order[i]] != label_[order[(i + k - 1) % k]]) {
          std::rotate(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(i), order.end());
          closed = false;
          break;
        }
    }
    // The midpoint of the edge from v between triangles t and u (u after t), unless both
    // take circumcentres: then the face is the segment joining them, on the edge's bisector.
    auto between = [&](int t, int u, std::vector<int>& ring) {
      if (!(use_circumcentre_[t] && use_circumcentre_[u])) ring.push_back(midpoint(v, other(t, v, 2)));
    };
    std::vector<Cell> cells;
    if (closed) {
      Cell cell{{}, order, v};
      for (std::size_t i = 0; i < k; ++i) {
        between(order[(i + k - 1) % k], order[i], cell.ring);
        cell.ring.push_back(centre(order[i]));
      }
      cells.push_back(std::move(cell));
    } else {
      for (std::size_t i = 0; i < k;) {
        std::size_t j = i;
        while (j + 1 < k && label_[order[j + 1]] == label_[order[i]]) ++j;
        Cell cell{{v, midpoint(v, other(order[i], v, 1))}, {}, v};
        for (std::size_t q = i; q <= j; ++q) {
          if (q > i) between(order[q - 1], order[q], cell.ring);
          cell.ring.push_back(centre(order[q]));
          cell.triangles.push_back(order[q]);
        }
        cell.ring.push_back(midpoint(v, other(order[j], v, 2)));
        cells.push_back(std::move(cell));
        i = j + 1;
      }
      // A node inside a straight side or grain boundary (one cell on a side, two halves
      // inside the cell): the cut runs straight through it, so it is no corner, and each
      // half's cut is one face, centred near the node, not two.
      const std::size_t first_run = cells.front().triangles.size();
      if (cells.size() == (open_fan ? 1u : 2u) &&
          straight_through(v, other(order.front(), v, 1), other(order[first_run - 1], v, 2)))
        for (Cell& cell : cells) cell.ring.erase(cell.ring.begin());
    }
    for (Cell& cell : cells) {  // coinciding circumcentres appear once
      auto& r = cell.ring;
      r.erase(std::unique(r.begin(), r.end()), r.end());
      while (r.size() > 1 && r.front() == r.back()) r.pop_back();
    }
    return cells;
  }

  DualMesh assemble(std::vector<Cell>& cells) const {
    const std::size_t n = mesh_.points.size(), ne = edges_.size();
    DualMesh out;
    // Keep the used candidates, in candidate order.
    std::vector<int> id(n + ne + mesh_.triangles.size(), -1);
    for (const Cell& cell : cells)
      for (int p : cell.ring) id[p] = 0;
    for (std::size_t p = 0; p < id.size(); ++p) {
      if (id[p] < 0) continue;
      id[p] = static_cast<int>(out.mesh.points.size());
      out.mesh.points.push_back(position(p));
    }
    for (Cell& cell : cells) {
      for (int& p : cell.ring) p = id[p];
      out.mesh.add_cell(cell.ring);
      out.node.push_back(cell.node);
      out.triangle.push_back(in_.origin[cell.triangles.front()]);
    }
    for (char c : use_circumcentre_) (c ? out.circumcentres : out.centroids) += 1;
    out.splits = in_.splits;
    out.flips = in_.flips;
    carry_pairs(id, out.pairs);
    validate(out.mesh);
    return out;
  }

  // The pairs of nodes, and of the midpoints of the side edges whose ends are paired.
  void carry_pairs(const std::vector<int>& id, PeriodicPairs& out) const {
    for (const auto& [from, to] : {std::pair{&in_.pairs.axis[0], &out.axis[0]}, std::pair{&in_.pairs.axis[1], &out.axis[1]}}) {
      std::unordered_map<int, int> image;
      for (const auto& [lo, hi] : *from) {
        image[lo] = hi;
        if (id[lo] >= 0 && id[hi] >= 0) to->push_back({id[lo], id[hi]});
      }
      for (const MeshEdge& e : edges_) {
        if (e.right >= 0) continue;
        const auto a = image.find(e.a), b = image.find(e.b);
        if (a == image.end() || b == image.end()) continue;
        const auto it = edge_id_.find(edge_key(std::min(a->second, b->second), std::max(a->second, b->second)));
        if (it == edge_id_.end()) continue;
        const int lo = id[midpoint(e.a, e.b)], hi = id[static_cast<int>(mesh_.points.size()) + it->second];
        if (lo >= 0 && hi >= 0) to->push_back({lo, hi});
      }
    }
  }

  const ConformingMesh in_;
  const TriMesh& mesh_;
  const std::vector<int>& label_;
  std::vector<MeshEdge> edges_;
  std::unordered_map<std::uint64_t, int> edge_id_;      // (low, high) -> edge
  mesh_detail::TriangleOfEdge triangle_of_;
  std::vector<std::vector<int>> at_node_;
  std::vector<Vec2> circumcentre_;     // #T
  std::vector<char> use_circumcentre_; // #T: the circumcentre is the triangle's centre, else the centroid
  std::vector<int> beyond_;            // #T: the same-label neighbour the circumcentre lies in the direction of, or -1
  std::vector<int> same_;              // #T: the triangle whose centre stands for this one's
};

}  // namespace

DualMesh dual_mesh(const TriMesh& mesh, const std::vector<int>& label, const PeriodicPairs& pairs) {
  validate(mesh);
  return DualBuilder(conforming_delaunay(mesh, label, pairs)).build();
}

}  // namespace grainmesh
