// results.vtu: the solved fields of every load case over the mesh, for ParaView, beside
// the mesh's own grain and phase (the phases' names stored in the file).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/foam_fields.hpp"
#include "analysis/stress_measures.hpp"
#include "export/export_mesh.hpp"
#include "export/polymesh_3d.hpp"

namespace grainmesh {

// A solved case's displacement and cell stresses, its arrays named with `suffix` (empty
// for the mixed load's one case, "_xx", "_yy", ... for the periodic ones); `stress` the
// 2D cells' recovered stresses (in 3D OpenFOAM's own are written).
struct SolvedFields {
  std::string suffix;
  const CaseFields* fields = nullptr;
  const std::vector<StressState>* stress = nullptr;
};

// One length unit for points and displacements alike, the mesh's (`metres_per_unit` of
// them to the metre: export.convert_to_meters), so that ParaView's Warp By Vector moves
// the cells by what the solve gave; field data length_unit names it ("µm").
//
// Cell arrays: grain, phase, and per case displacement (vector, mesh units), stress
// (symmetric tensor, Pa, the recovered cell stress; zz the out-of-plane stress),
// von_mises and max_principal (Pa); field data phase_names, length_unit. Throws IoError
// naming the file when it cannot be written.
void write_results_vtu(const std::filesystem::path& file, const ExportMesh<2>& m, const std::vector<std::string>& phase_names,
                       const std::vector<SolvedFields>& cases, double metres_per_unit);

// The same over a 3D case's cells (VTK polyhedra): grain, phase, and per case (`suffix`
// and its fields; the stress OpenFOAM's whole tensor, `stress` unused) displacement,
// stress and von_mises.
void write_results_vtu(const std::filesystem::path& file, const FoamMesh3& m, const std::vector<std::string>& phase_names,
                       const std::vector<SolvedFields>& cases, double metres_per_unit);

}  // namespace grainmesh
