#include "pipelines/answer.hpp"

#include <optional>
#include <tuple>

#include "analysis/bounds.hpp"
#include "analysis/phase_statistics.hpp"
#include "analysis/results_vtu.hpp"
#include "analysis/thermal.hpp"
#include "common/format.hpp"
#include "pipelines/report_json.hpp"
#include "pipelines/result_pictures.hpp"
#include "view/picture.hpp"
#include "view/section.hpp"

namespace grainmesh {

namespace {

// `stresses.CASE` of a solved state, each cell weighted by its volume; `loaded` the loaded
// component's Voigt index (-1 none); `balanced`: the means from the virial stresses
// (a periodic case's).
Json state_stresses(const SolvedState<6>& s, const SolveInput<3>& in, int loaded, bool balanced) {
  return state_stresses_json(s, in.pm.volume, in.pm.phase, phase_names(in.t.phases), loaded, balanced);
}

// The pictures of a solved state (`load_case`): the section z = in.section_z, each
// tetrahedron cut showing the mean of its corners' cells (one cell each on tetrahedra),
// sigma_xx and von Mises in MPa, in stress_xx`suffix`.png and von_mises`suffix`.png; and
// each phase's volume-weighted distribution of the cells' von Mises stress in
// stress_histogram`suffix`.png.
void write_state_pictures(const SolveInput<3>& in, const CaseFields& fields, const std::string& load_case,
                          const std::string& suffix) {
  if (in.picture_width == 0) return;
  std::vector<double> cell_mises;
  for (std::size_t c = 0; c < fields.stress.size(); ++c) cell_mises.push_back(von_mises(openfoam_stress(fields.stress[c])));
  const std::vector<std::string> names = phase_names(in.t.phases);
  write_stress_histogram(in.dir / ("stress_histogram" + suffix + ".png"), load_case,
                         phase_histograms(cell_mises, in.pm.volume, in.pm.phase, static_cast<int>(names.size()),
                                          kHistogramBins),
                         names, "volume");
  const Section s = mesh_section(in.e.mesh, in.e.grain, in.e.phase, in.section_z);
  std::vector<double> xx, mises;
  for (const int t : s.tet) {
    double sum_xx = 0.0, sum_mises = 0.0;
    for (int k = 0; k < 4; ++k) {
      const double* c = fields.stress[static_cast<std::size_t>(in.pm.corner_cell[4 * static_cast<std::size_t>(t) + k])];
      sum_xx += c[0];
      sum_mises += von_mises(openfoam_stress(c));
    }
    xx.push_back(0.25e-6 * sum_xx);
    mises.push_back(0.25e-6 * sum_mises);
  }
  const std::string at = ", z = " + to_text(in.section_z, 3) + (in.unit.empty() ? "" : " " + in.unit);
  // A state other than a load case's own (the thermal residual) says so in its titles.
  const std::string state = suffix.empty() ? "" : "residual ";
  for (const auto& [name, field, title, signed_field] : {std::tuple{"stress_xx", &xx, "sigma_xx (MPa)", true},
                                                         std::tuple{"von_mises", &mises, "von Mises (MPa)", false}})
    write_mesh_png(in.dir / (std::string(name) + suffix + ".png"), s.cells,
                   {.width_px = in.picture_width, .fill_by = {}, .outline_by = s.grain, .view = {}, .field = *field,
                    .field_name = state + title + at, .signed_field = signed_field, .legend = {}, .scale_bar = true,
                    .length_unit = in.unit});
}

// What a thermal load adds to the answer: effective.thermal_expansion {xx ... xy} (1/K,
// tensor components), effective.thermal {delta_T, levin, levin_difference}, the free
// state's phase stresses as stresses.thermal (and cooled, then pulled as the xx case, as
// stresses.thermal_xx) and its section pictures.
// Levin's relation with the stiffness the expansion was freed with (as solved).
ThermalResidual<6> add_thermal_answer(Answer& answer, const PeriodicHomogenised<6>& h, const SolveInput<3>& in,
                                         std::vector<std::string>& warnings) {
  const ThermalResidual<6> r = thermal_residual(h);
  answer.effective["thermal_expansion"] = voigt_json<6>(r.expansion);
  Json thermal{{"delta_T", r.delta_T}};
  if (const auto levin = levin_expansion(in.e.phases, h.stiffness))
    add_levin<6>(r.expansion, *levin, thermal, warnings,
                 "refine the mesh (mesh.tets_per_grain; see docs/3d.md, 3D cases and solves)");
  answer.effective["thermal"] = thermal;
  answer.stresses["thermal"] = state_stresses(r.free, in, -1, true);
  answer.stresses["thermal_xx"] = state_stresses(r.loaded, in, 0, true);
  write_state_pictures(in, r.free.fields, "thermal", "_thermal");
  return r;
}

// results.vtu (unless pictures are off) of the periodic cases: each mechanical case's
// fields suffixed _NAME, the thermal residual's _thermal and, cooled then pulled, _thermal_xx.
void write_periodic_results_vtu(const SolveInput<3>& in, const PeriodicHomogenised<6>& h,
                                const ThermalResidual<6>* thermal) {
  if (in.picture_width == 0) return;
  std::vector<SolvedFields> cases;
  for (const LoadCaseResult<6>& r : h.cases)
    if (r.load.delta_T == 0.0) cases.push_back({"_" + r.load.name, &r.fields, nullptr});
  if (thermal != nullptr) {
    cases.push_back({"_thermal", &thermal->free.fields, nullptr});
    cases.push_back({"_thermal_xx", &thermal->loaded.fields, nullptr});
  }
  write_results_vtu(in.dir / "results.vtu", in.pm, phase_names(in.t.phases), cases, in.foam.convert_to_meters);
}

}  // namespace

Answer homogenise_mixed(const SolveInput<3>& in, std::vector<std::string>& warnings) {
  const MixedHomogenised<6> h = solve_mixed(in.dir / "case", in.e, in.pm, in.foam, in.deadline, in.staged.failed_dir() / "case");
  Answer answer;
  answer.stresses["mixed"] = state_stresses(h, in, 0, false);
  write_state_pictures(in, h.fields, "mixed", "");
  if (in.picture_width > 0) write_results_vtu(in.dir / "results.vtu", in.pm, phase_names(in.t.phases), {{"", &h.fields, nullptr}}, in.foam.convert_to_meters);
  Json& effective = answer.effective;
  add_mixed(h, in.dir, effective);
  if (in.foam.uniaxial) return answer;  // the bounds are for the cell held sideways
  // Uniaxial strain: between the Reuss and Voigt tensors' C11 for every microstructure.
  const TensorBounds<6> b = tensor_bounds<6>(
      in.e.phases, phase_volume_fractions(in.pm.volume, in.pm.phase, static_cast<int>(in.e.phases.size())));
  effective["voigt"] = b.voigt[0][0];
  effective["reuss"] = b.reuss[0][0];
  add_modulus_verdict(judge_modulus(h.modulus, b.voigt[0][0], b.reuss[0][0]), effective, warnings,
                      "check the solve; see docs/3d.md, 3D cases and solves");
  return answer;
}

Answer homogenise_periodic(const SolveInput<3>& in, std::vector<std::string>& warnings) {
  const std::vector<LoadCase<6>> loads = periodic_load_cases(in.e, in.foam);
  const PeriodicHomogenised<6> h =
      solve_periodic(load_case_dirs(loads, in.dir), in.e, in.pm, in.foam, solves_side_by_side(in.foam.processes),
                     in.deadline, load_case_dirs(loads, in.staged.failed_dir()));
  const std::vector<double> fractions =
      phase_volume_fractions(in.pm.volume, in.pm.phase, static_cast<int>(in.e.phases.size()));
  const TensorBounds<6> bounds = tensor_bounds<6>(in.e.phases, fractions);
  const StiffnessVerdict<6> verdict = judge_stiffness(h.stiffness, bounds);
  Answer answer;
  Json& effective = answer.effective;
  effective["boundary"] = "periodic";
  add_stiffness<6>(verdict, bounds, fractions, effective, warnings, "see docs/3d.md, 3D cases and solves",
                   "a finite cell is not isotropic, and the 3D cells' shears across phase interfaces are first "
                   "order in the mesh size; see docs/3d.md, 3D cases and solves");
  add_engineering(engineering_constants(verdict.stiffness), effective);
  std::optional<ThermalResidual<6>> thermal;
  if (in.foam.delta_T != 0.0) thermal = add_thermal_answer(answer, h, in, warnings);
  add_load_cases(h, in.dir, effective);
  // The thermal case at its fixed strain is no state of its own: its free state is above.
  for (std::size_t k = 0; k < 6; ++k) {
    const LoadCaseResult<6>& r = h.cases[k];
    answer.stresses[r.load.name] = state_stresses(r, in, static_cast<int>(k), true);
  }
  write_state_pictures(in, h.cases[0].fields, "xx", "");
  write_periodic_results_vtu(in, h, thermal ? &*thermal : nullptr);
  return answer;
}

}  // namespace grainmesh
