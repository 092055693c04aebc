#include "mesh/trimesh.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

#include "common/errors.hpp"
#include "common/predicates.hpp"
#include "mesh/edge_list.hpp"

namespace grainmesh {

std::vector<MeshEdge> mesh_edges(const TriMesh& mesh) {
  return mesh_detail::edges_of_rings(
      mesh.points.size(), mesh.triangles.size(),
      [&](std::size_t t) { return std::span<const int>(mesh.triangles[t].data(), 3); }, "triangle");
}

double triangle_area(const TriMesh& mesh, int t) {
  const auto& v = mesh.triangles[t];
  return 0.5 * signed_area2(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]]);
}

Vec2 triangle_centroid(const TriMesh& mesh, int t) {
  const auto& v = mesh.triangles[t];
  return (mesh.points[v[0]] + mesh.points[v[1]] + mesh.points[v[2]]) / 3.0;
}

double mesh_area(const TriMesh& mesh) {
  double area = 0.0;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) area += triangle_area(mesh, t);
  return area;
}

std::vector<int> boundary_points(const TriMesh& mesh, const std::vector<MeshEdge>& edges) {
  std::vector<char> on(mesh.points.size(), 0);
  for (const auto& e : edges)
    if (e.right < 0) on[e.a] = on[e.b] = 1;
  std::vector<int> ids;
  for (int i = 0; i < static_cast<int>(on.size()); ++i)
    if (on[i]) ids.push_back(i);
  return ids;
}

void validate(const TriMesh& mesh) {
  const int np = static_cast<int>(mesh.points.size());
  std::vector<char> used(mesh.points.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t];
    for (int id : v) {
      if (id < 0 || id >= np)
        throw GeometryError("mesh: triangle " + std::to_string(t) + " has point id " + std::to_string(id) +
                            " out of range");
      used[id] = 1;
    }
    if (orient2d(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]]) <= 0)
      throw GeometryError("mesh: triangle " + std::to_string(t) + " is inverted or has zero area");
  }
  for (int i = 0; i < np; ++i) {
    if (!used[i]) throw GeometryError("mesh: point " + std::to_string(i) + " belongs to no triangle");
    if (!is_finite(mesh.points[i])) throw GeometryError("mesh: point " + std::to_string(i) + " is not finite");
  }
  mesh_edges(mesh);  // throws on non-manifold edges
}

}  // namespace grainmesh
