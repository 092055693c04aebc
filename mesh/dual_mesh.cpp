#include "mesh/dual_mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "common/errors.hpp"

namespace grainmesh {

namespace {

std::uint64_t edge_key(int a, int b) {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32 | static_cast<std::uint32_t>(b);
}

// A triangle's centre (see kCircumcentreMargin); true when it is the circumcentre.
std::pair<Vec2, bool> triangle_centre(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 ab = b - a, ac = c - a;
  const double d = 2.0 * cross(ab, ac);
  const Vec2 centre = a + Vec2{(ac.y * norm2(ab) - ab.y * norm2(ac)) / d, (ab.x * norm2(ac) - ac.x * norm2(ab)) / d};
  const double area2 = cross(ab, ac);
  const double la = signed_area2(centre, b, c) / area2, lb = signed_area2(a, centre, c) / area2,
               lc = signed_area2(a, b, centre) / area2;
  if (std::min({la, lb, lc}) >= kCircumcentreMargin) return {centre, true};
  return {(a + b + c) / 3.0, false};
}

// The dual's candidate points: node v is v, the midpoint of edge e is N + e, the centre
// of triangle t is N + E + t; only those some cell uses are kept, in this order.
class DualBuilder {
 public:
  DualBuilder(const TriMesh& mesh, const std::vector<int>& label) : mesh_(mesh), label_(label) {
    validate(mesh);
    if (label.size() != mesh.triangles.size())
      throw GeometryError("dual mesh: " + std::to_string(label.size()) + " labels for " +
                          std::to_string(mesh.triangles.size()) + " triangles");
    const int nt = static_cast<int>(mesh.triangles.size());
    edges_ = mesh_edges(mesh);
    for (int e = 0; e < static_cast<int>(edges_.size()); ++e) {
      edge_id_[edge_key(std::min(edges_[e].a, edges_[e].b), std::max(edges_[e].a, edges_[e].b))] = e;
    }
    at_node_.resize(mesh.points.size());
    centre_.reserve(nt);
    for (int t = 0; t < nt; ++t) {
      const auto& v = mesh.triangles[t];
      for (int k = 0; k < 3; ++k) {
        at_node_[v[k]].push_back(t);
        triangle_of_[edge_key(v[k], v[(k + 1) % 3])] = t;
      }
      centre_.push_back(triangle_centre(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]]));
    }
  }

  DualMesh build(const PeriodicPairs& pairs) {
    const std::size_t n = mesh_.points.size(), ne = edges_.size();
    std::vector<std::vector<int>> rings;  // in candidate ids
    DualMesh out;
    for (int v = 0; v < static_cast<int>(n); ++v) {
      for (auto& ring : cells_around(v)) {
        rings.push_back(std::move(ring.first));
        out.node.push_back(v);
        out.triangle.push_back(ring.second);
      }
    }
    // Keep the used candidates, in candidate order.
    std::vector<int> id(n + ne + mesh_.triangles.size(), -1);
    for (const auto& ring : rings)
      for (int p : ring) id[p] = 0;
    for (std::size_t p = 0; p < id.size(); ++p) {
      if (id[p] < 0) continue;
      id[p] = static_cast<int>(out.mesh.points.size());
      out.mesh.points.push_back(position(p));
    }
    for (auto& ring : rings) {
      for (int& p : ring) p = id[p];
      out.mesh.add_cell(ring);
    }
    for (const auto& c : centre_) (c.second ? out.circumcentres : out.centroids) += 1;
    carry_pairs(pairs, id, out.pairs);
    validate(out.mesh);
    return out;
  }

 private:
  int other(int t, int v, int offset) const {  // the corner `offset` places after v in t
    const auto& c = mesh_.triangles[t];
    const int k = c[0] == v ? 0 : (c[1] == v ? 1 : 2);
    return c[(k + offset) % 3];
  }
  // The triangle holding the directed edge a -> b, or -1.
  int holding(int a, int b) const {
    const auto it = triangle_of_.find(edge_key(a, b));
    return it == triangle_of_.end() ? -1 : it->second;
  }
  int midpoint(int a, int b) const {
    return static_cast<int>(mesh_.points.size()) + edge_id_.at(edge_key(std::min(a, b), std::max(a, b)));
  }
  int centre(int t) const { return static_cast<int>(mesh_.points.size() + edges_.size()) + t; }
  Vec2 position(std::size_t p) const {
    const std::size_t n = mesh_.points.size(), ne = edges_.size();
    if (p < n) return mesh_.points[p];
    if (p < n + ne) return 0.5 * (mesh_.points[edges_[p - n].a] + mesh_.points[edges_[p - n].b]);
    return centre_[p - n - ne].first;
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

  // v's cells: each run of equal labels in its fan, as a ring of candidate ids and a
  // triangle of the run.
  std::vector<std::pair<std::vector<int>, int>> cells_around(int v) const {
    auto [order, closed] = fan(v);
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
    // centres are circumcentres: then it lies on the segment joining them.
    auto between = [&](int t, int u, std::vector<int>& ring) {
      if (!(centre_[t].second && centre_[u].second)) ring.push_back(midpoint(v, other(t, v, 2)));
    };
    std::vector<std::pair<std::vector<int>, int>> cells;
    if (closed) {
      std::vector<int> ring;
      for (std::size_t i = 0; i < k; ++i) {
        between(order[(i + k - 1) % k], order[i], ring);
        ring.push_back(centre(order[i]));
      }
      cells.push_back({std::move(ring), order[0]});
      return cells;
    }
    for (std::size_t i = 0; i < k;) {
      std::size_t j = i;
      while (j + 1 < k && label_[order[j + 1]] == label_[order[i]]) ++j;
      std::vector<int> ring{v, midpoint(v, other(order[i], v, 1))};
      for (std::size_t q = i; q <= j; ++q) {
        if (q > i) between(order[q - 1], order[q], ring);
        ring.push_back(centre(order[q]));
      }
      ring.push_back(midpoint(v, other(order[j], v, 2)));
      cells.push_back({std::move(ring), order[i]});
      i = j + 1;
    }
    return cells;
  }

  // The pairs of nodes, and of the midpoints of the side edges whose ends are paired.
  void carry_pairs(const PeriodicPairs& pairs, const std::vector<int>& id, PeriodicPairs& out) const {
    for (const auto& [from, to] : {std::pair{&pairs.x, &out.x}, std::pair{&pairs.y, &out.y}}) {
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

  const TriMesh& mesh_;
  const std::vector<int>& label_;
  std::vector<MeshEdge> edges_;
  std::unordered_map<std::uint64_t, int> edge_id_;      // (low, high) -> edge
  std::unordered_map<std::uint64_t, int> triangle_of_;  // directed edge -> its triangle
  std::vector<std::vector<int>> at_node_;
  std::vector<std::pair<Vec2, bool>> centre_;  // per triangle: its centre, and whether the circumcentre
};

}  // namespace

DualMesh dual_mesh(const TriMesh& mesh, const std::vector<int>& label, const PeriodicPairs& pairs) {
  return DualBuilder(mesh, label).build(pairs);
}

}  // namespace grainmesh
