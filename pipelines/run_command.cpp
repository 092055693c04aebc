#include "pipelines/run_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <thread>

#include "analysis/foam_fields.hpp"
#include "analysis/homogenise.hpp"
#include "analysis/phase_statistics.hpp"
#include "analysis/results_vtu.hpp"
#include "analysis/thermal.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/memory.hpp"
#include "export/foam.hpp"
#include "export/picture.hpp"
#include "grains/conformity.hpp"
#include "mesh/quality.hpp"
#include "pipelines/default_config.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/mesh_command.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/tessellate_command.hpp"
#include "tessellate/tessellation_json.hpp"

namespace grainmesh {

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The largest of a report's per-stage figures.
double largest(const Json& stages) {
  double most = 0.0;
  for (const auto& [stage, value] : stages.items()) most = std::max(most, value.get<double>());
  return most;
}

}  // namespace

const std::vector<std::string>& run_own_config_keys() {
  static const std::vector<std::string> keys{"homogenise.boundary", "output.pictures", "load.delta_T",
                                             "solve.processes"};
  return keys;
}

Boundary read_boundary(const Config& c) {
  const std::string b = c.has("homogenise.boundary") ? c.text("homogenise.boundary") : "mixed";
  if (b == "mixed") return Boundary::mixed;
  if (b == "periodic") return Boundary::periodic;
  c.fail("homogenise.boundary", "must be mixed or periodic, got '" + b + "'");
}

Pictures read_pictures(const Config& c) {
  if (!c.has("output.pictures")) return Pictures::all;
  const std::string p = c.text("output.pictures");
  if (p == "none" || p == "false") return Pictures::none;
  if (p == "basic") return Pictures::basic;
  if (p == "all" || p == "true") return Pictures::all;
  c.fail("output.pictures", "must be none, basic or all, got '" + p + "'");
}

std::vector<std::string> run_config_keys() {
  std::vector<std::string> keys = tessellate_config_keys();
  for (const auto& k : run_own_config_keys()) keys.push_back(k);
  for (const auto& k : mesh_config_keys()) keys.push_back(k);
  for (const auto& k : export_config_keys()) keys.push_back(k);
  return keys;
}

const char* default_run_config() { return kDefaultRunConfig; }

std::string config_ini(const Config& config) {
  // "a.b.c" is key c of section [a.b]; sections in order of first appearance.
  std::vector<std::string> order;
  std::map<std::string, std::string> body;
  for (const auto& [key, value] : config.entries()) {
    const auto dot = key.rfind('.');
    const std::string section = dot == std::string::npos ? "" : key.substr(0, dot);
    if (!body.count(section)) order.push_back(section);
    body[section] += key.substr(dot + 1) + " = " + value + "\n";
  }
  std::string text = "# The resolved config of a grainmesh run: `grainmesh run config.ini -o OUT` repeats it.\n";
  for (const std::string& s : order) text += "\n[" + s + "]\n" + body[s];
  return text;
}

