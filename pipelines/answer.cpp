#include "pipelines/answer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <thread>

#include "analysis/bounds.hpp"
#include "analysis/check_mesh.hpp"
#include "analysis/phase_statistics.hpp"
#include "analysis/results_vtu.hpp"
#include "analysis/thermal.hpp"
#include "common/format.hpp"
#include "pipelines/result_pictures.hpp"

namespace grainmesh {

std::string periodic_case_dir(const LoadCase& c) { return "case_" + c.name; }

void check_case_mesh(const std::filesystem::path& dir, const Deadline& deadline, Json& report, Warnings& warnings) {
  const Json& cases = report["case"];
  const std::string first = cases.is_array() ? cases.front().get<std::string>() : cases.get<std::string>();
  const MeshCheck check = check_mesh(dir / first, deadline);
  report["mesh_check"] = {{"case", first}, {"failed_checks", check.failed_checks}, {"failures", check.failures}};
  if (const std::string w = mesh_check_warning(check, first); !w.empty()) warnings.add(w);
}

Json solve_json(const SolveRun& r, const std::filesystem::path& dir) {
  Json json{{"corrections", r.corrections},
          {"final_residual", r.final_residual},
          {"stress_change", r.stress_change},
          {"component_residuals", r.component_residuals},
          {"linear_solver", r.linear_solver},
          {"result", std::filesystem::relative(r.result_dir, dir).string()},
          {"seconds",
           {{"decomposePar", r.decompose_seconds},
            {"solidDisplacementFoam", r.solver_seconds},
            {"reconstructPar", r.reconstruct_seconds}}}};
  if (!r.linear_solver_fallback.empty()) json["linear_solver_fallback"] = r.linear_solver_fallback;
  return json;
}

double bounds_tolerance(double measured_error) {
  constexpr double kRounding = 1e-6;  // relative: bounds that coincide (one material) are met to rounding
  return std::max(kRounding, measured_error);
}

std::optional<std::string> outside(const std::string& what, double value, double bound, const std::string& name,
                                   bool above, double tolerance) {
  if (above ? value <= bound * (1 + tolerance) : value >= bound * (1 - tolerance)) return std::nullopt;
  return what + " " + to_text(value, 4) + " Pa lies " + (above ? "above" : "below") + " " + name + " " +
         to_text(bound, 4) + " Pa by " + to_text(100.0 * std::abs(value / bound - 1.0), 2) + " %";
}

void note_voigt_reuss(bool inside, Json& effective, std::vector<std::string>& warnings, const std::string& see) {
  effective["inside_bounds"]["voigt_reuss"] = inside;
  if (!inside)
    warnings.push_back("effective.stiffness does not lie between the Reuss and Voigt tensors (positive semidefinite "
                       "order): check the solve (" + see + ")");
}

void check_hashin_shtrikman(double K, double G, const ModuliBounds& b, Json& effective, std::vector<std::string>& warnings,
                            const std::string& why, double tolerance) {
  effective["hashin_shtrikman"] = {
      {"bulk_lower", b.bulk_lower}, {"bulk_upper", b.bulk_upper}, {"shear_lower", b.shear_lower}, {"shear_upper", b.shear_upper}};
  bool inside = true;
  for (const auto& w : {outside("effective.bulk_modulus", K, b.bulk_upper, "the Hashin-Shtrikman upper bound", true, tolerance),
                        outside("effective.bulk_modulus", K, b.bulk_lower, "the Hashin-Shtrikman lower bound", false, tolerance),
                        outside("effective.shear_modulus", G, b.shear_upper, "the Hashin-Shtrikman upper bound", true, tolerance),
                        outside("effective.shear_modulus", G, b.shear_lower, "the Hashin-Shtrikman lower bound", false, tolerance)})
    if (w) {
      inside = false;
      warnings.push_back(*w + " (" + why + ")");
    }
  effective["inside_bounds"]["hashin_shtrikman"] = inside;
}

Json distribution_json(const Distribution& d) {
  return {{"mean", d.mean}, {"std", d.std}, {"p50", d.p50}, {"p90", d.p90}, {"p99", d.p99}, {"max", d.max}};
}

double levin_difference(const std::vector<double>& expansion, const std::vector<double>& levin,
                        std::vector<std::string>& warnings, const std::string& advice) {
  double scale = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < levin.size(); ++k) {
    scale = std::max(scale, std::abs(levin[k]));
    difference = std::max(difference, std::abs(expansion[k] - levin[k]));
  }
  if (difference > 0.01 * scale)
    warnings.push_back("effective.thermal_expansion differs from Levin's exact relation by " +
                       to_text(100.0 * difference / scale, 2) + " % of its largest component: " + advice);
  return difference / scale;
}

