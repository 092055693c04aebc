// results.vtu: the solved fields of every load case over the mesh, for ParaView, beside
// the mesh's own grain and phase (the phases' names stored in the file).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/foam_fields.hpp"
#include "analysis/stress_measures.hpp"
#include "export/foam.hpp"
#include "export/foam_3d.hpp"

namespace grainmesh {

// A solved case's displacement and cell stresses, its arrays named with `suffix` (empty
// for the mixed load's one case, "_xx", "_yy", "_xy" for the periodic ones).
struct SolvedFields {
  std::string suffix;
  const CaseFields* fields = nullptr;
  const std::vector<StressState>* stress = nullptr;
};

// Cell arrays: grain, phase, and per case displacement (vector, m), stress (symmetric
// tensor, Pa, the recovered cell stress; zz the out-of-plane stress), von_mises and
// max_principal (Pa); field data phase_names. Throws IoError naming the file when it
// cannot be written.
void write_results_vtu(const std::filesystem::path& file, const ExportMesh& m, const std::vector<std::string>& phase_names,
                       const std::vector<SolvedFields>& cases);

// The same over a 3D case's cells (VTK polyhedra, mesh units): grain, phase, and per case
// (`suffix` and its fields, the whole stress) displacement, stress and von_mises.
void write_results_vtu_3d(const std::filesystem::path& file, const FoamMesh3& m,
                          const std::vector<std::string>& phase_names,
                          const std::vector<std::pair<std::string, const CaseFields*>>& cases);

}  // namespace grainmesh
