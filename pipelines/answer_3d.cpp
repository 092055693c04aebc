#include "pipelines/answer_3d.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <thread>
#include <tuple>

#include "analysis/bounds.hpp"
#include "analysis/phase_statistics_3d.hpp"
#include "analysis/results_vtu.hpp"
#include "analysis/thermal_3d.hpp"
#include "common/format.hpp"
#include "pipelines/result_pictures.hpp"
#include "view/picture.hpp"
#include "view/section.hpp"

namespace grainmesh {

namespace {

constexpr const char* kVoigtNames[6] = {"xx", "yy", "zz", "yz", "xz", "xy"};

// {PHASE: {volume_fraction, mean {xx ... xy}, von_mises, hydrostatic}}, Pa; the means
// from the virial stresses when given (a periodic case's).
Json phase_stresses_json(const CaseFields& fields, const SolveInput3& in, const FieldValues* balanced = nullptr) {
  Json out;
  const std::vector<PhaseStresses3> ps =
      phase_stresses_3d(fields.stress, in.fm.volume, in.fm.phase, static_cast<int>(in.e.phases.size()), balanced);
  for (std::size_t p = 0; p < ps.size(); ++p) {
    Json mean;
    for (int i = 0; i < 6; ++i) mean[kVoigtNames[i]] = ps[p].mean[static_cast<std::size_t>(i)];
    out[in.e.phases[p].name] = {{"volume_fraction", ps[p].volume_fraction},
                                {"mean", mean},
                                {"von_mises", distribution_json(ps[p].von_mises)},
                                {"hydrostatic", distribution_json(ps[p].hydrostatic)}};
  }
  return out;
}

// Cij for 1 <= i <= j <= 6.
Json stiffness_json(const Stiffness<6>& c) {
  Json out;
  for (int i = 0; i < 6; ++i)
    for (int j = i; j < 6; ++j) {
      const char name[4] = {'C', static_cast<char>('1' + i), static_cast<char>('1' + j), '\0'};
      out[name] = c[i][j];
    }
  return out;
}

std::vector<std::string> phase_names(const SolveInput3& in) {
  std::vector<std::string> names;
  for (const FoamPhase& p : in.e.phases) names.push_back(p.name);
  return names;
}

// {xx, yy, zz, yz, xz, xy}.
Json voigt_json(const Voigt6& v) {
  Json out;
  for (int i = 0; i < 6; ++i) out[kVoigtNames[i]] = v[static_cast<std::size_t>(i)];
  return out;
}

// The pictures of a solved state (`load_case`): the section z = in.section_z, each
// tetrahedron cut showing the mean of its corners' cells (one cell each on tetrahedra),
// sigma_xx and von Mises in MPa, in stress_xx`suffix`.png and von_mises`suffix`.png; and
// each phase's volume-weighted distribution of the cells' von Mises stress in
// stress_histogram`suffix`.png.
void write_state_pictures(const SolveInput3& in, const CaseFields& fields, const std::string& load_case,
                          const std::string& suffix) {
  if (in.picture_width == 0) return;
  std::vector<double> cell_mises;
  for (std::size_t c = 0; c < fields.stress.size(); ++c) cell_mises.push_back(von_mises_3d(fields.stress[c]));
  const std::vector<std::string> names = phase_names(in);
  write_stress_histogram(in.dir / ("stress_histogram" + suffix + ".png"), load_case,
                         phase_histograms(cell_mises, in.fm.volume, in.fm.phase, static_cast<int>(names.size()),
                                          kHistogramBins),
                         names, "volume");
  const Section s = mesh_section(in.e.mesh, in.e.grain, in.e.phase, in.section_z);
  std::vector<double> xx, mises;
  for (const int t : s.tet) {
    double sum_xx = 0.0, sum_mises = 0.0;
    for (int k = 0; k < 4; ++k) {
      const double* c = fields.stress[static_cast<std::size_t>(in.fm.corner_cell[4 * static_cast<std::size_t>(t) + k])];
      sum_xx += c[0];
      sum_mises += von_mises_3d(c);
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
ThermalResidual3 add_thermal_answer_3d(Answer& answer, const PeriodicHomogenised3& h, const Stiffness<6>& C,
                                       const SolveInput3& in, std::vector<std::string>& warnings) {
  const ThermalResidual3 r = thermal_residual_3d(h, C);
  answer.effective["thermal_expansion"] = voigt_json(r.expansion);
  Json thermal{{"delta_T", r.delta_T}};
  if (const auto levin = levin_expansion_3d(in.e.phases, C)) {
    thermal["levin"] = voigt_json(*levin);
    thermal["levin_difference"] =
        levin_difference({r.expansion.begin(), r.expansion.end()}, {levin->begin(), levin->end()}, warnings,
                         "refine the mesh (mesh.tets_per_grain; see docs/3d.md, 3D cases and solves)");
  }
  answer.effective["thermal"] = thermal;
  answer.stresses["thermal"] = phase_stresses_json(r.fields, in, &r.virial_stress);
  answer.stresses["thermal_xx"] = phase_stresses_json(r.loaded_fields, in, &r.loaded_virial_stress);
  write_state_pictures(in, r.fields, "thermal", "_thermal");
  return r;
}

// results.vtu (unless pictures are off) of the periodic cases: each mechanical case's
// fields suffixed _NAME, the thermal residual's _thermal and, cooled then pulled, _thermal_xx.
void write_periodic_results_vtu(const SolveInput3& in, const PeriodicHomogenised3& h, const ThermalResidual3* thermal) {
  if (in.picture_width == 0) return;
  std::vector<std::pair<std::string, const CaseFields*>> cases;
  for (const LoadCaseResult3& r : h.cases)
    if (r.load.delta_T == 0.0) cases.push_back({"_" + r.load.name, &r.fields});
  if (thermal != nullptr) {
    cases.push_back({"_thermal", &thermal->fields});
    cases.push_back({"_thermal_xx", &thermal->loaded_fields});
  }
  write_results_vtu_3d(in.dir / "results.vtu", in.fm, phase_names(in), cases, in.foam.convert_to_meters);
}

}  // namespace

std::string periodic_case_dir_3d(const LoadCase3& c) { return "case_" + c.name; }

Answer homogenise_mixed_3d(const SolveInput3& in, std::vector<std::string>& warnings) {
  const Mixed3 h = solve_mixed_3d(in.dir / "case", in.e, in.fm, in.foam, in.deadline, in.staged.failed_dir() / "case");
  Answer answer;
  answer.stresses["mixed"] = phase_stresses_json(h.fields, in);
  write_state_pictures(in, h.fields, "mixed", "");
  if (in.picture_width > 0) write_results_vtu_3d(in.dir / "results.vtu", in.fm, phase_names(in), {{"", &h.fields}}, in.foam.convert_to_meters);
  Json& effective = answer.effective;
  effective = solve_json(h.run, in.dir);
  effective["boundary"] = "mixed";
  effective["modulus"] = h.modulus;
  effective["sigma_xx"] = h.sigma_xx;
  effective["strain_xx"] = h.strain_xx;
  if (in.foam.uniaxial) return answer;  // the bounds are for the cell held sideways
  // Uniaxial strain: between the Reuss and Voigt tensors' C11 for every microstructure.
  const TensorBounds<6> b = tensor_bounds<6>(
      in.e.phases, phase_volume_fractions(in.fm.volume, in.fm.phase, static_cast<int>(in.e.phases.size())));
  effective["voigt"] = b.voigt[0][0];
  effective["reuss"] = b.reuss[0][0];
  const auto above = outside("effective.modulus", h.modulus, b.voigt[0][0], "the Voigt bound", true);
  const auto below = outside("effective.modulus", h.modulus, b.reuss[0][0], "the Reuss bound", false);
  effective["inside_bounds"]["voigt_reuss"] = !above && !below;
  for (const auto& w : {above, below})
    if (w) warnings.push_back(*w + ": check the solve (see docs/3d.md, 3D cases and solves)");
  return answer;
}

Answer homogenise_periodic_3d(const SolveInput3& in, std::vector<std::string>& warnings) {
  std::vector<std::filesystem::path> dirs, shown;
  for (const LoadCase3& c : periodic_load_cases_3d(in.e, in.foam)) {
    dirs.push_back(in.dir / periodic_case_dir_3d(c));
    shown.push_back(in.staged.failed_dir() / periodic_case_dir_3d(c));
  }
  // The load cases side by side, as many as the cores take with each case's processes.
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int parallel = std::max(1, cores / std::max(1, in.foam.processes));
  const PeriodicHomogenised3 h = solve_periodic_3d(dirs, in.e, in.fm, in.foam, parallel, in.deadline, shown);
  Answer answer;
  Json& effective = answer.effective;
  effective["boundary"] = "periodic";
  effective["strain"] = load_strain(foam_cell(in.e), in.foam);  // each case's (engineering) strain
  int corrections = 0;
  for (const LoadCaseResult3& r : h.cases) {
    effective["load_cases"][r.load.name] = solve_json(r.run, in.dir);
    corrections = std::max(corrections, r.run.corrections);
    // The thermal case at its fixed strain is no state of its own: its free state is below.
    if (r.load.delta_T == 0.0) answer.stresses[r.load.name] = phase_stresses_json(r.fields, in, &r.virial_stress);
  }
  effective["corrections"] = corrections;
  write_state_pictures(in, h.cases[0].fields, "xx", "");
  const Stiffness<6> C = symmetric_part(h.stiffness);
  effective["stiffness"] = stiffness_json(C);
  effective["symmetry_error"] = symmetry_error(h.stiffness);
  const EngineeringConstants3 k = engineering_constants_3d(C);
  effective["engineering"] = {{"E_x", k.E_x},     {"E_y", k.E_y},     {"E_z", k.E_z},     {"G_yz", k.G_yz},
                              {"G_xz", k.G_xz},   {"G_xy", k.G_xy},   {"nu_xy", k.nu_xy}, {"nu_xz", k.nu_xz},
                              {"nu_yz", k.nu_yz}, {"universal_anisotropy", k.universal_anisotropy}};
  std::optional<ThermalResidual3> thermal;
  if (in.foam.delta_T != 0.0) thermal = add_thermal_answer_3d(answer, h, C, in, warnings);
  write_periodic_results_vtu(in, h, thermal ? &*thermal : nullptr);
  effective["bulk_modulus"] = bulk_modulus(C);
  effective["shear_modulus"] = shear_modulus(C);
  const std::vector<double> fractions =
      phase_volume_fractions(in.fm.volume, in.fm.phase, static_cast<int>(in.e.phases.size()));
  effective["volume_fractions"] = fractions;
  const TensorBounds<6> b = tensor_bounds<6>(in.e.phases, fractions);
  effective["voigt"] = stiffness_json(b.voigt);
  effective["reuss"] = stiffness_json(b.reuss);
  const double tolerance = bounds_tolerance(symmetry_error(h.stiffness));
  effective["bounds_tolerance"] = tolerance;
  note_voigt_reuss(semidefinite_order(b.reuss, C, tolerance) && semidefinite_order(C, b.voigt, tolerance), effective,
                   warnings, "see docs/3d.md, 3D cases and solves");
  if (b.bulk_upper)
    check_hashin_shtrikman(bulk_modulus(C), shear_modulus(C),
                           {*b.bulk_lower, *b.bulk_upper, *b.shear_lower, *b.shear_upper}, effective, warnings,
                           "a finite cell is not isotropic, and the 3D cells' shears across phase interfaces are first "
                           "order in the mesh size; see docs/3d.md, 3D cases and solves", tolerance);
  return answer;
}

}  // namespace grainmesh
