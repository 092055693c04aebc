// OpenFOAM output of 3D grain meshes: the tetrahedra or their dual's polyhedra are the
// cells (no extrusion); the case around them is the 2D one's (write_case_files,
// foam_case.hpp), solved by the same solidDisplacementFoam in 3D.
#pragma once

#include <filesystem>

#include "export/export_mesh.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh_3d.hpp"

namespace grainmesh {

// The mesh a 3D case is written on: the tetrahedra (build_polymesh), or with
// options.cells = polygons their dual's polyhedra (build_dual_polymesh_3d).
FoamMesh3 foam_mesh(const ExportMesh<3>& m, const FoamOptions& options);

// Writes the complete 3D case into `dir` as write_foam_case does a 2D one (foam_case.hpp): the polyMesh,
// 0/D (under the mixed load, or a cyclic case's mean strain: all six components), 0/E,
// 0/nu (and under a temperature change 0/alpha and 0/T), the properties (planeStress
// no), the system dictionaries (the force through right, and top and front when cyclic,
// logged), Allrun, case.foam. Throws ConfigError for export.plane_stress and as
// check_case (a temperature change only on a cyclic case), GeometryError as
// foam_mesh. Returns the mesh it wrote.
FoamMesh3 write_foam_case(const std::filesystem::path& dir, const ExportMesh<3>& m, const FoamOptions& options);
// The same on a mesh already built (foam_mesh(m, options): a load case's options keep
// the mesh), its polyMesh's files copied from `polymesh_from` when given.
void write_foam_case(const std::filesystem::path& dir, const ExportMesh<3>& m, const FoamMesh3& mesh,
                        const FoamOptions& options, const std::filesystem::path& polymesh_from = {});

}  // namespace grainmesh
