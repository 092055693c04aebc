// A plane section of a 3D tessellation, as 2D polygons: what tessellation.png shows of a
// 3D cell and what a user compares with a micrograph.
#pragma once

#include <vector>

#include "mesh/cell_mesh.hpp"
#include "mesh/tetmesh.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// The section z = `z` of every region: one polygon per region the plane cuts
// (passes through, not only touches),
// counter-clockwise in (x, y), with the grain and phase of each. Points where the plane
// crosses an edge of the tessellation are shared by the polygons around that edge.
struct Section {
  CellMesh cells;
  std::vector<int> grain;  // #cells
  std::vector<int> phase;  // #cells
  std::vector<int> tet;    // #cells: the tetrahedron cut (mesh_section only)
};
Section tessellation_section(const Tessellation3& t, double z);

// Where a section asked for at `z` is drawn: z itself, unless a vertex of the tessellation
// lies in that plane (a face of a laminate does, between its layers); then the middle of
// the gap between that level of vertices and the next one above (below, at the top), where
// the plane cuts every region it meets through its inside.
double section_height(const Tessellation3& t, double z);

// The section z = `z` of a tetrahedral mesh: a triangle or quadrilateral per tetrahedron
// the plane passes through, with that tetrahedron's grain and phase (and index).
Section mesh_section(const TetMesh& mesh, const std::vector<int>& grain, const std::vector<int>& phase, double z);

}  // namespace grainmesh
