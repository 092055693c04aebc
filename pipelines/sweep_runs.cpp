#include "pipelines/sweep_runs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "common/errors.hpp"
#include "pipelines/report_read.hpp"
#include "pipelines/sweep_dir.hpp"

namespace grainmesh {

namespace {

// Student's t at 97.5 % for n - 1 degrees of freedom (n up to 31; 1.96 beyond).
constexpr double kT975[] = {0,     12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                            2.201, 2.179,  2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080,
                            2.074, 2.069,  2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};

// A periodic answer's columns beside its tensor: each quantity's error estimate,
// OpenFOAM's answer beside the finite elements' (solver fe, --solve) and the reference
// beside OpenFOAM's (solver openfoam), each with the errors against the other.
template <class Add>
void add_solver_columns(const Json& e, Add& add) {
  // A quantity set {stiffness {Cij}, bulk_modulus, shear_modulus} as columns PREFIX_...
  auto columns = [&](const std::string& prefix, const Json& q) {
    for (const auto& [c, value] : q["stiffness"].items()) add(prefix + c, value);
    for (const char* m : {"bulk_modulus", "shear_modulus"}) add(prefix + m, q[m]);
  };
  if (e.contains("error_estimate")) {
    const Json& x = e["error_estimate"];
    columns("error_estimate_", x);
    if (x.contains("thermal_expansion"))
      for (const auto& [c, value] : x["thermal_expansion"].items()) add("error_estimate_thermal_expansion_" + c, value);
  }
  if (e.contains("openfoam")) {
    columns("openfoam_", e["openfoam"]);
    columns("discretisation_error_", e["openfoam"]["discretisation_error"]);
  }
  if (e.contains("reference")) {
    columns("reference_", e["reference"]);
    columns("discretisation_error_", e["discretisation_error"]);
  }
}

// One done run's report into `pr`; `names` gets each extra column's name the first time.
void add_run(const Json& j, const std::string& x_phase, const TensorQuantities& tensor, PointRuns& pr,
             std::vector<std::string>& names) {
  auto add = [&](const std::string& name, const Json& value) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    if (value.is_number()) pr.extras[name].push_back(value.get<double>());
  };
  ++pr.found;
  pr.cells += j["mesh"]["cells"].get<double>();
  pr.q_min = std::min(pr.q_min, j["mesh"]["q_min"].get<double>());
  if (j.contains("plane_state")) pr.plane_state = j["plane_state"].get<std::string>();
  if (j.contains("warnings") && !j["warnings"].empty()) {
    ++pr.warned;
    for (const Json& w : j["warnings"])
      if (std::find(pr.warnings.begin(), pr.warnings.end(), w.get<std::string>()) == pr.warnings.end())
        pr.warnings.push_back(w.get<std::string>());
  }
  for (const Json& phase : j["phases"]) {
    if (!x_phase.empty() && phase["name"] == x_phase) pr.achieved.push_back(phase["achieved_fraction"].get<double>());
    add("achieved_fraction_" + phase["name"].get<std::string>(), phase["achieved_fraction"]);
  }
  if (j.contains("statistics"))
    for (const char* key : {"contiguity", "intercept_length", "mean_free_path"})
      if (j["statistics"].contains(key))
        for (const auto& [phase, value] : j["statistics"][key].items()) add(std::string(key) + "_" + phase, value);
  if (j.contains("stresses"))
    for (const auto& [load, phases] : j["stresses"].items()) {
      // The loaded component; both in-plane normal ones of the thermal residual.
      const bool component = load.size() == 2 && load.find_first_not_of("xyz") == std::string::npos;
      const std::vector<std::string> components = load == "thermal" ? std::vector<std::string>{"xx", "yy"}
                                                  : component       ? std::vector<std::string>{load}
                                                                    : std::vector<std::string>{"xx"};
      for (const auto& [phase, s] : phases.items()) {
        for (const std::string& component : components) add(load + "_" + phase + "_mean_" + component, s["mean"][component]);
        add(load + "_" + phase + "_von_mises_p99", s["von_mises"]["p99"]);
      }
    }
  if (!j.contains("effective")) return;
  const Json& e = j["effective"];
  if (e.contains("thermal_expansion")) {
    // A 2D run's in-plane components, a 3D run's six.
    for (const auto& [c, value] : e["thermal_expansion"].items()) add("thermal_expansion_" + c, value);
  }
  if (e.contains("stiffness")) {
    for (std::size_t q = 0; q < tensor.size(); ++q) pr.tensor[q].push_back(e[tensor[q].first][tensor[q].second].get<double>());
    // The moduli and the bounds they are judged by.
    add("bulk_modulus", e["bulk_modulus"]);
    add("shear_modulus", e["shear_modulus"]);
    add("voigt_C11", e["voigt"]["C11"]);
    add("reuss_C11", e["reuss"]["C11"]);
    if (e.contains("hashin_shtrikman"))
      for (const char* b : {"bulk_lower", "bulk_upper", "shear_lower", "shear_upper"}) add(std::string("hs_") + b, e["hashin_shtrikman"][b]);
    add_solver_columns(e, add);
    return;
  }
  pr.modulus.push_back(e["modulus"].get<double>());
  pr.voigt = e.value("voigt", NAN);
  pr.reuss = e.value("reuss", NAN);
  if (e.contains("hashin_shtrikman")) {
    pr.hs_lo = e["hashin_shtrikman"]["lower"].get<double>();
    pr.hs_hi = e["hashin_shtrikman"]["upper"].get<double>();
  }
}

}  // namespace

