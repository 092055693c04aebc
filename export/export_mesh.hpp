// What the export needs of a mesh: its cells (2D: triangles or the dual's polygons; 3D:
// tetrahedra) with a grain and a phase each, the phases, the cell whose sides become
// patches, and the periodic pairs; made from a grain mesh and its tessellation.
#pragma once

#include <type_traits>
#include <vector>

#include "common/geometry.hpp"
#include "common/periodic_pairs.hpp"
#include "common/vec3.hpp"
#include "export/foam_load.hpp"
#include "export/foam_material.hpp"
#include "export/foam_options.hpp"
#include "grains/grain_mesh.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "mesh/cell_mesh.hpp"
#include "mesh/tetmesh.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// What the export needs of a mesh, plane (D = 2) or solid (D = 3): its cells with a grain
// and a phase each, the phases, the cell whose sides become the patches (2D left, right,
// bottom, top; 3D also back, front) and, when periodic, the points on its low sides
// paired with their images on the high sides, per axis. 2D cells are triangles or the
// dual's polygons (boundary edges off the cell's sides, e.g. around a hole, form the patch
// `boundary`); 3D cells are positive tetrahedra in the box [0, W] x [0, H] x [0, D].
template <int D>
struct ExportMesh {
  static_assert(D == 2 || D == 3, "a plane or a solid mesh");
  std::conditional_t<D == 2, CellMesh, TetMesh> mesh;
  std::vector<int> grain;         // per cell
  std::vector<int> phase;         // per cell, index into phases
  std::vector<FoamPhase> phases;
  std::conditional_t<D == 2, Box, Box3> cell;
  bool periodic = false;          // opposite sides carry matching nodes,
  PeriodicPairs pairs;            // ... paired (the cyclic faces are paired through them)
};

// A grain mesh with its tessellation's cell and phases.
ExportMesh<2> grain_export_mesh(const Tessellation& t, const GrainMesh& m);
ExportMesh<3> grain_export_mesh(const Tessellation3& t, const GrainMesh3& m);

// A mesh of triangles as polygons: the dual (dual_mesh.hpp) split at grain boundaries,
// each cell with the grain and phase of its triangles, the periodic pairs carried.
ExportMesh<2> polygon_cells(const ExportMesh<2>& triangles);
// The export's mesh of a plane grain mesh: grain_export_mesh, as polygon_cells when asked
// (a solid mesh's dual is built with its polyMesh, polymesh_dual_3d.hpp).
ExportMesh<2> export_mesh(const Tessellation& t, const GrainMesh& m, FoamOptions::Cells cells);

// What the case and its solve need of it (foam_load.hpp): the phases, the cell's extents,
// periodicity.
template <int D>
FoamCell foam_cell(const ExportMesh<D>& m) {
  if constexpr (D == 2)
    return {m.phases, {m.cell.width(), m.cell.height(), 0.0}, m.periodic};
  else
    return {m.phases, m.cell.size(), m.periodic};
}

}  // namespace grainmesh
