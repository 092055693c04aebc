// OpenFOAM output of 3D grain meshes: the tetrahedra or their dual's polyhedra are the
// cells (no extrusion), with phase (and grain) cellZones, grain-boundary and
// phase-interface faceZones, and the box's six sides as patches or as three cyclic pairs;
// the case around it is the 2D one's (write_case_files, foam.hpp), solved by the same
// solidDisplacementFoam in 3D.
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

// The cells a 3D case is solved on, as OpenFOAM sees them: the polyMesh, each cell's grain
// and phase, and its centre and volume as OpenFOAM computes them from its faces
// (foam_cell_geometry).
struct FoamMesh3 {
  PolyMesh mesh;
  std::vector<int> grain, phase;  // per cell
  std::vector<Vec3> centre;       // mesh units
  std::vector<double> volume;     // mesh units cubed
  std::vector<int> corner_cell;   // #4T: the cell holding each tetrahedron's corner k (at 4 t + k)
};

// The patch of the box's side s (0 left ... 5 front) under `options`: cyclic (with its
// partner and separation), or the mixed load's type: right a patch, the others symmetry
// planes, top and front patches too when uniaxial.
PolyMesh::Patch side_patch_3d(int side, Vec3 box, const FoamOptions& options);

// Builds the polyMesh: internal faces in upper-triangular order, then the sides' faces
// patch by patch (left, right, bottom, top, back, front). With options.cyclic, the three
// pairs are cyclic (translational; a high side's faces the images of its low side's, in
// their order, each starting at the image of its partner's first point); otherwise the
// thesis' mixed load's types: right a patch (the loaded face), the others symmetry
// planes, top and front patches too when options.uniaxial. Zones by add_zones. Throws
// ConfigError for export.cyclic on a mesh that is not periodic, GeometryError when a
// boundary face lies on no side or a cyclic side's faces do not pair.
PolyMesh build_polymesh_3d(const ExportMesh3& m, const FoamOptions& options);

// The median dual of the tetrahedra split at grain boundaries (export.cells = polygons):
// one cell for each mesh point and grain around it (for each set of the point's
// tetrahedra of one grain joined through faces), the union of its tetrahedra's corner
// pieces (each tetrahedron cut through points on its edges, faces and inside: the means
// of their corners, a point on a phase interface weighted so that its cells' centres on
// the two sides lie at distances in the ratio sqrt(gamma_soft / gamma_hard), where the
// compact form's face force across the interface is exact for a laminate; elsewhere the
// midpoints and centroids). A face between the cells of an edge's two ends runs round the
// edge; a face between two cells of one point lies in the grain boundary (a quarter of a
// triangle, plane, so each grain keeps its volume exactly), as does a face on a side of
// the box; each is one polygon (its ring of corners, and the point or edge point it fans
// from when the ring is open). Internal faces in OpenFOAM's order, boundary faces patch
// by patch as build_polymesh_3d (cyclic sides' faces the images of their partners'),
// zones by add_zones; cells in the order of their points. Throws as build_polymesh_3d,
// and GeometryError where the dual's faces would not be simple (a grain boundary not
// manifold at a point).
FoamMesh3 build_dual_polymesh_3d(const ExportMesh3& m, const FoamOptions& options);

// A polyMesh face's area vector (normal by its points' turning, right hand) and centre
// as OpenFOAM computes them: a triangle's own; a polygon's from the triangles about its
// points' mean, centres weighted by area (mesh units; a 2D mesh's faces as extruded).
struct FoamFace {
  Vec3 area, centre;
};
FoamFace foam_face(const PolyMesh& pm, int face);
// Each cell's centre and volume as OpenFOAM computes them: pyramids from the mean of the
// cell's face centres to its faces.
void foam_cell_geometry(FoamMesh3& m);

// The mesh a 3D case is written on: the tetrahedra (build_polymesh_3d), or with
// options.cells = polygons their dual's polyhedra (build_dual_polymesh_3d).
FoamMesh3 foam_mesh_3d(const ExportMesh3& m, const FoamOptions& options);

// Writes the complete 3D case into `dir` as write_foam_case does a 2D one: the polyMesh,
// 0/D (under the mixed load, or a cyclic case's mean strain: all six components), 0/E,
// 0/nu (and under a temperature change 0/alpha and 0/T), the properties (planeStress
// no), the system dictionaries (the force through right, and top and front when cyclic,
// logged), Allrun, case.foam. Throws ConfigError for export.plane_stress and as
// check_case (a temperature change only on a cyclic case), GeometryError as
// foam_mesh_3d. Returns the mesh it wrote.
FoamMesh3 write_foam_case_3d(const std::filesystem::path& dir, const ExportMesh3& m, const FoamOptions& options);
// The same on a mesh already built (foam_mesh_3d(m, options): a load case's options keep
// the mesh), its polyMesh's files copied from `polymesh_from` when given.
void write_foam_case_3d(const std::filesystem::path& dir, const ExportMesh3& m, const FoamMesh3& mesh,
                        const FoamOptions& options, const std::filesystem::path& polymesh_from = {});

}  // namespace grainmesh
