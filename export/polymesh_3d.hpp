// The polyMesh of a 3D mesh: its tetrahedra as cells (or, in polymesh_dual_3d.hpp, their
// dual's polyhedra), the box's sides as patches or cyclic pairs, the cells' labels and
// their geometry as OpenFOAM computes it.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "common/vec3.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh.hpp"

namespace grainmesh {

// The patches of the box's sides, low then high along x, y, z.
inline constexpr const char* kSideNames3[6] = {"left", "right", "bottom", "top", "back", "front"};

// The cells a 3D case is solved on, as OpenFOAM sees them: the polyMesh, each cell's grain
// and phase, and its centre and volume as OpenFOAM computes them from its faces
// (foam_cell_geometry).
// What the 3D dual's export mended where checkMesh would fail (FoamOptions::mend_checks),
// and what its own check of checkMesh's limits (foam_mesh_check.hpp) still finds failing.
struct DualMending {
  int folded_points = 0;  // points whose faces between their own cells were folded into one
  int joined_cells = 0;   // cells joined into a neighbour of their grain or phase
  int failing_faces = 0;  // left failing: skewness, non-orthogonality
  int failing_cells = 0;  // left failing: volume, aspect ratio
};

struct FoamMesh3 {
  PolyMesh mesh;
  std::vector<int> grain, phase;  // per cell
  std::vector<Vec3> centre;       // mesh units
  std::vector<double> volume;     // mesh units cubed
  std::vector<int> corner_cell;   // #4T: the cell holding each tetrahedron's corner k (at 4 t + k)
  std::optional<DualMending> mending;  // the dual's under mend_checks; none for tetrahedra
};

// The side of `box` all three points of `f` lie on (0 left, 1 right, 2 bottom, 3 top,
// 4 back, 5 front), -1 for none. Points on a side carry its coordinate exactly (the 3D
// stages put them there).
int box_side_of(const std::vector<Vec3>& p, const std::array<int, 3>& f, const Box3& box);

// The patch of the box's side s (0 left ... 5 front) under `options`: cyclic (with its
// partner and separation), or the mixed load's type: right a patch, the others symmetry
// planes, top and front patches too when uniaxial.
PolyMesh::Patch side_patch(int side, Vec3 box, const FoamOptions& options);

// Builds the polyMesh: internal faces in upper-triangular order, then the sides' faces
// patch by patch (left, right, bottom, top, back, front). With options.cyclic, the three
// pairs are cyclic (translational; a high side's faces the images of its low side's, in
// their order, each starting at the image of its partner's first point); otherwise the
// thesis' mixed load's types: right a patch (the loaded face), the others symmetry
// planes, top and front patches too when options.uniaxial. Zones by add_zones. Throws
// ConfigError for export.cyclic on a mesh that is not periodic, GeometryError when a
// boundary face lies on no side or a cyclic side's faces do not pair.
PolyMesh build_polymesh(const ExportMesh<3>& m, const FoamOptions& options);

}  // namespace grainmesh
