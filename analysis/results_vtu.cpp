#include "analysis/results_vtu.hpp"

#include "analysis/stress_measures.hpp"
#include "export/vtu.hpp"

namespace grainmesh {

void write_results_vtu(const std::filesystem::path& file, const ExportMesh& m, const std::vector<std::string>& phase_names,
                       const std::vector<SolvedFields>& cases) {
  const std::size_t cells = m.mesh.cells();
  std::vector<CellField> fields{{"grain", m.grain}, {"phase", m.phase}};
  for (const SolvedFields& c : cases) {
    const FieldValues& D = c.fields->displacement;
    std::vector<double> stress, mises, principal;
    stress.reserve(6 * cells);
    for (const StressState& s : *c.stress) {
      for (double v : vtk_components(s)) stress.push_back(v);
      mises.push_back(von_mises(s));
      principal.push_back(largest_principal(s));
    }
    fields.push_back({"displacement" + c.suffix, D.values, 3});
    fields.push_back({"stress" + c.suffix, std::move(stress), 6});
    fields.push_back({"von_mises" + c.suffix, std::move(mises)});
    fields.push_back({"max_principal" + c.suffix, std::move(principal)});
  }
  write_vtu(file, m.mesh, fields, {{"phase_names", phase_names}});
}

}  // namespace grainmesh
