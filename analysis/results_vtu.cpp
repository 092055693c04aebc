#include "analysis/results_vtu.hpp"

#include "analysis/stress_measures.hpp"
#include "view/picture.hpp"
#include "view/vtu.hpp"

namespace grainmesh {

namespace {
// A displacement (metres) in the mesh's units.
std::vector<double> in_mesh_units(const FieldValues& D, double metres_per_unit) {
  std::vector<double> out = D.values;
  for (double& v : out) v /= metres_per_unit;
  return out;
}
}  // namespace

void write_results_vtu(const std::filesystem::path& file, const ExportMesh<2>& m, const std::vector<std::string>& phase_names,
                       const std::vector<SolvedFields>& cases, double metres_per_unit) {
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
    fields.push_back({"displacement" + c.suffix, in_mesh_units(D, metres_per_unit), 3});
    fields.push_back({"stress" + c.suffix, std::move(stress), 6});
    fields.push_back({"von_mises" + c.suffix, std::move(mises)});
    fields.push_back({"max_principal" + c.suffix, std::move(principal)});
  }
  write_vtu(file, m.mesh, fields, {{"phase_names", phase_names}, {"length_unit", {length_unit_name(metres_per_unit)}}});
}

void write_results_vtu(const std::filesystem::path& file, const FoamMesh3& m, const std::vector<std::string>& phase_names,
                       const std::vector<SolvedFields>& cases, double metres_per_unit) {
  std::vector<CellField> fields{{"grain", m.grain}, {"phase", m.phase}};
  for (const auto& [suffix, f, unused] : cases) {
    std::vector<double> stress, mises;
    for (std::size_t c = 0; c < f->stress.size(); ++c) {
      const double* s = f->stress[c];  // OpenFOAM's xx xy xz yy yz zz into VTK's xx yy zz xy yz xz
      for (const int k : {0, 3, 5, 1, 4, 2}) stress.push_back(s[k]);
      mises.push_back(von_mises(openfoam_stress(s)));
    }
    fields.push_back({"displacement" + suffix, in_mesh_units(f->displacement, metres_per_unit), 3});
    fields.push_back({"stress" + suffix, std::move(stress), 6});
    fields.push_back({"von_mises" + suffix, std::move(mises)});
  }
  write_vtu(file, m.mesh, fields, {{"phase_names", phase_names}, {"length_unit", {length_unit_name(metres_per_unit)}}});
}

}  // namespace grainmesh
