// What makes a grain mesh right, checked against its tessellation: nodes, edges, every
// triangle in its grain and phase, grain areas, periodic node pairs.
#pragma once

#include <cstddef>

#include "grains/grain_mesh.hpp"

namespace grainmesh {

// Fills m.pairs from the node positions (exact coordinates on the cell's sides), for a
// mesh read from a file (a mesh the mesh stage made carries its pairs); empty when the
// tessellation is not periodic. Throws GeometryError for a side node without a partner.
void pair_periodic_nodes(const Tessellation& t, GrainMesh& m);

// What check_conformity measured.
struct Conformity {
  double max_area_error = 0.0;       // max over grains |mesh area - polygon area| / polygon area
  double max_pair_mismatch = 0.0;    // max over node pairs of the position error
  std::size_t boundary_edges = 0;    // edges with one triangle (all on the cell's sides)
};

// Checks the mesh against its tessellation: no two nodes at one place and every
// tessellation vertex a node; each edge in one or two triangles; edges with one triangle
// on the cell's sides only; every triangle inside the region of its grain and of its
// grain's phase; each grain's area equal to its polygons' within `area_tolerance`
// (relative); periodic pairs complete and matching within 1e-12 max(W, H). Throws
// GeometryError naming the first violation.
Conformity check_conformity(const Tessellation& t, const GrainMesh& m, double area_tolerance = 1e-9);

}  // namespace grainmesh
