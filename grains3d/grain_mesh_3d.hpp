// The 3D mesh stage on a tessellation: the surfaces meshed once (surface_mesh.hpp), each
// region filled with tetrahedra that keep its surface triangles exactly (TetGen's library,
// each try in a fresh helper process: tetgen_fill.hpp), the pieces assembled into one conforming
// mesh with a grain and a phase per tetrahedron and, when periodic, paired surface points.
#pragma once

#include <vector>

#include "common/deadline.hpp"
#include "mesh/tetmesh.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

struct GrainMesh3Options {
  double size = 0.0;               // element edge length h, the tessellation's unit; > 0
  double core_size = 0.0;          // > size: the grains' (not the matrix's) volume bound, their surfaces staying at size
  int threads = 0;                 // regions filled in parallel; 0 = all cores
  // TetGen's quality bounds (-q): radius-edge ratio and smallest dihedral angle; its
  // volume bound is the regular tetrahedron of edge `size`.
  double radius_edge = 1.3;
  double min_dihedral_deg = 15.0;
  int improvement_passes = 3;      // improve_tets.hpp: flips, insertion and smoothing inside each region
  Deadline deadline{};
};

struct GrainMesh3 {
  TetMesh mesh;
  std::vector<int> grain;  // #T
  std::vector<int> phase;  // #T
  std::vector<int> region; // #T
  // Each tessellation face's triangles (point ids), turning as its ring does.
  std::vector<std::vector<std::array<int, 3>>> faces;
  PeriodicPairs pairs;    // surface points on the box's sides and their images
  int surface_points = 0;
  int surface_triangles = 0;
  double seconds = 0.0, surface_seconds = 0.0, fill_seconds = 0.0;
};

// Meshes every face, fills every region and assembles; the result does not depend on the
// thread count. Throws GeometryError (a face or a region that cannot be meshed, TetGen
// missing or failing), TimeLimitError when the deadline passes.
GrainMesh3 mesh_tessellation_3d(const Tessellation3& t, const GrainMesh3Options& options);

// The element size for about `per_grain` tetrahedra per grain: the edge of the regular
// tetrahedron of 1.05 x the mean grain volume / per_grain, since the fill makes about 1.05
// tetrahedra per regular one of its volume bound (measured with bent faces meshed whole:
// 526 per grain for 500 nominal at a factor of 1 on the 100-grain example).
double size_for_tets_per_grain(const Tessellation3& t, double per_grain);

}  // namespace grainmesh
