#include "mesh/conforming_delaunay.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "common/errors.hpp"
#include "mesh/delaunay.hpp"
#include "mesh/directed_edges.hpp"

namespace grainmesh {

namespace {

constexpr int kRounds = 4;

using mesh_detail::edge_key;

class Conformer {
 public:
  Conformer(const TriMesh& mesh, const std::vector<int>& label, const PeriodicPairs& pairs)
      : out_{mesh, label, {}, pairs} {
    if (label.size() != mesh.triangles.size())
      throw GeometryError("dual mesh: " + std::to_string(label.size()) + " labels for " +
                          std::to_string(mesh.triangles.size()) + " triangles");
    out_.origin.resize(mesh.triangles.size());
    std::iota(out_.origin.begin(), out_.origin.end(), 0);
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) enter(t);
    for (int axis : {0, 1})
      for (const auto& [lo, hi] : axis == 0 ? pairs.axis[0] : pairs.axis[1]) {
        image_[axis][lo] = hi;
        image_[axis][hi] = lo;
        low_[axis].insert(lo);
      }
  }

  ConformingMesh run() && {
    for (int round = 0; round < kRounds; ++round) {
      flip_all();
      const std::vector<std::pair<int, int>> edges = encroached_edges();
      if (edges.empty()) break;
      for (const auto& [a, b] : edges) split(a, b);
      pair_midpoints(edges);
    }
    flip_all();
    for (int t = 0; t < static_cast<int>(out_.mesh.triangles.size()); ++t)
      for (int k = 0; k < 3; ++k)
        if (encroaches(t, k)) {
          ++out_.encroaching;
          break;
        }
    return std::move(out_);
  }

 private:
  const std::array<int, 3>& corners(int t) const { return out_.mesh.triangles[t]; }
  Vec2 point(int v) const { return out_.mesh.points[v]; }
  int holding(int a, int b) const { return triangle_of_.holding(a, b); }
  void enter(int t) { triangle_of_.enter(corners(t), t); }
  // The edge from corner k to corner k + 1 of t bounds t's label.
  bool bounds_label(int t, int k) const {
    const int u = holding(corners(t)[(k + 1) % 3], corners(t)[k]);
    return u < 0 || out_.label[u] != out_.label[t];
  }
  bool encroaches(int t, int k) const {
    if (!bounds_label(t, k)) return false;
    const Vec2 a = point(corners(t)[k]), b = point(corners(t)[(k + 1) % 3]), c = point(corners(t)[(k + 2) % 3]);
    static const double limit = std::cos(kEncroachDegrees * std::numbers::pi / 180.0);
    return dot(a - c, b - c) < limit * std::sqrt(norm2(a - c) * norm2(b - c));
  }

  // The side edge a -> b's image across the cell (as held by its triangle), or {-1, -1}.
  std::pair<int, int> image_edge(int a, int b, int axis) const {
    const auto ia = image_[axis].find(a), ib = image_[axis].find(b);
    if (ia == image_[axis].end() || ib == image_[axis].end()) return {-1, -1};
    if (holding(ia->second, ib->second) >= 0) return {ia->second, ib->second};
    if (holding(ib->second, ia->second) >= 0) return {ib->second, ia->second};
    return {-1, -1};
  }

  // The encroached edges, each once as its triangle holds it, with the periodic images
  // of side edges; a side edge whose ends are paired but whose image is not an edge is
  // left alone (its midpoint would have no partner).
  std::vector<std::pair<int, int>> encroached_edges() const {
    std::vector<std::pair<int, int>> edges;
    std::unordered_set<std::uint64_t> seen;
    auto add = [&](int a, int b) {
      if (seen.insert(edge_key(std::min(a, b), std::max(a, b))).second) edges.push_back({a, b});
    };
    for (int t = 0; t < static_cast<int>(out_.mesh.triangles.size()); ++t)
      for (int k = 0; k < 3; ++k) {
        if (!encroaches(t, k)) continue;
        const int a = corners(t)[k], b = corners(t)[(k + 1) % 3];
        std::vector<std::pair<int, int>> images;
        bool paired = true;
        if (holding(b, a) < 0)
          for (int axis : {0, 1}) {
            if (!image_[axis].contains(a) || !image_[axis].contains(b)) continue;
            const auto image = image_edge(a, b, axis);
            if (image.first < 0) paired = false;
            else images.push_back(image);
          }
        if (!paired) continue;
        add(a, b);
        for (const auto& [p, q] : images) add(p, q);
      }
    return edges;
  }

