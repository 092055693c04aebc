// OpenFOAM output of 3D grain meshes: the tetrahedra are the cells (no extrusion), with
// phase (and grain) cellZones, grain-boundary and phase-interface faceZones, and the box's
// six sides as patches or as three cyclic pairs; the case around it is the 2D one's
// (write_case_files, foam.hpp), solved by the same solidDisplacementFoam in 3D.
#pragma once

#include <filesystem>
#include <vector>

#include "common/vec3.hpp"
#include "export/foam.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "mesh/tetmesh.hpp"

namespace grainmesh {

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
  PeriodicPairs3 pairs;
};

// A 3D grain mesh with its tessellation's box and phases.
ExportMesh3 grain_export_mesh_3d(const Tessellation3& t, const GrainMesh3& m);
// What the case and its solve need of it (foam.hpp): the phases, the box, periodicity.
FoamCell foam_cell(const ExportMesh3& m);

// The patches of the box's sides, low then high along x, y, z.
inline constexpr const char* kSideNames3[6] = {"left", "right", "bottom", "top", "back", "front"};

// Builds the polyMesh: internal faces in upper-triangular order, then the sides' faces
// patch by patch (left, right, bottom, top, back, front). With options.cyclic, the three
// pairs are cyclic (translational; a high side's faces the images of its low side's, in
// their order, each starting at the image of its partner's first point); otherwise the
// thesis' mixed load's types: right a patch (the loaded face), the others symmetry
// planes, top and front patches too when options.uniaxial. Zones by add_zones. Throws
// ConfigError for export.cyclic on a mesh that is not periodic, GeometryError when a
// boundary face lies on no side or a cyclic side's faces do not pair.
PolyMesh build_polymesh_3d(const ExportMesh3& m, const FoamOptions& options);

// Writes the complete 3D case into `dir` as write_foam_case does a 2D one: the polyMesh,
// 0/D (under the mixed load, or a cyclic case's mean strain: all six components), 0/E,
// 0/nu, the properties (planeStress no), the system dictionaries (the force through
// right, and top and front when cyclic, logged), Allrun, case.foam. Throws ConfigError
// for export.plane_stress or load.delta_T (not solved in 3D yet) and as check_case,
// GeometryError as build_polymesh_3d. Returns the mesh it wrote.
PolyMesh write_foam_case_3d(const std::filesystem::path& dir, const ExportMesh3& m, const FoamOptions& options);

}  // namespace grainmesh
