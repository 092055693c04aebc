#include "pipelines/answer.hpp"

#include <optional>

#include "analysis/bounds.hpp"
#include "analysis/check_mesh.hpp"
#include "analysis/results_vtu.hpp"
#include "analysis/thermal.hpp"
#include "common/format.hpp"
#include "pipelines/report_json.hpp"
#include "pipelines/result_pictures.hpp"

namespace grainmesh {

void check_case_mesh(const std::filesystem::path& dir, const Deadline& deadline, Json& report, Warnings& warnings) {
  const Json& cases = report["case"];
  const std::string first = cases.is_array() ? cases.front().get<std::string>() : cases.get<std::string>();
  const MeshCheck check = check_mesh(dir / first, deadline);
  report["mesh_check"] = {{"case", first}, {"failed_checks", check.failed_checks}, {"failures", check.failures}};
  if (const std::string w = mesh_check_warning(check, first); !w.empty()) warnings.add(w);
}

namespace {

std::vector<double> achieved_fractions(const Tessellation& t) {
  std::vector<double> fractions;
  for (const PhaseStats& p : t.stats.phases) fractions.push_back(p.achieved_fraction);
  return fractions;
}

// `stresses.CASE` of a solved state, each cell weighted by its area; `loaded` the loaded
// component (0 xx, 1 yy, 2 xy; -1 none: the thermal residual's mean is zero); `balanced`:
// the means from the virial stresses (periodic).
Json state_stresses(const SolvedState<3>& s, const Tessellation& t, const ExportMesh<2>& e, int loaded, bool balanced) {
  return state_stresses_json(s, cell_areas(e.mesh), e.phase, phase_names(t.phases), loaded, balanced);
}

// What a thermal load adds to the answer: effective.thermal_expansion {xx, yy, xy}
// (1/K), effective.thermal {delta_T, plane_state, levin, levin_difference}, and
// stresses.thermal (the residual stress, free expansion) and stresses.thermal_xx (cooled,
// then the load.displacement of the xx case); a free expansion that breaks Levin's
// relation (with the stiffness it was freed with, as solved) by more than 1 % is a warning.
void add_thermal_answer(Answer& answer, const PeriodicHomogenised<3>& h, const ThermalResidual<3>& r,
                        const Tessellation& t, const ExportMesh<2>& e, const FoamOptions& foam,
                        std::vector<std::string>& warnings) {
  Json& effective = answer.effective;
  effective["thermal_expansion"] = voigt_json<3>(r.expansion);
  // In plane strain the cell is held out of plane: one material expands (1 + nu) alpha in
  // plane, and carries sigma_zz; in plane stress alpha (docs/run.md, Thermal residual stress).
  Json thermal{{"delta_T", r.delta_T}, {"plane_state", plane_state(foam)}};
  if (const auto levin = levin_expansion(e.phases, h.stiffness, foam.plane_stress))
    add_levin<3>(r.expansion, *levin, thermal, warnings,
                 "refine the mesh at the interfaces (mesh.boundary_size; see docs/run.md, Thermal residual stress)");
  effective["thermal"] = thermal;
  answer.stresses["thermal"] = state_stresses(r.free, t, e, -1, true);
  answer.stresses["thermal_xx"] = state_stresses(r.loaded, t, e, 0, true);
}

}  // namespace

Answer homogenise_mixed(const SolveInput<2>& in, std::vector<std::string>& warnings) {
  const auto& [dir, staged, t, e, pm, foam, deadline, picture_width, all_pictures, section_z, unit] = in;

  const MixedHomogenised<3> h = solve_mixed(dir / "case", e, pm, foam, deadline, staged.failed_dir() / "case");
  Answer answer;
  answer.stresses["mixed"] = state_stresses(h, t, e, 0, false);
  if (picture_width > 0) write_stress_histogram(dir / "stress_histogram.png", "mixed", h.cell_stress, t, e);
  Json& effective = answer.effective;
  add_mixed(h, dir, effective);
  if (picture_width > 0) write_results_vtu(dir / "results.vtu", e, phase_names(t.phases), {{"", &h.fields, &h.cell_stress}}, foam.convert_to_meters);
  write_field_pictures(dir, h.fields, h.cell_stress, e, picture_width, all_pictures, unit);
  if (foam.uniaxial) return answer;  // the bounds are for the default load (mean eps_yy zero)
  const ElasticBounds b = elastic_bounds(e.phases, achieved_fractions(t), foam.plane_stress);
  effective["voigt"] = b.voigt;
  effective["reuss"] = b.reuss;
  if (b.hs_lower) effective["hashin_shtrikman"] = {{"lower", *b.hs_lower}, {"upper", *b.hs_upper}};
  // Voigt and Reuss hold for every microstructure; Hashin-Shtrikman for isotropic ones
  // (a finite cell is not quite).
  add_modulus_verdict(judge_modulus(h.modulus, b.voigt, b.reuss, b.hs_lower, b.hs_upper), effective, warnings,
                      "a finite cell is not isotropic; see docs/run.md, Homogenisation");
  return answer;
}

Answer homogenise_periodic(const SolveInput<2>& in, std::vector<std::string>& warnings) {
  const auto& [dir, staged, t, e, pm, foam, deadline, picture_width, all_pictures, section_z, unit] = in;

  const std::vector<LoadCase<3>> loads = periodic_load_cases(e, foam);
  const PeriodicHomogenised<3> h =
      solve_periodic(load_case_dirs(loads, dir), e, pm, foam, solves_side_by_side(foam.processes), deadline,
                     load_case_dirs(loads, staged.failed_dir()));
  Answer answer;
  for (int k = 0; k < 3; ++k)
    answer.stresses[h.cases[k].load.name] = state_stresses(h.cases[k], t, e, k, true);
  if (picture_width > 0)
    write_stress_histogram(dir / "stress_histogram.png", h.cases[0].load.name, h.cases[0].cell_stress, t, e);
  Json& effective = answer.effective;
  const std::vector<double> fractions = achieved_fractions(t);
  const TensorBounds<3> bounds = tensor_bounds<3>(e.phases, fractions, foam.plane_stress);
  const StiffnessVerdict<3> verdict = judge_stiffness(h.stiffness, bounds);
  effective["boundary"] = "periodic";
  add_stiffness<3>(verdict, bounds, fractions, effective, warnings, "see docs/run.md, Homogenisation",
                   "a finite cell is not isotropic; see docs/run.md, Homogenisation");
  add_engineering(engineering_constants(verdict.stiffness), effective);
  std::vector<SolvedFields> solved;
  for (int k = 0; k < 3; ++k) solved.push_back({"_" + h.cases[k].load.name, &h.cases[k].fields, &h.cases[k].cell_stress});
  std::optional<ThermalResidual<3>> thermal;
  if (foam.delta_T != 0.0) {
    thermal = thermal_residual(h);
    add_thermal_answer(answer, h, *thermal, t, e, foam, warnings);
    solved.push_back({"_thermal", &thermal->free.fields, &thermal->free.cell_stress});
    solved.push_back({"_thermal_xx", &thermal->loaded.fields, &thermal->loaded.cell_stress});
    if (picture_width > 0)
      write_stress_histogram(dir / "stress_histogram_thermal.png", "thermal", thermal->free.cell_stress, t, e);
  }
  add_load_cases(h, dir, effective);
  if (picture_width > 0) write_results_vtu(dir / "results.vtu", e, phase_names(t.phases), solved, foam.convert_to_meters);
  write_field_pictures(dir, h.cases[0].fields, h.cases[0].cell_stress, e, picture_width, all_pictures, unit);
  return answer;
}

}  // namespace grainmesh
