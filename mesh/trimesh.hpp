// The triangle mesh that the mesh stage produces and the export stage writes.
#pragma once

#include <array>
#include <vector>

#include "common/geometry.hpp"
#include "mesh/mesh_edge.hpp"

namespace grainmesh {

struct TriMesh {
  std::vector<Vec2> points;                   // #P positions
  std::vector<std::array<int, 3>> triangles;  // #T vertex ids into points, counter-clockwise
};

// Every edge once, sorted by (min(a,b), max(a,b)). Throws GeometryError when an edge has
// more than two triangles or two triangles that run it the same way (a non-manifold or
// inconsistently oriented mesh).
std::vector<MeshEdge> mesh_edges(const TriMesh& mesh);

// Signed area of triangle t (> 0 when counter-clockwise).
double triangle_area(const TriMesh& mesh, int t);
Vec2 triangle_centroid(const TriMesh& mesh, int t);
double mesh_area(const TriMesh& mesh);

// Ids of the points on boundary edges, ascending.
std::vector<int> boundary_points(const TriMesh& mesh, const std::vector<MeshEdge>& edges);

// Checks the invariants every stage promises: ids in range, every triangle counter-clockwise with positive area (exact test), every
// point used, edges manifold. Throws GeometryError naming the first violation.
void validate(const TriMesh& mesh);

}  // namespace grainmesh