namespace {

// A solved load case: its name in the report, its recovered cell stresses, its loaded
// component (0 xx, 1 yy, 2 xy; -1 none: the thermal residual's mean is zero).
struct StressedCase {
  std::string name;
  const std::vector<StressState>* cell_stress;
  int loaded;
  const std::vector<StressState>* balanced = nullptr;  // the virial stresses, for the means (periodic)
};

std::vector<double> achieved_fractions(const Tessellation& t) {
  std::vector<double> fractions;
  for (const PhaseStats& p : t.stats.phases) fractions.push_back(p.achieved_fraction);
  return fractions;
}



// `stresses` {CASE: {PHASE: {area_fraction, mean {xx, yy, zz, xy}, von_mises,
// max_principal, hydrostatic (each mean, std, p50, p90, p99, max), partition}}}, Pa, from
// the recovered cell stresses.
Json phase_stresses_json(const std::vector<StressedCase>& cases, const Tessellation& t, const ExportMesh& e) {
  Json out;
  const int phases = static_cast<int>(t.phases.size());
  for (const StressedCase& c : cases) {
    const std::vector<PhaseStresses> ps = phase_stresses(*c.cell_stress, e.mesh, e.phase, phases, c.loaded, c.balanced);
    for (int p = 0; p < phases; ++p) {
      const PhaseStresses& s = ps[p];
      out[c.name][t.phases[p].name] = {
          {"area_fraction", s.area_fraction},
          {"mean", {{"xx", s.mean.xx}, {"yy", s.mean.yy}, {"zz", s.mean.zz}, {"xy", s.mean.xy}}},
          {"von_mises", distribution_json(s.von_mises)},
          {"max_principal", distribution_json(s.max_principal)},
          {"hydrostatic", distribution_json(s.hydrostatic)}};
      // No partition where the cell's mean stress is zero (the thermal residual).
      if (c.loaded >= 0) out[c.name][t.phases[p].name]["partition"] = s.partition;
    }
  }
  return out;
}


// What a thermal load adds to the answer: effective.thermal_expansion {a11, a22, a12}
// (1/K), effective.thermal {delta_T, levin, levin_difference}, and
// stresses.thermal (the residual stress, free expansion) and stresses.thermal_xx (cooled,
// then the load.displacement of the xx case); a free expansion that breaks Levin's
// relation by more than 1 % is a warning.
void add_thermal_answer(Answer& answer, const ThermalResidual& r, const Stiffness<3>& C, const Tessellation& t,
                        const ExportMesh& e, const FoamOptions& foam,
                        std::vector<std::string>& warnings) {
  const auto expansion_json = [](const std::array<double, 3>& a) {
    return Json{{"a11", a[0]}, {"a22", a[1]}, {"a12", a[2]}};
  };
  Json& effective = answer.effective;
  effective["thermal_expansion"] = expansion_json(r.expansion);
  // In plane strain the cell is held out of plane: one material expands (1 + nu) alpha in
  // plane, and carries sigma_zz; in plane stress alpha (docs/run.md, Thermal residual stress).
  Json thermal{{"delta_T", r.delta_T}, {"plane_state", plane_state(foam)}};
  if (const auto levin = levin_expansion(e.phases, C, foam.plane_stress)) {
    thermal["levin"] = expansion_json(*levin);
    thermal["levin_difference"] =
        levin_difference({r.expansion.begin(), r.expansion.end()}, {levin->begin(), levin->end()}, warnings,
                         "refine the mesh at the interfaces (mesh.boundary_size; see docs/run.md, Thermal residual stress)");
  }
  effective["thermal"] = thermal;
  const Json stresses = phase_stresses_json(
      {{"thermal", &r.cell_stress, -1, &r.virial_stress}, {"thermal_xx", &r.loaded_stress, 0, &r.loaded_virial_stress}},
      t, e);
  for (const auto& [name, value] : stresses.items()) answer.stresses[name] = value;
}


Json stiffness_json(const Stiffness<3>& c) {
  return {{"C11", c[0][0]}, {"C22", c[1][1]}, {"C12", c[0][1]}, {"C21", c[1][0]}, {"C66", c[2][2]},
          {"C16", c[0][2]}, {"C26", c[1][2]}, {"C61", c[2][0]}, {"C62", c[2][1]}};
}


// The Voigt and Reuss tensors and Hashin-Shtrikman's bulk and shear bounds beside the
// stiffness C in `effective`, with whether C keeps them to `tolerance` (a broken one a
// warning).
void check_tensor_bounds(const Stiffness<3>& C, const TensorBounds<3>& b, double tolerance, Json& effective,
                         std::vector<std::string>& warnings) {
  effective["voigt"] = stiffness_json(b.voigt);
  effective["reuss"] = stiffness_json(b.reuss);
  effective["bounds_tolerance"] = tolerance;
  note_voigt_reuss(semidefinite_order(b.reuss, C, tolerance) && semidefinite_order(C, b.voigt, tolerance), effective,
                   warnings, "see docs/run.md, Homogenisation");
  if (b.bulk_upper)
    check_hashin_shtrikman(bulk_modulus(C), shear_modulus(C), {*b.bulk_lower, *b.bulk_upper, *b.shear_lower, *b.shear_upper},
                           effective, warnings, "a finite cell is not isotropic; see docs/run.md, Homogenisation", tolerance);
}

}  // namespace

