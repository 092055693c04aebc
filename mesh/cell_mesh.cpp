#include "mesh/cell_mesh.hpp"

#include <string>

#include "common/errors.hpp"
#include "common/ring.hpp"
#include "mesh/edge_list.hpp"

namespace grainmesh {

namespace {

std::vector<Vec2> ring_of(const CellMesh& mesh, std::size_t c) {
  std::vector<Vec2> ring;
  for (int v : mesh.cell(c)) ring.push_back(mesh.points[v]);
  return ring;
}

}  // namespace

CellMesh cell_mesh(const TriMesh& mesh) {
  CellMesh out;
  out.points = mesh.points;
  out.corners.reserve(3 * mesh.triangles.size());
  out.start.reserve(mesh.triangles.size() + 1);
  for (const auto& t : mesh.triangles) out.add_cell(t);
  return out;
}

std::optional<TriMesh> as_triangles(const CellMesh& mesh) {
  TriMesh out;
  out.points = mesh.points;
  out.triangles.reserve(mesh.cells());
  for (std::size_t c = 0; c < mesh.cells(); ++c) {
    const std::span<const int> v = mesh.cell(c);
    if (v.size() != 3) return std::nullopt;
    out.triangles.push_back({v[0], v[1], v[2]});
  }
  return out;
}

double cell_area(const CellMesh& mesh, std::size_t c) {
  const std::span<const int> v = mesh.cell(c);
  return ring_area(v.size(), [&](std::size_t k) { return mesh.points[v[k]]; });
}

std::vector<double> cell_areas(const CellMesh& mesh) {
  std::vector<double> out(mesh.cells());
  for (std::size_t c = 0; c < out.size(); ++c) out[c] = cell_area(mesh, c);
  return out;
}

Vec2 cell_centroid(const CellMesh& mesh, std::size_t c) {
  const std::span<const int> v = mesh.cell(c);
  if (v.size() == 3) return (mesh.points[v[0]] + mesh.points[v[1]] + mesh.points[v[2]]) / 3.0;  // as triangle_centroid
  return ring_centroid(v.size(), [&](std::size_t k) { return mesh.points[v[k]]; });
}

std::vector<MeshEdge> mesh_edges(const CellMesh& mesh) {
  return mesh_detail::edges_of_rings(
      mesh.points.size(), mesh.cells(), [&](std::size_t c) { return mesh.cell(c); }, "cell");
}

void validate(const CellMesh& mesh) {
  const std::size_t np = mesh.points.size();
  if (mesh.start.empty() || mesh.start.front() != 0 || static_cast<std::size_t>(mesh.start.back()) != mesh.corners.size())
    throw GeometryError("mesh: the cells' corner offsets do not cover the corner list");
  std::vector<char> used(np, 0);
  for (std::size_t c = 0; c < mesh.cells(); ++c) {
    const std::span<const int> ring = mesh.cell(c);
    const std::string name = "mesh: cell " + std::to_string(c);
    if (ring.size() < 3) throw GeometryError(name + " has fewer than three corners");
    for (int id : ring) {
      if (id < 0 || static_cast<std::size_t>(id) >= np)
        throw GeometryError(name + " has point id " + std::to_string(id) + " out of range");
      if (used[id] == 2) throw GeometryError(name + " has point " + std::to_string(id) + " twice");
      used[id] = 2;
    }
    for (int id : ring) used[id] = 1;
    const std::vector<Vec2> points = ring_of(mesh, c);
    if (!(polygon_area(points) > 0.0)) throw GeometryError(name + " is inverted or has zero area");
    if (!ring_is_simple(points)) throw GeometryError(name + " is not a simple polygon");
  }
  for (std::size_t i = 0; i < np; ++i) {
    if (!used[i]) throw GeometryError("mesh: point " + std::to_string(i) + " belongs to no cell");
    if (!is_finite(mesh.points[i])) throw GeometryError("mesh: point " + std::to_string(i) + " is not finite");
  }
  mesh_edges(mesh);  // throws on non-manifold edges
}

}  // namespace grainmesh
