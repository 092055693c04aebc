// OpenFOAM output: a complete case that solidDisplacementFoam (OpenFOAM v1912) runs as it
// is, two-phase linear elasticity on the polyMesh (polymesh.hpp), its fields, properties
// and dictionaries (foam_solver.hpp); for 2D meshes here, for 3D in foam_case_3d.hpp.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "common/vec3.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_load.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh.hpp"

namespace grainmesh {

// Writes a complete case into `dir` (which must exist and be empty): constant/polyMesh
// (points, faces, owner, neighbour, boundary, cellZones, faceZones), 0/D, 0/E, 0/nu,
// constant/mechanicalProperties and thermalProperties, system/controlDict, fvSchemes,
// fvSolution, Allrun and an empty case.foam. Throws ConfigError for a phase without a
// usable E or nu, IoError when a file cannot be written. Returns the mesh it wrote.
PolyMesh write_foam_case(const std::filesystem::path& dir, const ExportMesh<2>& m, const FoamOptions& options);
// The same on a polyMesh already built (build_polymesh(m, options): a load case's options
// keep the mesh), its files copied from `polymesh_from` when given (a case of the same
// mesh written before).
void write_foam_case(const std::filesystem::path& dir, const ExportMesh<2>& m, const PolyMesh& pm,
                     const FoamOptions& options, const std::filesystem::path& polymesh_from = {});

// What write_foam_case writes of a 2D or 3D case around its built polyMesh `pm`: 0/D (the
// solve started from the imposed mean strain at each cell's `centroid`, mesh units from
// the cell's low corner), 0/E, 0/nu (each cell's `phase`), the properties, the system
// dictionaries, Allrun and case.foam; the polyMesh's files copied from `polymesh_from`
// when given (a case of the same mesh written before: formatting them is the most of a
// case's writing). `check_case` first: it refuses what the case cannot
// carry (a phase without a usable E, nu or alpha; a cell without a grain or a phase;
// check_load), throwing ConfigError naming the key.
void check_case(const FoamCell& cell, const std::vector<int>& grain, const std::vector<int>& phase, std::size_t cells,
                const FoamOptions& options);
void write_case_files(const std::filesystem::path& dir, const FoamCell& cell, const std::vector<int>& phase,
                      const std::vector<Vec3>& centroid, const PolyMesh& pm, const FoamOptions& options,
                      const std::filesystem::path& polymesh_from = {});

}  // namespace grainmesh