std::string config_fingerprint(const Config& c) {
  std::string text;
  for (const auto& [key, value] : c.entries())
    if (key != "mesh.threads" && key != kTimeLimitKey) text += key + "=" + value + "\n";
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a, 64 bits
  for (const unsigned char ch : text) h = (h ^ ch) * 0x100000001b3ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

FoamOptions read_run_foam_options(const Config& c) {
  FoamOptions o = read_foam_options(c.subset(export_config_keys()));
  const long long processes = c.integer("solve.processes", 1);
  if (processes < 1 || processes > 1024) c.fail("solve.processes", "must be a count from 1 to 1024, got " + c.text("solve.processes"));
  o.processes = static_cast<int>(processes);
  o.delta_T = c.number("load.delta_T", 0.0);
  if (!std::isfinite(o.delta_T)) c.fail("load.delta_T", "must be a finite number (K), got " + c.text("load.delta_T"));
  if (o.delta_T != 0.0) {
    // Every phase's expansion, from the config (the tessellation reads the same keys).
    for (const std::string& name : c.names_in("phase")) {
      const std::string key = "phase." + name + ".alpha";
      if (!c.has(key))
        c.fail(key, "missing: load.delta_T = " + c.text("load.delta_T") +
                        " needs every phase's linear thermal expansion (1/K, e.g. 5e-6 for WC, 14e-6 for Co)");
      if (!(c.number(key) >= 0.0)) c.fail(key, "must be >= 0 (1/K), got " + c.text(key));
    }
    if (read_boundary(c) != Boundary::periodic)
      c.fail("load.delta_T", "needs homogenise.boundary = periodic: the thermal load is solved on a periodic cell, "
                             "free to expand on average");
  }
  if (read_boundary(c) != Boundary::periodic) return o;
  if (!c.flag("domain.periodic", false))
    c.fail("homogenise.boundary", "periodic needs a periodic cell: set domain.periodic = true");
  for (const char* key : {"load.traction", "load.uniaxial"})
    if (c.has(key))
      c.fail(key, "not with homogenise.boundary = periodic, whose load cases are macroscopic strains (of "
                  "load.displacement / width)");
  if (c.has("export.cyclic") && !o.cyclic)
    c.fail("export.cyclic", "homogenise.boundary = periodic needs the cyclic pairs; remove export.cyclic = false");
  o.cyclic = true;
  return o;
}

void check_run_config(const Config& c) {
  c.check_keys(run_config_keys());
  read_pictures(c);
  read_tessellate_job(c.subset(tessellate_config_keys()));
  read_run_foam_options(c);
}

namespace {

// Pictures of a solved case's fields over the cells, grain boundaries drawn (the thesis'
// 3.14-3.15), stresses in MPa, the displacement in nm, a scale bar in `unit`; none when
// picture_width is 0, sigma_xx alone when not `all`.
void write_field_pictures(const std::filesystem::path& dir, const CaseFields& fields,
                          const std::vector<StressState>& sigma, const GrainMesh& m, int picture_width, bool all,
                          const std::string& unit) {
  if (picture_width == 0) return;
  std::vector<double> sxx, syy, sxy, d = displacement_length(fields);
  for (const StressState& s : sigma) sxx.push_back(1e-6 * s.xx), syy.push_back(1e-6 * s.yy), sxy.push_back(1e-6 * s.xy);
  for (double& v : d) v *= 1e9;
  std::vector<std::pair<std::string, std::pair<std::vector<double>, std::string>>> pictures{
      {"stress_xx.png", {sxx, "sigma_xx (MPa)"}}};
  if (all) {
    pictures.push_back({"stress_yy.png", {syy, "sigma_yy (MPa)"}});
    pictures.push_back({"stress_xy.png", {sxy, "tau_xy (MPa)"}});
    pictures.push_back({"displacement.png", {d, "|D| (nm)"}});
  }
  for (const auto& [name, field] : pictures)
    write_mesh_png(dir / name, m.mesh,
                   {.width_px = picture_width, .outline_by = {}, .view = {}, .field = field.first,
                    .field_name = field.second, .legend = {}, .scale_bar = true, .length_unit = unit});
}

Json solve_json(const SolveRun& r, const std::filesystem::path& dir) {
  return {{"corrections", r.corrections},
          {"final_residual", r.final_residual},
          {"stress_change", r.stress_change},
          {"component_residuals", r.component_residuals},
          {"result", std::filesystem::relative(r.result_dir, dir).string()},
          {"seconds",
           {{"decomposePar", r.decompose_seconds},
            {"solidDisplacementFoam", r.solver_seconds},
            {"reconstructPar", r.reconstruct_seconds}}}};
}

// A bound broken by `value`, as a warning (nothing when it holds, to rounding).
constexpr double kRounding = 1e-6;  // relative: bounds that coincide (one material) are met to rounding
std::optional<std::string> outside(const std::string& what, double value, double bound, const std::string& name,
                                   bool above) {
  if (above ? value <= bound * (1 + kRounding) : value >= bound * (1 - kRounding)) return std::nullopt;
  return what + " " + to_text(value, 4) + " Pa lies " + (above ? "above" : "below") + " " + name + " " +
         to_text(bound, 4) + " Pa by " + to_text(100.0 * std::abs(value / bound - 1.0), 2) + " %";
}

std::vector<std::string> phase_names(const Tessellation& t) {
  std::vector<std::string> names;
  for (const Phase& p : t.phases) names.push_back(p.name);
  return names;
}

std::vector<double> achieved_fractions(const Tessellation& t) {
  std::vector<double> fractions;
  for (const PhaseStats& p : t.stats.phases) fractions.push_back(p.achieved_fraction);
  return fractions;
}

// The case directory of a periodic load case: case_xx, case_yy, case_xy.
std::string periodic_case_dir(const LoadCase& c) { return "case_" + c.name; }

// What a solve adds to report.json: `effective` and `stresses`.
struct Answer {
  Json effective;
  Json stresses;
};

Json distribution_json(const Distribution& d) {
  return {{"mean", d.mean}, {"std", d.std}, {"p50", d.p50}, {"p90", d.p90}, {"p99", d.p99}, {"max", d.max}};
}

// A solved load case: its name in the report, its recovered cell stresses, its loaded
// component (0 xx, 1 yy, 2 xy; -1 none: the thermal residual's mean is zero).
struct StressedCase {
  std::string name;
  const std::vector<StressState>* cell_stress;
  int loaded;
  const std::vector<StressState>* balanced = nullptr;  // the virial stresses, for the means (periodic)
};

// `stresses` {CASE: {PHASE: {area_fraction, mean {xx, yy, zz, xy}, von_mises,
// max_principal, hydrostatic (each mean, std, p50, p90, p99, max), partition}}}, Pa, from
// the recovered cell stresses.
Json phase_stresses_json(const std::vector<StressedCase>& cases, const Tessellation& t, const GrainMesh& m) {
  Json out;
  const int phases = static_cast<int>(t.phases.size());
  for (const StressedCase& c : cases) {
    const std::vector<PhaseStresses> ps = phase_stresses(*c.cell_stress, m.mesh, m.phase, phases, c.loaded, c.balanced);
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

// stress_histogram.png: each phase's distribution of von Mises stress in load case `c`.
void write_stress_histogram(const std::filesystem::path& file, const StressedCase& c, const Tessellation& t,
                            const GrainMesh& m) {
  const int phases = static_cast<int>(t.phases.size());
  Plot plot{.x_label = "von Mises stress (MPa), load case " + c.name, .y_label = "share of the phase's area",
            .series = {}};
  auto histograms = von_mises_histograms(*c.cell_stress, m.mesh, m.phase, phases, 40);
  for (int p = 0; p < phases; ++p) {
    for (Vec2& point : histograms[p]) point.x *= 1e-6;
    plot.series.push_back({t.phases[p].name, histograms[p], true, p});
  }
  write_plot_png(file, plot);
}

// The mixed (thesis) load's answer in report.json, with the bounds that hold for it;
// a broken bound is added to `warnings`.
Answer homogenise_mixed(const std::filesystem::path& dir, const StagedOutput& staged, const Tessellation& t,
                        const GrainMesh& m, const ExportMesh& e, const PolyMesh& pm, const FoamOptions& foam,
                        const Deadline& deadline, int picture_width, bool all_pictures,
                        std::vector<std::string>& warnings) {
  const Homogenised h = solve_and_homogenise(dir / "case", e, pm, foam, deadline, staged.failed_dir() / "case");
  Answer answer;
  const StressedCase stressed{"mixed", &h.cell_stress, 0};
  answer.stresses = phase_stresses_json({stressed}, t, m);
  if (picture_width > 0) write_stress_histogram(dir / "stress_histogram.png", stressed, t, m);
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
  if (picture_width > 0) write_results_vtu(dir / "results.vtu", m, phase_names(t), {{"", &h.fields, &h.cell_stress}});
  write_field_pictures(dir, h.fields, h.cell_stress, m, picture_width, all_pictures,
                       length_unit_name(foam.convert_to_meters));
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
    if (w) warnings.push_back(*w + " (a finite cell is not isotropic; see README, Homogenisation)");
  return answer;
}

// What a thermal load adds to the answer: effective.thermal_expansion {a11, a22, a12}
// (1/K), effective.thermal {delta_T, levin, levin_difference}, and
// stresses.thermal (the residual stress, free expansion) and stresses.thermal_xx (cooled,
// then the load.displacement of the xx case); a free expansion that breaks Levin's
// relation by more than 1 % is a warning.
void add_thermal_answer(Answer& answer, const ThermalResidual& r, const Stiffness& C, const Tessellation& t,
                        const GrainMesh& m, const ExportMesh& e, const FoamOptions& foam,
                        std::vector<std::string>& warnings) {
  const auto expansion_json = [](const std::array<double, 3>& a) {
    return Json{{"a11", a[0]}, {"a22", a[1]}, {"a12", a[2]}};
  };
  Json& effective = answer.effective;
  effective["thermal_expansion"] = expansion_json(r.expansion);
  Json thermal{{"delta_T", r.delta_T}};
  if (const auto levin = levin_expansion(e.phases, C, foam.plane_stress)) {
    double scale = 0.0, difference = 0.0;
    for (int k = 0; k < 3; ++k) {
      scale = std::max(scale, std::abs((*levin)[k]));
      difference = std::max(difference, std::abs(r.expansion[k] - (*levin)[k]));
    }
    thermal["levin"] = expansion_json(*levin);
    thermal["levin_difference"] = difference / scale;
    if (difference > 0.01 * scale)
      warnings.push_back("effective.thermal_expansion differs from Levin's exact relation by " +
                         to_text(100.0 * difference / scale, 2) + " % of its largest component: refine the mesh at "
                         "the interfaces (mesh.boundary_size; see README, Thermal residual stress)");
  }
  effective["thermal"] = thermal;
  const Json stresses = phase_stresses_json(
      {{"thermal", &r.cell_stress, -1, &r.virial_stress}, {"thermal_xx", &r.loaded_stress, 0, &r.loaded_virial_stress}},
      t, m);
  for (const auto& [name, value] : stresses.items()) answer.stresses[name] = value;
}

Json stiffness_json(const Stiffness& c) {
  return {{"C11", c[0][0]}, {"C22", c[1][1]}, {"C12", c[0][1]}, {"C21", c[1][0]}, {"C66", c[2][2]},
          {"C16", c[0][2]}, {"C26", c[1][2]}, {"C61", c[2][0]}, {"C62", c[2][1]}};
}

// The periodic load cases' answer in report.json: the stiffness tensor, its engineering
// constants, and the bounds; a broken bound is added to `warnings`.
Answer homogenise_periodic(const std::filesystem::path& dir, const StagedOutput& staged, const Tessellation& t,
                           const GrainMesh& m, const ExportMesh& e, const PolyMesh& pm, const FoamOptions& foam,
                           const Deadline& deadline, int picture_width, bool all_pictures,
                           std::vector<std::string>& warnings) {
  std::vector<std::filesystem::path> dirs, shown;
  for (const LoadCase& lc : periodic_load_cases(e, foam)) {
    dirs.push_back(dir / periodic_case_dir(lc));
    shown.push_back(staged.failed_dir() / periodic_case_dir(lc));
  }
  // As many solves side by side as there are cores for their processes.
  const int parallel = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / foam.processes);
  const PeriodicHomogenised h = solve_periodic(dirs, e, pm, foam, parallel, deadline, shown);
  const Stiffness& C = h.stiffness;
  const EngineeringConstants ec = engineering_constants(C);
  std::vector<StressedCase> stressed;
  for (int k = 0; k < 3; ++k)
    stressed.push_back({h.cases[k].load.name, &h.cases[k].cell_stress, k, &h.cases[k].virial_stress});
  Answer answer;
  answer.stresses = phase_stresses_json(stressed, t, m);
  if (picture_width > 0) write_stress_histogram(dir / "stress_histogram.png", stressed[0], t, m);
  Json& effective = answer.effective;
  effective = {{"boundary", "periodic"},
                 {"stiffness", stiffness_json(C)},
                 {"engineering", {{"E_x", ec.E_x}, {"E_y", ec.E_y}, {"nu_xy", ec.nu_xy}, {"nu_yx", ec.nu_yx}, {"G_xy", ec.G_xy}}},
                 {"anisotropy", {{"normal", ec.anisotropy_normal}, {"shear", ec.anisotropy_shear}}},
                 {"symmetry_error", std::abs(C[0][1] - C[1][0]) / C[0][0]},
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
    add_thermal_answer(answer, *thermal, C, t, m, e, foam, warnings);
    solved.push_back({"_thermal", &thermal->fields, &thermal->cell_stress});
    solved.push_back({"_thermal_xx", &thermal->loaded_fields, &thermal->loaded_stress});
    if (picture_width > 0)
      write_stress_histogram(dir / "stress_histogram_thermal.png", {"thermal", &thermal->cell_stress, -1}, t, m);
  }
  if (picture_width > 0) write_results_vtu(dir / "results.vtu", m, phase_names(t), solved);
  write_field_pictures(dir, h.cases[0].fields, h.cases[0].cell_stress, m, picture_width, all_pictures,
                       length_unit_name(foam.convert_to_meters));

  const TensorBounds b = tensor_bounds(e.phases, achieved_fractions(t), foam.plane_stress);
  effective["voigt"] = stiffness_json(b.voigt);
  effective["reuss"] = stiffness_json(b.reuss);
  const bool voigt_reuss = semidefinite_order(b.reuss, C) && semidefinite_order(C, b.voigt);
  effective["inside_bounds"]["voigt_reuss"] = voigt_reuss;
  if (!voigt_reuss)
    warnings.push_back("effective.stiffness does not lie between the Reuss and Voigt tensors (positive semidefinite "
                       "order): check the solve (see README, Homogenisation)");
  if (b.bulk_upper) {
    effective["hashin_shtrikman"] = {{"bulk_lower", *b.bulk_lower}, {"bulk_upper", *b.bulk_upper},
                                     {"shear_lower", *b.shear_lower}, {"shear_upper", *b.shear_upper}};
    const std::vector<std::optional<std::string>> broken{
        outside("effective.bulk_modulus", bulk_modulus(C), *b.bulk_upper, "the Hashin-Shtrikman upper bound", true),
        outside("effective.bulk_modulus", bulk_modulus(C), *b.bulk_lower, "the Hashin-Shtrikman lower bound", false),
        outside("effective.shear_modulus", shear_modulus(C), *b.shear_upper, "the Hashin-Shtrikman upper bound", true),
        outside("effective.shear_modulus", shear_modulus(C), *b.shear_lower, "the Hashin-Shtrikman lower bound", false)};
    bool inside = true;
    for (const auto& w : broken)
      if (w) {
        inside = false;
        warnings.push_back(*w + " (a finite cell is not isotropic; see README, Homogenisation)");
      }
    effective["inside_bounds"]["hashin_shtrikman"] = inside;
  }
  return answer;
}

}  // namespace

void run_run_command(const Config& c, const std::filesystem::path& out, bool solve, bool quiet, bool summary) {
  c.check_keys(run_config_keys());
  check_output_replaceable(out, "run");
  // Each stage reads its part; every value is checked before any work is done.
  const Config tess_config = c.subset(tessellate_config_keys());
  const Config mesh_config = c.subset(mesh_config_keys());
  const TessellateJob tess_job = read_tessellate_job(tess_config);
  FoamOptions foam = read_run_foam_options(c);
  const Boundary boundary = read_boundary(c);
  // Pictures cost more than the rest of a small run's output; sweeps may do without.
  const Pictures pictures = read_pictures(c);
  if (solve && foam.traction != 0.0)
    c.fail("load.traction", "--solve homogenises under an imposed displacement; remove load.traction");
  Warnings warnings;
  const TessellationOptions& to = tess_job.options;
  for (const std::string& w :
       check_load(Box{{0.0, 0.0}, {to.width, to.height}}, to.periodic, foam_phases(to.phases), foam))
    warnings.add(w);
  const auto start = std::chrono::steady_clock::now();
  // The stage on one line of a terminal, rewritten in place (at most ten times a second).
  const bool show = !quiet && isatty(STDERR_FILENO) != 0;
  auto last_shown = start - std::chrono::seconds(1);
  auto stage = [&](const std::string& what, bool force = true) {
    if (!show) return;
    const auto now = std::chrono::steady_clock::now();
    if (!force && now - last_shown < std::chrono::milliseconds(100)) return;
    last_shown = now;
    std::fprintf(stderr, "\r\033[Kgrainmesh run: %s (%.1f s)", what.c_str(), since(start));
    std::fflush(stderr);
  };
  auto end_stage_line = [&] {
    if (show) std::fprintf(stderr, "\r\033[K");
  };

  auto clock = std::chrono::steady_clock::now();
  // Each stage's peak resident memory (the solve's with the solver's processes).
  Json memory = Json::object();
  std::unique_ptr<StageMemory> memory_meter;
  auto begin_memory = [&](bool with_children = false) { memory_meter = std::make_unique<StageMemory>(with_children); };
  auto end_memory = [&](const char* name) {
    memory[name] = memory_meter->peak_mib();
    memory_meter.reset();
  };
  begin_memory();
  stage("tessellating");
  const Tessellation t = run_tessellate_job(tess_job, tess_config);
  check_phases_have_grains(t, tess_job, tess_config);
  const double tessellate_seconds = since(clock);
  end_memory("tessellate");
  end_stage_line();
  for (const std::string& w : tessellation_warnings(t)) warnings.add(w);

  clock = std::chrono::steady_clock::now();
  begin_memory();
  MeshJob mesh_job = read_mesh_job(mesh_config, t);
  mesh_job.options.distmesh.deadline = tess_job.options.deadline;  // one guard for the whole run
  stage("meshing");
  if (show)
    mesh_job.options.progress = [&](int done, int total) {
      stage("meshing: " + std::to_string(done) + " / " + std::to_string(total) + " regions", done == total);
    };
  const GrainMesh m = mesh_tessellation(t, mesh_job.options);
  check_conformity(t, m);
  const double mesh_seconds = since(clock);
  const MeshQuality q = measure_quality(m.mesh);
  end_stage_line();
  for (const std::string& w : mesh_warnings(m, q, mesh_job.options)) warnings.add(w);

  StagedOutput staged(out, "run");
  const std::string unit = length_unit_name(foam.convert_to_meters);  // the pictures' scale bars
  const std::filesystem::path dir = staged.dir();
  write_text_file(dir / "tessellation.json", tessellation_to_json(t));
  if (pictures != Pictures::none)
    write_tessellation_png(dir / "tessellation.png", t, tessellation_picture(t, tess_job.picture_width, unit));
  const int picture_width = pictures != Pictures::none ? mesh_job.picture_width : 0;
  const bool all_pictures = pictures == Pictures::all;
  write_mesh_files(dir, t, m, picture_width, all_pictures, unit);

  end_memory("mesh");
  clock = std::chrono::steady_clock::now();
  begin_memory();
  stage("exporting");
  const ExportMesh e = grain_export_mesh(t, m);
  if (!c.has("export.format") && m.mesh.triangles.size() > kBinaryCaseAboveCells) foam.binary = true;
  // The mixed load in case/; the periodic load cases each in their own case_NAME/.
  std::vector<std::string> case_dirs;
  PolyMesh pm;
  if (boundary == Boundary::mixed) {
    case_dirs.push_back("case");
    std::filesystem::create_directories(dir / "case");
    pm = write_foam_case(dir / "case", e, foam);
  } else {
    for (const LoadCase& lc : periodic_load_cases(e, foam)) {
      case_dirs.push_back(periodic_case_dir(lc));
      std::filesystem::create_directories(dir / case_dirs.back());
      pm = write_foam_case(dir / case_dirs.back(), e, load_case_options(foam, lc));
    }
  }
  const double export_seconds = since(clock);
  end_memory("export");
  write_text_file(dir / "config.ini", config_ini(c));

  Json phases = Json::array();
  for (std::size_t p = 0; p < t.phases.size(); ++p)
    phases.push_back({{"name", t.phases[p].name},
                      {"target_fraction", t.stats.phases[p].target_fraction},
                      {"achieved_fraction", t.stats.phases[p].achieved_fraction},
                      {"grains", t.stats.phases[p].grains}});
  Json report{{"config", c.source()},
              {"config_fingerprint", config_fingerprint(c)},
              {"seed", tess_job.seed},
              {"grains", t.stats.grains},
              {"phases", phases},
              {"statistics", descriptors_json(t)},
              {"mesh",
               {{"points", m.mesh.points.size()},
                {"cells", m.mesh.triangles.size()},
                {"q_min", q.q_min},
                {"q_mean", q.q_mean},
                {"min_angle_deg", q.min_angle_deg},
                {"max_non_orthogonality_deg", q.max_non_orthogonality_deg},
                {"cells_per_grain_mean", static_cast<double>(m.mesh.triangles.size()) / t.stats.grains},
                {"unconverged_regions", m.unconverged_regions}}},
              {"seconds",
               {{"tessellate", tessellate_seconds}, {"mesh", mesh_seconds}, {"export", export_seconds}}},
              {"memory_mib", memory},
              {"case", case_dirs.size() == 1 ? Json(case_dirs[0]) : Json(case_dirs)},
              {"case_format", foam.binary ? "binary" : "ascii"},
              {"solved", solve}};
  add_time_limit(report, tess_job.options.deadline);

  double solve_seconds = 0.0;
  if (solve) {
    clock = std::chrono::steady_clock::now();
    begin_memory(true);
    stage("solving with solidDisplacementFoam");
    std::vector<std::string> solve_warnings;
    try {
      Answer answer = boundary == Boundary::mixed
                          ? homogenise_mixed(dir, staged, t, m, e, pm, foam, tess_job.options.deadline, picture_width,
                                             all_pictures, solve_warnings)
                          : homogenise_periodic(dir, staged, t, m, e, pm, foam, tess_job.options.deadline,
                                                picture_width, all_pictures, solve_warnings);
      report["effective"] = std::move(answer.effective);
      report["effective"]["processes"] = foam.processes;
      report["stresses"] = std::move(answer.stresses);
    } catch (const SolveError& err) {
      // Kept for a look: the case with the solver's log, as OUT.failed.
      end_stage_line();
      report["failed"] = err.what();
      end_memory("solve");
      report["memory_mib"] = memory;
      report["peak_memory_mib"] = largest(memory);
      try {
        write_report(staged, report, warnings);
        staged.keep_as_failed();
      } catch (const IoError& io) {
        throw SolveError(std::string(err.what()) + " (but it could not be kept: " + io.what() + ")");
      }
      throw;
    }
    solve_seconds = since(clock);
    end_memory("solve");
    end_stage_line();
    for (const std::string& w : solve_warnings) warnings.add(w);
  }
  report["seconds"]["solve"] = solve_seconds;
  report["seconds"]["total"] = since(start);
  report["memory_mib"] = memory;
  report["peak_memory_mib"] = largest(memory);
  write_report(staged, report, warnings);
  staged.commit();
  end_stage_line();

  if (!summary) return;
  // What is there (the pictures are optional), directories marked.
  std::string written;
  for (const std::string& name : entry_names(out))
    written += (written.empty() ? "" : ", ") + name + (std::filesystem::is_directory(out / name) ? "/" : "");
  std::printf("grainmesh run: %d grains, %zu cells (q_min %.3f, q_mean %.3f), %.2f s\n  wrote %s/{%s}\n  each case's "
              "Allrun runs checkMesh and solidDisplacementFoam\n",
              t.stats.grains, m.mesh.triangles.size(), q.q_min, q.q_mean, since(start), out.string().c_str(),
              written.c_str());
  if (solve && boundary == Boundary::mixed) {
    const Json& eff = report["effective"];
    std::printf("  solved: effective modulus %.4g Pa", eff["modulus"].get<double>());
    if (eff.contains("reuss"))
      std::printf(" (Reuss %.4g, Voigt %.4g)", eff["reuss"].get<double>(), eff["voigt"].get<double>());
    std::printf(", %d corrections\n", eff["corrections"].get<int>());
  } else if (solve) {
    const Json& C = report["effective"]["stiffness"];
    std::printf("  solved: effective stiffness C11 %.4g, C22 %.4g, C12 %.4g, C66 %.4g Pa (%zu load cases, at most %d "
                "corrections)\n",
                C["C11"].get<double>(), C["C22"].get<double>(), C["C12"].get<double>(), C["C66"].get<double>(),
                report["effective"]["load_cases"].size(), report["effective"]["corrections"].get<int>());
    if (foam.delta_T != 0.0) {
      const Json& a = report["effective"]["thermal_expansion"];
      std::printf("  thermal: free expansion a11 %.4g, a22 %.4g 1/K; residual stresses in report.json (stresses.thermal)\n",
                  a["a11"].get<double>(), a["a22"].get<double>());
    }
  }
  if (!warnings.all().empty())
    std::printf("  %zu warning%s (stderr and report.json)\n", warnings.all().size(), warnings.all().size() > 1 ? "s" : "");
}

}  // namespace grainmesh
