// Which triangle holds each directed edge (a -> b, counter-clockwise in it) of a triangle
// mesh, kept up to date as triangles change: the neighbour lookups of the dual mesh and of
// the conforming copy it is built on. Internal to gm_mesh.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>

namespace grainmesh::mesh_detail {

// One key per ordered pair of point ids.
inline std::uint64_t edge_key(int a, int b) {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32 | static_cast<std::uint32_t>(b);
}

class TriangleOfEdge {
 public:
  // Triangle t with these corners holds its three directed edges.
  void enter(const std::array<int, 3>& corners, int t) {
    for (int k = 0; k < 3; ++k) map_[edge_key(corners[k], corners[(k + 1) % 3])] = t;
  }
  void erase(int a, int b) { map_.erase(edge_key(a, b)); }
  void clear() { map_.clear(); }
  // The triangle holding a -> b, or -1.
  int holding(int a, int b) const {
    const auto it = map_.find(edge_key(a, b));
    return it == map_.end() ? -1 : it->second;
  }

 private:
  std::unordered_map<std::uint64_t, int> map_;
};

}  // namespace grainmesh::mesh_detail
