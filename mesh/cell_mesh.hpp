// Meshes of polygonal cells: the mesh stage's triangles, or the polygons of their dual
// (dual_mesh.hpp). Cells are counter-clockwise rings of point ids.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "common/geometry.hpp"
#include "mesh/trimesh.hpp"

namespace grainmesh {

struct CellMesh {
  std::vector<Vec2> points;
  std::vector<int> start{0};  // #C + 1: cell c's corners are corners[start[c] .. start[c + 1])
  std::vector<int> corners;

  std::size_t cells() const { return start.size() - 1; }
  std::span<const int> cell(std::size_t c) const {
    return {corners.data() + start[c], static_cast<std::size_t>(start[c + 1] - start[c])};
  }
  // Appends a cell with these corners (counter-clockwise).
  void add_cell(std::span<const int> ring) {
    corners.insert(corners.end(), ring.begin(), ring.end());
    start.push_back(static_cast<int>(corners.size()));
  }
};

// One cell per triangle, in order; the same points.
CellMesh cell_mesh(const TriMesh& mesh);
// The triangles back when every cell is one; nullopt otherwise.
std::optional<TriMesh> as_triangles(const CellMesh& mesh);

// Signed area of cell c (> 0 when counter-clockwise) and its centroid (a triangle's:
// triangle_centroid's bits). No allocation: these run once per cell in every stage.
double cell_area(const CellMesh& mesh, std::size_t c);
Vec2 cell_centroid(const CellMesh& mesh, std::size_t c);
// Every cell's cell_area, in order.
std::vector<double> cell_areas(const CellMesh& mesh);

// Triangles and cells read alike, for code written once for both (the conformity checker,
// the VTU and PNG writers) without copying a triangle mesh into a CellMesh.
inline std::size_t cell_count(const TriMesh& mesh) { return mesh.triangles.size(); }
inline std::size_t cell_count(const CellMesh& mesh) { return mesh.cells(); }
inline std::span<const int> cell_ring(const TriMesh& mesh, std::size_t c) { return mesh.triangles[c]; }
inline std::span<const int> cell_ring(const CellMesh& mesh, std::size_t c) { return mesh.cell(c); }
inline double cell_area(const TriMesh& mesh, std::size_t c) { return triangle_area(mesh, static_cast<int>(c)); }
inline Vec2 cell_centroid(const TriMesh& mesh, std::size_t c) { return triangle_centroid(mesh, static_cast<int>(c)); }

// Every edge once, as mesh_edges(TriMesh) gives them: `left` the cell in which the edge
// runs a -> b counter-clockwise, `right` the cell on the other side or -1. Throws
// GeometryError for an edge of more than two cells or two cells running it one way.
std::vector<MeshEdge> mesh_edges(const CellMesh& mesh);

// The invariants the export relies on: every cell at least three corners, ids in range,
// no corner repeated in a cell, positive area, every point used, edges manifold. Throws
// GeometryError naming the first violation.
void validate(const CellMesh& mesh);

}  // namespace grainmesh
