#include "pipelines/solve_cell.hpp"

#include <optional>

#include "analysis/bounds.hpp"
#include "analysis/check_mesh.hpp"
#include "analysis/results_vtu.hpp"
#include "analysis/thermal.hpp"
#include "common/format.hpp"
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

// Where the 2D answer's warnings send the user.
const AnswerAdvice kAdvice{
    .see = "see docs/run.md, Homogenisation",
    .why = "a finite cell is not isotropic; see docs/run.md, Homogenisation",
    .refine = "refine the mesh at the interfaces (mesh.boundary_size; see docs/run.md, Thermal residual stress)"};

// The phases' stresses of a solved state (`state` in report.json), each cell weighted by
// its area; `loaded` the loaded component (0 xx, 1 yy, 2 xy; -1 none: the thermal
// residual's mean is zero); `balanced`: the means from the virial stresses (periodic).
StateStresses state_stresses(const std::string& state, const SolvedState<3>& s, const ExportMesh<2>& e, int loaded,
                             bool balanced) {
  return {state, state_phase_stresses(s, cell_areas(e.mesh), e.phase, static_cast<int>(e.phases.size()), loaded,
                                      balanced)};
}

}  // namespace

CellAnswer<2> homogenise_mixed(const SolveInput<2>& in, std::vector<std::string>& warnings) {
  const auto& [dir, staged, t, e, pm, foam, deadline, picture_width, all_pictures, section_z, unit, fe_mesh, refine, solver, fe_mesh_file] = in;

  const MixedHomogenised<3> h = solve_mixed(dir / "case", e, pm, foam, deadline, staged.failed_dir() / "case");
  if (picture_width > 0) {
    write_stress_histogram(dir / "stress_histogram.png", "mixed", h.cell_stress, t, e);
    write_results_vtu(dir / "results.vtu", e, phase_names(t.phases), {{"", &h.fields, &h.cell_stress}},
                      foam.convert_to_meters);
  }
  write_field_pictures(dir, h.fields, h.cell_stress, e, picture_width, all_pictures, unit);
  return {.effective = mixed_answer(h, e.phases, achieved_fractions(t), foam, kAdvice, warnings),
          .phase_names = phase_names(t.phases),
          .stresses = {state_stresses("mixed", h, e, 0, false)}};
}

CellAnswer<2> homogenise_periodic(const SolveInput<2>& in, std::vector<std::string>& warnings) {
  const auto& [dir, staged, t, e, pm, foam, deadline, picture_width, all_pictures, section_z, unit, fe_mesh, refine, solver, fe_mesh_file] = in;

  const std::vector<LoadCase<3>> loads = periodic_load_cases(e, foam);
  const PeriodicHomogenised<3> h =
      solve_periodic(load_case_dirs(loads, dir), e, pm, foam, solves_side_by_side(foam.processes), deadline,
                     load_case_dirs(loads, staged.failed_dir()));
  std::optional<ThermalResidual<3>> thermal;
  if (foam.delta_T != 0.0) thermal = thermal_residual(h);
  std::vector<std::string> openfoams;  // OpenFOAM's doubts, when its answer is not the one reported
  CellAnswer<2> answer{
      .effective = periodic_answer(h, thermal ? &*thermal : nullptr, e.phases, achieved_fractions(t), foam, kAdvice,
                                   in.solver == Solver::fe ? openfoams : warnings),
      .phase_names = phase_names(t.phases),
      .stresses = {}};
  std::vector<SolvedFields> solved;
  for (int k = 0; k < 3; ++k) {
    answer.stresses.push_back(state_stresses(h.cases[k].load.name, h.cases[k], e, k, true));
    solved.push_back({"_" + h.cases[k].load.name, &h.cases[k].fields, &h.cases[k].cell_stress});
  }
  if (picture_width > 0)
    write_stress_histogram(dir / "stress_histogram.png", h.cases[0].load.name, h.cases[0].cell_stress, t, e);
  if (thermal) {
    answer.stresses.push_back(state_stresses("thermal", thermal->free, e, -1, true));
    answer.stresses.push_back(state_stresses("thermal_xx", thermal->loaded, e, 0, true));
    solved.push_back({"_thermal", &thermal->free.fields, &thermal->free.cell_stress});
    solved.push_back({"_thermal_xx", &thermal->loaded.fields, &thermal->loaded.cell_stress});
    if (picture_width > 0)
      write_stress_histogram(dir / "stress_histogram_thermal.png", "thermal", thermal->free.cell_stress, t, e);
  }
  if (picture_width > 0) write_results_vtu(dir / "results.vtu", e, phase_names(t.phases), solved, foam.convert_to_meters);
  write_field_pictures(dir, h.cases[0].fields, h.cases[0].cell_stress, e, picture_width, all_pictures, unit);
  if (fe_mesh == nullptr) return answer;
  return fe_cell_answer(in, achieved_fractions(t), kAdvice, std::move(answer), warnings);
}

CellAnswer<2> homogenise_fe(const SolveInput<2>& in, std::vector<std::string>& warnings) {
  return fe_cell_answer(in, achieved_fractions(in.t), kAdvice, {}, warnings);
}

}  // namespace grainmesh
