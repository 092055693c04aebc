// The export's mesh: a grain mesh's triangles with the tessellation's cell and phases, or
// their dual's polygonal cells (export.cells).
#include "export/export_mesh.hpp"

#include <optional>

#include "common/errors.hpp"
#include "export/foam_load.hpp"
#include "export/foam_material.hpp"
#include "export/foam_options.hpp"
#include "mesh/dual_mesh.hpp"

namespace grainmesh {

namespace {

// The export's frame of a grain mesh: everything but the cells.
ExportMesh<2> frame(const Tessellation& t, const GrainMesh& m) {
  return ExportMesh<2>{.mesh = {}, .grain = m.grain, .phase = m.phase, .phases = foam_phases(t.phases),
                    .cell = Box{{0.0, 0.0}, {t.width, t.height}}, .periodic = t.periodic, .pairs = m.pairs};
}

// The dual of `mesh` (whose triangles `triangles` labels) as cells, each with the grain and
// phase of its triangles, the periodic pairs carried.
ExportMesh<2> dual_cells(const TriMesh& mesh, const ExportMesh<2>& triangles) {
  DualMesh d = dual_mesh(mesh, triangles.grain, triangles.pairs);
  ExportMesh<2> e{.mesh = std::move(d.mesh), .grain = {}, .phase = {}, .phases = triangles.phases,
               .cell = triangles.cell, .periodic = triangles.periodic, .pairs = std::move(d.pairs)};
  for (int tri : d.triangle) {
    e.grain.push_back(triangles.grain[tri]);
    e.phase.push_back(triangles.phase[tri]);
  }
  return e;
}

}  // namespace

ExportMesh<2> grain_export_mesh(const Tessellation& t, const GrainMesh& m) {
  ExportMesh<2> e = frame(t, m);
  e.mesh = cell_mesh(m.mesh);
  return e;
}

ExportMesh<2> polygon_cells(const ExportMesh<2>& triangles) {
  const std::optional<TriMesh> mesh = as_triangles(triangles.mesh);
  if (!mesh) throw GeometryError("export: the dual needs a mesh of triangles");
  return dual_cells(*mesh, triangles);
}

ExportMesh<2> export_mesh(const Tessellation& t, const GrainMesh& m, FoamOptions::Cells cells) {
  // Polygons straight from the grain mesh's triangles, not through a copy of them as cells.
  return cells == FoamOptions::Cells::polygons ? dual_cells(m.mesh, frame(t, m)) : grain_export_mesh(t, m);
}

ExportMesh<3> grain_export_mesh(const Tessellation3& t, const GrainMesh3& m) {
  return {.mesh = m.mesh, .grain = m.grain, .phase = m.phase, .phases = foam_phases(t.phases),
          .cell = Box3{{}, t.size()}, .periodic = t.periodic, .pairs = m.pairs};
}

}  // namespace grainmesh