  // Splits the edge a -> b (held by a triangle) and the triangle across it at its midpoint.
  void split(int a, int b) {
    const int t = holding(a, b), u = holding(b, a);
    const int m = static_cast<int>(out_.mesh.points.size());
    out_.mesh.points.push_back(0.5 * (point(a) + point(b)));
    midpoint_[edge_key(std::min(a, b), std::max(a, b))] = m;
    triangle_of_.erase(a, b);
    triangle_of_.erase(b, a);
    for (const auto& [tri, from, to] : {std::tuple{t, a, b}, std::tuple{u, b, a}}) {
      if (tri < 0) continue;
      const auto c = corners(tri);
      const int apex = c[0] != from && c[0] != to ? c[0] : (c[1] != from && c[1] != to ? c[1] : c[2]);
      out_.mesh.triangles[tri] = {from, m, apex};
      out_.mesh.triangles.push_back({m, to, apex});
      out_.label.push_back(out_.label[tri]);
      out_.origin.push_back(out_.origin[tri]);
      enter(tri);
      enter(static_cast<int>(out_.mesh.triangles.size()) - 1);
    }
    ++out_.splits;
  }

  // Pairs the midpoints of the side edges split with their images (low side first).
  void pair_midpoints(const std::vector<std::pair<int, int>>& edges) {
    for (int axis : {0, 1})
      for (const auto& [a, b] : edges) {
        if (!low_[axis].contains(a) || !low_[axis].contains(b)) continue;
        const auto ia = image_[axis].find(a), ib = image_[axis].find(b);
        if (ia == image_[axis].end() || ib == image_[axis].end()) continue;
        const auto it = midpoint_.find(edge_key(std::min(ia->second, ib->second), std::max(ia->second, ib->second)));
        if (it == midpoint_.end()) continue;
        const int lo = midpoint_.at(edge_key(std::min(a, b), std::max(a, b))), hi = it->second;
        (axis == 0 ? out_.pairs.axis[0] : out_.pairs.axis[1]).push_back({lo, hi});
        image_[axis][lo] = hi;
        image_[axis][hi] = lo;
        low_[axis].insert(lo);
      }
  }

  // Lawson's flips (exact predicates) over the edges inside each label until every one is
  // locally Delaunay: edges between labels, or on the boundary, stay.
  void flip_all() {
    Triangulation t{out_.mesh.triangles, {}};
    t.neighbours.resize(t.triangles.size());
    for (int s = 0; s < static_cast<int>(t.triangles.size()); ++s)
      for (int i = 0; i < 3; ++i) {
        const int u = holding(corners(s)[(i + 2) % 3], corners(s)[(i + 1) % 3]);
        t.neighbours[s][i] = u >= 0 && out_.label[u] == out_.label[s] ? u : -1;
      }
    if (!restore_delaunay(t, out_.mesh.points, &out_.flips, false))
      throw GeometryError("dual mesh: a triangle is turned over");
    out_.mesh.triangles = std::move(t.triangles);  // a flip keeps both slots' labels: they are equal
    triangle_of_.clear();
    for (int s = 0; s < static_cast<int>(out_.mesh.triangles.size()); ++s) enter(s);
  }

  ConformingMesh out_;
  mesh_detail::TriangleOfEdge triangle_of_;
  std::unordered_map<std::uint64_t, int> midpoint_;     // (low, high) of a split edge -> its midpoint
  std::array<std::unordered_map<int, int>, 2> image_;   // per axis: a side point's image, both ways
  std::array<std::unordered_set<int>, 2> low_;          // per axis: the points on the low side
};

}  // namespace

ConformingMesh conforming_delaunay(const TriMesh& mesh, const std::vector<int>& label, const PeriodicPairs& pairs) {
  return Conformer(mesh, label, pairs).run();
}

}  // namespace grainmesh
