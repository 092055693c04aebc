// What the export needs of a mesh: its cells (2D: triangles or the dual's polygons; 3D:
// tetrahedra) with a grain and a phase each, the phases, the cell whose sides become
// patches, and the periodic pairs; made from a grain mesh and its tessellation.
#pragma once

#include <vector>

#include "common/geometry.hpp"
#include "common/periodic_pairs.hpp"
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

// What the export needs of a mesh: triangles with a grain and a phase each,
// the phases, and the cell whose sides become the patches left, right, bottom, top
// (boundary edges elsewhere, e.g. around a hole, form the patch `boundary`).
struct ExportMesh {
  CellMesh mesh;                  // triangles, or polygons (the dual)
  std::vector<int> grain;         // #T
  std::vector<int> phase;         // #T, index into phases
  std::vector<FoamPhase> phases;
  Box cell;
  bool periodic = false;          // opposite sides carry matching nodes,
  PeriodicPairs pairs;            // ... paired (the cyclic faces are paired through them)
};

// A grain mesh with its tessellation's cell and phases.
ExportMesh grain_export_mesh(const Tessellation& t, const GrainMesh& m);
// A mesh of triangles as polygons: the dual (dual_mesh.hpp) split at grain boundaries,
// each cell with the grain and phase of its triangles, the periodic pairs carried.
ExportMesh polygon_cells(const ExportMesh& triangles);
// The export's mesh of a grain mesh: grain_export_mesh, as polygon_cells when asked.
ExportMesh export_mesh(const Tessellation& t, const GrainMesh& m, FoamOptions::Cells cells);

// What the case and its solve need of it (foam_load.hpp): the phases, the cell's extents,
// periodicity.
FoamCell foam_cell(const ExportMesh& m);

// What the export needs of a 3D mesh: positive tetrahedra with a grain and a phase each,
// the phases, the box [0, W] x [0, H] x [0, D], and when periodic the surface points on
// the low sides paired with their images on the high sides.
struct ExportMesh3 {
  TetMesh mesh;
  std::vector<int> grain;  // #T
  std::vector<int> phase;  // #T, index into phases
  std::vector<FoamPhase> phases;
  Vec3 box;
  bool periodic = false;
  PeriodicPairs pairs;
};

// A 3D grain mesh with its tessellation's box and phases.
ExportMesh3 grain_export_mesh_3d(const Tessellation3& t, const GrainMesh3& m);

// What the case and its solve need of it (foam_load.hpp): the phases, the box, periodicity.
FoamCell foam_cell(const ExportMesh3& m);

}  // namespace grainmesh
