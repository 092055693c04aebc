// What makes a grain mesh right, checked against its tessellation: nodes, edges, every
// cell (triangle or polygon) in its grain and phase, grain areas, periodic node pairs.
#pragma once

#include <cstddef>

#include <vector>

#include "grains/grain_mesh_options.hpp"
#include "mesh/cell_mesh.hpp"

namespace grainmesh {

// The periodic pairs of a mesh's points from their positions (exact coordinates on the
// cell's sides), for a mesh read from a file (a mesh the mesh stage made carries its
// pairs); empty when the tessellation is not periodic. Throws GeometryError for a side
// point without a partner.
PeriodicPairs pair_periodic_nodes(const Tessellation& t, const std::vector<Vec2>& points);

// What check_conformity measured.
struct Conformity {
  double max_area_error = 0.0;       // max over grains |mesh area - polygon area| / polygon area
  double max_pair_mismatch = 0.0;    // max over node pairs of the position error
  std::size_t boundary_edges = 0;    // edges with one triangle (all on the cell's sides)
};

// Checks the mesh against its tessellation: no two nodes at one place and every
// tessellation vertex a node; each edge in one or two cells; edges with one cell on the
// periodic cell's sides only; every cell inside the region of its grain and of its
// grain's phase; each grain's area equal to its polygons' within `area_tolerance`
// (relative); periodic pairs complete and matching within 1e-12 max(W, H). Throws
// GeometryError naming the first violation.
Conformity check_conformity(const Tessellation& t, const GrainMesh& m, double area_tolerance = 1e-9);

// The same for cells of any shape (the polygonal cells of export.cells = polygons, a mesh
// file read back): one grain and one phase per cell.
struct LabelledCells {
  CellMesh mesh;
  std::vector<int> grain, phase;  // #C
  PeriodicPairs pairs;
};
Conformity check_conformity(const Tessellation& t, const LabelledCells& m, double area_tolerance = 1e-9);

}  // namespace grainmesh
