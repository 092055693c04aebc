#include "pipelines/solve_cell.hpp"

#include <optional>
#include <tuple>

#include "analysis/bounds.hpp"
#include "analysis/phase_statistics.hpp"
#include "analysis/results_vtu.hpp"
#include "analysis/thermal.hpp"
#include "common/format.hpp"
#include "pipelines/result_pictures.hpp"
#include "view/box_view.hpp"
#include "view/picture.hpp"
#include "view/section.hpp"

namespace grainmesh {

namespace {

// Where the 3D answer's warnings send the user.
const AnswerAdvice kAdvice{.see = "see docs/3d.md, 3D cases and solves",
                           .why = "a finite cell is not isotropic, and the 3D cells' shears across phase interfaces "
                                  "are first order in the mesh size; see docs/3d.md, 3D cases and solves",
                           .refine = "refine the mesh (mesh.tets_per_grain; see docs/3d.md, 3D cases and solves)"};

// The phases' stresses of a solved state (`state` in report.json), each cell weighted by
// its volume; `loaded` the loaded component's Voigt index (-1 none); `balanced`: the
// means from the virial stresses (a periodic case's).
StateStresses state_stresses(const std::string& state, const SolvedState<6>& s, const SolveInput<3>& in, int loaded,
                             bool balanced) {
  return {state, state_phase_stresses(s, in.pm.volume, in.pm.phase, static_cast<int>(in.e.phases.size()), loaded,
                                      balanced)};
}

// The fractions of the phases' volumes.
std::vector<double> volume_fractions(const SolveInput<3>& in) {
  return phase_volume_fractions(in.pm.volume, in.pm.phase, static_cast<int>(in.e.phases.size()));
}

// The pictures of a solved state (`load_case`): the section z = in.section_z, each
// tetrahedron cut showing the mean of its corners' cells (one cell each on tetrahedra),
// sigma_xx and von Mises in MPa, in stress_xx`suffix`.png and von_mises`suffix`.png; and
// each phase's volume-weighted distribution of the cells' von Mises stress in
// stress_histogram`suffix`.png; von Mises on the cell's surface seen from outside in
// von_mises_view`suffix`.png.
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
  // A tetrahedron's value: the mean of its corners' cells' (one cell each on tetrahedra), in MPa.
  auto tet_mean = [&](int t, auto&& of) {
    double sum = 0.0;
    for (int k = 0; k < 4; ++k)
      sum += of(fields.stress[static_cast<std::size_t>(in.pm.corner_cell[4 * static_cast<std::size_t>(t) + k])]);
    return 0.25e-6 * sum;
  };
  auto sigma_xx = [](const double* c) { return c[0]; };
  auto mises = [](const double* c) { return von_mises(openfoam_stress(c)); };
  const Section s = mesh_section(in.e.mesh, in.e.grain, in.e.phase, in.section_z);
  std::vector<double> xx, section_mises;
  for (const int t : s.tet) {
    xx.push_back(tet_mean(t, sigma_xx));
    section_mises.push_back(tet_mean(t, mises));
  }
  const std::string at = ", z = " + to_text(in.section_z, 3) + (in.unit.empty() ? "" : " " + in.unit);
  // A state other than a load case's own (the thermal residual) says so in its titles.
  const std::string state = suffix.empty() ? "" : "residual ";
  for (const auto& [name, field, title, signed_field] :
       {std::tuple{"stress_xx", &xx, "sigma_xx (MPa)", true}, std::tuple{"von_mises", &section_mises, "von Mises (MPa)", false}})
    write_mesh_png(in.dir / (std::string(name) + suffix + ".png"), s.cells,
                   {.width_px = in.picture_width, .fill_by = {}, .outline_by = s.grain, .view = {}, .field = *field,
                    .field_name = state + title + at, .signed_field = signed_field, .legend = {}, .scale_bar = true,
                    .length_unit = in.unit});
  // The same von Mises stress on the cell's surface, seen from outside.
  BoxView view = box_view(in.e.mesh);
  for (double& shade : view.shade) shade = 0.6 + 0.4 * shade;  // lighter: the colours still read against the bar
  std::vector<double> surface_mises;
  for (const int t : view.tet) surface_mises.push_back(tet_mean(t, mises));
  write_mesh_png(in.dir / ("von_mises_view" + suffix + ".png"), view.mesh,
                 {.width_px = in.picture_width, .fill_by = {}, .outline_by = view.outline(in.e.grain), .view = {}, .shade = view.shade,
                  .field = surface_mises, .field_name = state + "von Mises (MPa) on the cell's surface",
                  .signed_field = false, .legend = {}, .scale_bar = true, .length_unit = in.unit});
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

CellAnswer<3> homogenise_mixed(const SolveInput<3>& in, std::vector<std::string>& warnings) {
  const MixedHomogenised<6> h = solve_mixed(in.dir / "case", in.e, in.pm, in.foam, in.deadline, in.staged.failed_dir() / "case");
  write_state_pictures(in, h.fields, "mixed", "");
  if (in.picture_width > 0) write_results_vtu(in.dir / "results.vtu", in.pm, phase_names(in.t.phases), {{"", &h.fields, nullptr}}, in.foam.convert_to_meters);
  return {.effective = mixed_answer(h, in.e.phases, volume_fractions(in), in.foam, kAdvice, warnings),
          .phase_names = phase_names(in.t.phases),
          .stresses = {state_stresses("mixed", h, in, 0, false)}};
}

CellAnswer<3> homogenise_periodic(const SolveInput<3>& in, std::vector<std::string>& warnings) {
  const std::vector<LoadCase<6>> loads = periodic_load_cases(in.e, in.foam);
  const PeriodicHomogenised<6> h =
      solve_periodic(load_case_dirs(loads, in.dir), in.e, in.pm, in.foam, solves_side_by_side(in.foam.processes),
                     in.deadline, load_case_dirs(loads, in.staged.failed_dir()));
  std::optional<ThermalResidual<6>> thermal;
  if (in.foam.delta_T != 0.0) thermal = thermal_residual(h);
  std::vector<std::string> openfoams;  // OpenFOAM's doubts, when its answer is not the one reported
  CellAnswer<3> answer{.effective = periodic_answer(h, thermal ? &*thermal : nullptr, in.e.phases, volume_fractions(in),
                                                    in.foam, kAdvice, in.solver == Solver::fe ? openfoams : warnings),
                       .phase_names = phase_names(in.t.phases),
                       .stresses = {}};
  // The thermal case at its fixed strain is no state of its own: its free state is below.
  for (std::size_t k = 0; k < 6; ++k)
    answer.stresses.push_back(state_stresses(h.cases[k].load.name, h.cases[k], in, static_cast<int>(k), true));
  if (thermal) {
    answer.stresses.push_back(state_stresses("thermal", thermal->free, in, -1, true));
    answer.stresses.push_back(state_stresses("thermal_xx", thermal->loaded, in, 0, true));
    write_state_pictures(in, thermal->free.fields, "thermal", "_thermal");
  }
  write_state_pictures(in, h.cases[0].fields, "xx", "");
  write_periodic_results_vtu(in, h, thermal ? &*thermal : nullptr);
  if (in.fe_mesh == nullptr) return answer;
  return fe_cell_answer(in, volume_fractions(in), kAdvice, std::move(answer), warnings);
}

CellAnswer<3> homogenise_fe(const SolveInput<3>& in, std::vector<std::string>& warnings) {
  return fe_cell_answer(in, volume_fractions(in), kAdvice, {}, warnings);
}

}  // namespace grainmesh
