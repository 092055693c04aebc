#include "mesh/trimesh.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

#include "common/errors.hpp"
#include "common/predicates.hpp"

namespace grainmesh {

std::vector<MeshEdge> mesh_edges(const TriMesh& mesh) {
  // Half-edges bucketed by their lower end (a counting sort, linear), each bucket (a few
  // half-edges) put in order of the higher end by a stable insertion sort, so that equal
  // edges stay in triangle order.
  struct HalfEdge {
    int high, a, b, tri;
  };
  const std::size_t np = mesh.points.size();
  std::vector<std::size_t> start(np + 2, 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      if (a < 0 || b < 0 || static_cast<std::size_t>(a) >= np || static_cast<std::size_t>(b) >= np)
        throw GeometryError("mesh: triangle " + std::to_string(t) + " has a point id out of range");
      ++start[static_cast<std::size_t>(std::min(a, b)) + 2];
    }
  for (std::size_t v = 2; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<HalfEdge> half(3 * mesh.triangles.size());
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      half[start[static_cast<std::size_t>(std::min(a, b)) + 1]++] = {std::max(a, b), a, b, t};
    }
  for (std::size_t v = 0; v < np; ++v)
    for (std::size_t i = start[v] + 1; i < start[v + 1]; ++i)
      for (std::size_t j = i; j > start[v] && half[j - 1].high > half[j].high; --j) std::swap(half[j - 1], half[j]);
  auto same = [](const HalfEdge& x, const HalfEdge& y) { return std::min(x.a, x.b) == std::min(y.a, y.b) && x.high == y.high; };

  std::vector<MeshEdge> edges;
  edges.reserve(half.size() / 2 + 1);
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i + 1;
    while (j < half.size() && same(half[j], half[i])) ++j;
    const HalfEdge& h = half[i];
    if (j - i > 2)
      throw GeometryError("mesh: edge " + std::to_string(h.a) + "-" + std::to_string(h.b) + " has " +
                          std::to_string(j - i) + " triangles");
    if (j - i == 2) {
      const HalfEdge& g = half[i + 1];
      if (g.a == h.a)
        throw GeometryError("mesh: triangles " + std::to_string(h.tri) + " and " + std::to_string(g.tri) +
                            " are oriented inconsistently");
      edges.push_back({h.a, h.b, h.tri, g.tri});
    } else {
      edges.push_back({h.a, h.b, h.tri, -1});
    }
    i = j;
  }
  return edges;
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
