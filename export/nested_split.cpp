#include "export/nested_split.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>

#include "common/errors.hpp"

namespace grainmesh {

namespace {

// Each edge's midpoint, by its ends' ids, appended to `points` once.
template <class Point>
class Midpoints {
 public:
  explicit Midpoints(std::vector<Point>& points) : points_(points) {}
  int operator()(int a, int b) {
    const auto [it, added] = id_.try_emplace(key(a, b), static_cast<int>(points_.size()));
    if (added) {
      const Point pa = points_[static_cast<std::size_t>(a)], pb = points_[static_cast<std::size_t>(b)];
      points_.push_back(0.5 * (pa + pb));
    }
    return it->second;
  }
  // The midpoint of edge (a, b) if it was made, else -1.
  int find(int a, int b) const {
    const auto it = id_.find(key(a, b));
    return it == id_.end() ? -1 : it->second;
  }
  const std::unordered_map<std::uint64_t, int>& edges() const { return id_; }

  static std::pair<int, int> ends(std::uint64_t k) {
    return {static_cast<int>(k >> 32), static_cast<int>(k & 0xffffffffu)};
  }

 private:
  static std::uint64_t key(int a, int b) {
    const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
    return lo << 32 | hi;
  }
  std::vector<Point>& points_;
  std::unordered_map<std::uint64_t, int> id_;
};

// The pairs of `m` extended to the midpoints: an edge whose ends both have images on an
// axis splits at the image of its image edge's midpoint.
template <int D, class Point>
PeriodicPairs split_pairs(const ExportMesh<D>& m, const Midpoints<Point>& mid) {
  PeriodicPairs out = m.pairs;
  for (int axis = 0; axis < D; ++axis) {
    const auto& pairs = m.pairs.axis[static_cast<std::size_t>(axis)];
    if (pairs.empty()) continue;
    std::unordered_map<int, int> image;
    for (const auto& [low, high] : pairs) image.emplace(low, high);
    std::vector<std::pair<int, int>> added;
    for (const auto& [key, middle] : mid.edges()) {
      const auto [a, b] = Midpoints<Point>::ends(key);
      const auto ia = image.find(a), ib = image.find(b);
      if (ia == image.end() || ib == image.end()) continue;
      const int other = mid.find(ia->second, ib->second);
      if (other < 0)
        throw GeometryError("nested refinement: the edge of points " + std::to_string(a) + " and " + std::to_string(b) +
                            " on a low side has no image edge");
      added.emplace_back(middle, other);
    }
    std::sort(added.begin(), added.end());  // the map's order is no order
    auto& axis_pairs = out.axis[static_cast<std::size_t>(axis)];
    axis_pairs.insert(axis_pairs.end(), added.begin(), added.end());
  }
  return out;
}

}  // namespace

ExportMesh<2> split_nested(const ExportMesh<2>& m) {
  ExportMesh<2> out{.mesh = {}, .grain = {}, .phase = {}, .phases = m.phases, .cell = m.cell, .periodic = m.periodic,
                    .pairs = {}};
  out.mesh.points = m.mesh.points;
  Midpoints<Vec2> mid(out.mesh.points);
  const std::size_t cells = m.mesh.cells();
  out.grain.reserve(4 * cells);
  out.phase.reserve(4 * cells);
  for (std::size_t c = 0; c < cells; ++c) {
    const std::span<const int> t = m.mesh.cell(c);
    if (t.size() != 3)
      throw GeometryError("nested refinement: cell " + std::to_string(c) + " has " + std::to_string(t.size()) +
                          " corners; it needs triangles");
    const int a = t[0], b = t[1], c2 = t[2];
    const int ab = mid(a, b), bc = mid(b, c2), ca = mid(c2, a);
    for (const std::array<int, 3>& child : {std::array{a, ab, ca}, std::array{ab, b, bc}, std::array{ca, bc, c2},
                                             std::array{ab, bc, ca}}) {
      out.mesh.add_cell(child);
      out.grain.push_back(m.grain[c]);
      out.phase.push_back(m.phase[c]);
    }
  }
  out.pairs = split_pairs(m, mid);
  return out;
}

ExportMesh<3> split_nested(const ExportMesh<3>& m) {
  ExportMesh<3> out{.mesh = {}, .grain = {}, .phase = {}, .phases = m.phases, .cell = m.cell, .periodic = m.periodic,
                    .pairs = {}};
  out.mesh.points = m.mesh.points;
  Midpoints<Vec3> mid(out.mesh.points);
  const auto& p = out.mesh.points;
  out.grain.reserve(8 * m.mesh.tets.size());
  out.phase.reserve(8 * m.mesh.tets.size());
  for (std::size_t c = 0; c < m.mesh.tets.size(); ++c) {
    const auto [v0, v1, v2, v3] = m.mesh.tets[c];
    const int m01 = mid(v0, v1), m02 = mid(v0, v2), m03 = mid(v0, v3), m12 = mid(v1, v2), m13 = mid(v1, v3),
              m23 = mid(v2, v3);
    std::vector<std::array<int, 4>> children{{v0, m01, m02, m03}, {m01, v1, m12, m13}, {m02, m12, v2, m23},
                                             {m03, m13, m23, v3}};
    // The octahedron's three diagonals; the shortest cuts it into four around itself.
    const std::array<std::array<int, 2>, 3> diagonals{{{m01, m23}, {m02, m13}, {m03, m12}}};
    auto length = [&](const std::array<int, 2>& d) {
      const Vec3 e = p[static_cast<std::size_t>(d[0])] - p[static_cast<std::size_t>(d[1])];
      return dot(e, e);
    };
    std::size_t k = 0;
    for (std::size_t i = 1; i < 3; ++i)
      if (length(diagonals[i]) < length(diagonals[k])) k = i;
    const auto [s, t] = diagonals[k];
    // The ring of four midpoints around the diagonal (s, t), in order: the other two
    // diagonals' ends alternate.
    const auto& u = diagonals[(k + 1) % 3];
    const auto& w = diagonals[(k + 2) % 3];
    const std::array<int, 4> ring{u[0], w[0], u[1], w[1]};
    for (std::size_t i = 0; i < 4; ++i) children.push_back({s, t, ring[i], ring[(i + 1) % 4]});
    for (std::array<int, 4>& tet : children) {
      if (tet_volume(p[static_cast<std::size_t>(tet[0])], p[static_cast<std::size_t>(tet[1])],
                     p[static_cast<std::size_t>(tet[2])], p[static_cast<std::size_t>(tet[3])]) < 0.0)
        std::swap(tet[2], tet[3]);
      out.mesh.tets.push_back(tet);
      out.grain.push_back(m.grain[c]);
      out.phase.push_back(m.phase[c]);
    }
  }
  out.pairs = split_pairs(m, mid);
  return out;
}

}  // namespace grainmesh