Answer homogenise_mixed(const SolveInput& in, std::vector<std::string>& warnings) {
  const auto& [dir, staged, t, e, pm, foam, deadline, picture_width, all_pictures, unit] = in;

  const Homogenised h = solve_and_homogenise(dir / "case", e, pm, foam, deadline, staged.failed_dir() / "case");
  Answer answer;
  const StressedCase stressed{"mixed", &h.cell_stress, 0};
  answer.stresses = phase_stresses_json({stressed}, t, e);
  if (picture_width > 0) write_stress_histogram(dir / "stress_histogram.png", stressed.name, h.cell_stress, t, e);
  Json& effective = answer.effective;
  effective = solve_json(h.run, dir);
  effective["boundary"] = "mixed";
  effective["modulus"] = h.modulus;
  effective["sigma_xx"] = h.sigma_xx;
  effective["strain_xx"] = h.strain_xx;
  effective["volume_average"] = {{"modulus", h.volume_average_modulus},
                                 {"sigma_xx", h.volume_average.xx},
                                 {"sigma_yy", h.volume_average.yy},
                                 {"sigma_xy", h.volume_average.xy}};
  if (picture_width > 0) write_results_vtu(dir / "results.vtu", e, phase_names(t), {{"", &h.fields, &h.cell_stress}}, foam.convert_to_meters);
  write_field_pictures(dir, h.fields, h.cell_stress, e, picture_width, all_pictures, unit);
  if (foam.uniaxial) return answer;  // the bounds are for the default load (mean eps_yy zero)
  const ElasticBounds b = elastic_bounds(e.phases, achieved_fractions(t), foam.plane_stress);
  effective["voigt"] = b.voigt;
  effective["reuss"] = b.reuss;
  if (b.hs_lower) effective["hashin_shtrikman"] = {{"lower", *b.hs_lower}, {"upper", *b.hs_upper}};
  // Voigt and Reuss hold for every microstructure; Hashin-Shtrikman for isotropic ones
  // (a finite cell is not quite).
  std::vector<std::optional<std::string>> broken{outside("effective.modulus", h.modulus, b.voigt, "the Voigt bound", true),
                                                 outside("effective.modulus", h.modulus, b.reuss, "the Reuss bound", false)};
  effective["inside_bounds"]["voigt_reuss"] = !broken[0] && !broken[1];
  if (b.hs_upper) {
    broken.push_back(outside("effective.modulus", h.modulus, *b.hs_upper, "the Hashin-Shtrikman upper bound", true));
    broken.push_back(outside("effective.modulus", h.modulus, *b.hs_lower, "the Hashin-Shtrikman lower bound", false));
    effective["inside_bounds"]["hashin_shtrikman"] = !broken[2] && !broken[3];
  }
  for (const auto& w : broken)
    if (w) warnings.push_back(*w + " (a finite cell is not isotropic; see docs/run.md, Homogenisation)");
  return answer;
}

