// The tessellation's edges by their two end vertices, in either order: how the mesh
// stage finds the seeds of a region's sides.
#pragma once

#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "tessellate/tessellation.hpp"

namespace grainmesh {

class EdgeIndex {
 public:
  explicit EdgeIndex(const Tessellation& t) {
    for (std::size_t e = 0; e < t.edges.size(); ++e) index_[key(t.edges[e].v0, t.edges[e].v1)] = static_cast<int>(e);
  }
  // The edge between vertices a and b, or -1.
  int find(int a, int b) const {
    const auto it = index_.find(key(a, b));
    return it == index_.end() ? -1 : it->second;
  }

 private:
  static std::int64_t key(int a, int b) { return static_cast<std::int64_t>(std::min(a, b)) << 32 | std::max(a, b); }
  std::unordered_map<std::int64_t, int> index_;
};

// The side of the cell edge e runs along, else kNoSide.
inline CellSide edge_side(const Tessellation& t, const TessEdge& e) {
  return cell_side(t, t.vertices[e.v0], t.vertices[e.v1]);
}

}  // namespace grainmesh