const TensorQuantities& tensor_quantities(int dimensions) {
  static const TensorQuantities two{
      {"stiffness", "C11"},  {"stiffness", "C22"},  {"stiffness", "C12"},    {"stiffness", "C66"},
      {"stiffness", "C16"},  {"stiffness", "C26"},  {"engineering", "E_x"},
      {"engineering", "E_y"}, {"engineering", "nu_xy"}, {"engineering", "nu_yx"}, {"engineering", "G_xy"},
      {"anisotropy", "universal"}};
  static const TensorQuantities three{
      {"stiffness", "C11"},   {"stiffness", "C22"},   {"stiffness", "C33"},   {"stiffness", "C12"},
      {"stiffness", "C13"},   {"stiffness", "C23"},   {"stiffness", "C44"},   {"stiffness", "C55"},
      {"stiffness", "C66"},   {"engineering", "E_x"}, {"engineering", "E_y"}, {"engineering", "E_z"},
      {"engineering", "G_xy"}, {"engineering", "nu_xy"}, {"anisotropy", "universal"}};
  return dimensions == 3 ? three : two;
}

std::array<double, 3> summary_stats(const std::vector<double>& v) {
  if (v.empty()) return {NAN, NAN, NAN};
  double mean = 0.0;
  for (double m : v) mean += m;
  mean /= static_cast<double>(v.size());
  if (v.size() < 2) return {mean, NAN, NAN};
  double ss = 0.0;
  for (double m : v) ss += (m - mean) * (m - mean);
  const double sd = std::sqrt(ss / static_cast<double>(v.size() - 1));
  const std::size_t dof = v.size() - 1;
  return {mean, sd, (dof <= 30 ? kT975[dof] : 1.96) * sd / std::sqrt(static_cast<double>(v.size()))};
}

CollectedPlan read_collected_plan(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::exists(dir / "plan.json", ec))
    throw IoError(dir.string() + ": not a grainmesh sweep's directory (no plan.json): give the directory a sweep wrote "
                                 "(grainmesh sweep SWEEP.ini -o DIR)");
  const Json plan = read_json(dir / "plan.json");
  CollectedPlan out;
  out.keys = plan.at("keys").get<std::vector<std::string>>();
  // Checked before the cast: nlohmann's get<int>() of 1e80 is undefined behaviour.
  const Json& count = plan.at("realisations");
  if (!count.is_number_integer() || count.get<std::int64_t>() < 1 || count.get<std::int64_t>() > 100000)
    throw IoError((dir / "plan.json").string() + ": realisations is " + count.dump() + ", not a count from 1 to 100000");
  out.realisations = static_cast<int>(count.get<std::int64_t>());
  const Json& listed = plan.contains("runs") ? plan["runs"] : Json();
  if (!listed.is_array() || (!listed.empty() && !listed.front().contains("point")))
    throw IoError((dir / "plan.json").string() + ": no list of runs by point (an older grainmesh wrote it); run the sweep again");
  for (const Json& r : listed)
    out.runs.push_back({r.at("name").get<std::string>(), r.at("fingerprint").get<std::string>(), r.at("point").get<std::size_t>()});
  out.solve = plan.value("solve", false);
  out.dimensions = plan.value("dimensions", 2);
  out.points = plan.at("points");
  return out;
}

PointRuns read_point_runs(const std::filesystem::path& dir, const CollectedPlan& plan, std::size_t p,
                          const std::string& x_phase, std::vector<std::string>& names, LeftOut& left_out) {
  PointRuns pr;
  const TensorQuantities& tensor = tensor_quantities(plan.dimensions);
  pr.tensor.resize(tensor.size());
  for (const CollectedRun& run : plan.runs) {
    if (run.point != p) continue;
    const std::string& name = run.name;
    const RunStatus status = run_status(dir / name, plan.solve, run.fingerprint);
    if (status != RunStatus::done) {
      std::error_code ec;
      (std::filesystem::exists(dir / (name + ".failed"), ec) ? left_out.failed
       : status == RunStatus::stale                          ? left_out.stale
                                                             : left_out.missing)
          .push_back(name);
      continue;
    }
    add_run(read_report(dir / name / "report.json"), x_phase, tensor, pr, names);
  }
  return pr;
}

}  // namespace grainmesh