Answer homogenise_periodic(const SolveInput& in, std::vector<std::string>& warnings) {
  const auto& [dir, staged, t, e, pm, foam, deadline, picture_width, all_pictures, unit] = in;

  std::vector<std::filesystem::path> dirs, shown;
  for (const LoadCase& lc : periodic_load_cases(e, foam)) {
    dirs.push_back(dir / periodic_case_dir(lc));
    shown.push_back(staged.failed_dir() / periodic_case_dir(lc));
  }
  // As many solves side by side as there are cores for their processes.
  const int parallel = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / foam.processes);
  const PeriodicHomogenised h = solve_periodic(dirs, e, pm, foam, parallel, deadline, shown);
  const Stiffness<3>& C = h.stiffness;
  const EngineeringConstants ec = engineering_constants(C);
  std::vector<StressedCase> stressed;
  for (int k = 0; k < 3; ++k)
    stressed.push_back({h.cases[k].load.name, &h.cases[k].cell_stress, k, &h.cases[k].virial_stress});
  Answer answer;
  answer.stresses = phase_stresses_json(stressed, t, e);
  if (picture_width > 0) write_stress_histogram(dir / "stress_histogram.png", stressed[0].name, *stressed[0].cell_stress, t, e);
  Json& effective = answer.effective;
  effective = {{"boundary", "periodic"},
                 {"stiffness", stiffness_json(C)},
                 {"engineering", {{"E_x", ec.E_x}, {"E_y", ec.E_y}, {"nu_xy", ec.nu_xy}, {"nu_yx", ec.nu_yx}, {"G_xy", ec.G_xy}}},
                 {"anisotropy", {{"normal", ec.anisotropy_normal}, {"shear", ec.anisotropy_shear}}},
                 {"symmetry_error", symmetry_error(C)},
                 {"bulk_modulus", bulk_modulus(C)},
                 {"shear_modulus", shear_modulus(C)},
                 {"volume_average", {{"stiffness", stiffness_json(h.volume_average_stiffness)}}}};
  Json cases = Json::array();
  int corrections = 0;
  for (const LoadCaseResult& r : h.cases) {
    Json c = solve_json(r.run, dir);
    c["name"] = r.load.name;
    c["strain"] = {{"xx", r.load.strain[0]}, {"yy", r.load.strain[1]}, {"xy", r.load.strain[2]}};
    c["stress"] = {{"xx", r.stress.xx}, {"yy", r.stress.yy}, {"xy", r.stress.xy}};
    if (r.load.delta_T != 0.0) c["delta_T"] = r.load.delta_T;
    cases.push_back(c);
    corrections = std::max(corrections, r.run.corrections);
  }
  effective["load_cases"] = cases;
  effective["corrections"] = corrections;
  std::vector<SolvedFields> solved;
  for (int k = 0; k < 3; ++k) solved.push_back({"_" + h.cases[k].load.name, &h.cases[k].fields, &h.cases[k].cell_stress});
  std::optional<ThermalResidual> thermal;
  if (foam.delta_T != 0.0) {
    thermal = thermal_residual(h);
    add_thermal_answer(answer, *thermal, C, t, e, foam, warnings);
    solved.push_back({"_thermal", &thermal->fields, &thermal->cell_stress});
    solved.push_back({"_thermal_xx", &thermal->loaded_fields, &thermal->loaded_stress});
    if (picture_width > 0)
      write_stress_histogram(dir / "stress_histogram_thermal.png", "thermal", thermal->cell_stress, t, e);
  }
  if (picture_width > 0) write_results_vtu(dir / "results.vtu", e, phase_names(t), solved, foam.convert_to_meters);
  write_field_pictures(dir, h.cases[0].fields, h.cases[0].cell_stress, e, picture_width, all_pictures, unit);

  check_tensor_bounds(C, tensor_bounds<3>(e.phases, achieved_fractions(t), foam.plane_stress),
                      bounds_tolerance(effective["symmetry_error"].get<double>()), effective, warnings);
  return answer;
}

}  // namespace grainmesh
