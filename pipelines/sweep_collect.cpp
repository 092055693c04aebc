#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "export/foam_options.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/report_read.hpp"
#include "pipelines/sweep_command.hpp"
#include "pipelines/sweep_plan.hpp"
#include "view/picture.hpp"

namespace grainmesh {

namespace {

// NAME of a key phase.NAME.fraction; empty for any other key.
std::string fraction_key_phase(const std::string& key) {
  const std::string head = "phase.", tail = ".fraction";
  if (key.size() <= head.size() + tail.size() || key.rfind(head, 0) != 0 ||
      key.compare(key.size() - tail.size(), tail.size(), tail) != 0)
    return {};
  return key.substr(head.size(), key.size() - head.size() - tail.size());
}

// Student's t at 97.5 % for n - 1 degrees of freedom (n up to 31; 1.96 beyond).
constexpr double kT975[] = {0,     12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                            2.201, 2.179,  2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080,
                            2.074, 2.069,  2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};

// The periodic tensor's components and engineering constants, summarised when any run
// has them: (group in effective, name), of a 2D or a 3D cell.
using TensorQuantities = std::vector<std::pair<std::string, std::string>>;
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

// Mean, standard deviation and the half-width of the 95 % confidence interval of the mean.
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

std::string num(double v) { return std::isnan(v) ? std::string() : to_text(v, 10); }

// plan.json as --collect reads it.
struct CollectedRun {
  std::string name, fingerprint;  // a run of another config than the fingerprint's is not counted
  std::size_t point = 0;
};
struct CollectedPlan {
  std::vector<std::string> keys;
  int realisations = 1;
  std::vector<CollectedRun> runs;
  bool solve = false;
  int dimensions = 2;
  Json points;
};

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

// The runs left out, by why.
struct LeftOut {
  std::vector<std::string> missing, failed, stale;
};

// What the done runs of one point report.
struct PointRuns {
  int found = 0;
  int warned = 0;                      // runs with warnings
  std::vector<std::string> warnings;   // theirs, each once
  std::string plane_state;             // a 2D run's (plane_strain, plane_stress)
  std::vector<double> modulus;
  std::vector<std::vector<double>> tensor;  // per tensor_quantities
  // Per-run numbers summarised per point, by column name: the WC-Co descriptors (e.g.
  // contiguity_WC), the phase stresses (e.g. mixed_WC_mean_xx, mixed_WC_von_mises_p99,
  // thermal_Co_mean_yy) and the thermal expansion (thermal_expansion_xx, ...).
  std::map<std::string, std::vector<double>> extras;
  double voigt = NAN, reuss = NAN, hs_lo = NAN, hs_hi = NAN, cells = 0.0, q_min = 1.0;
  std::vector<double> achieved;  // the swept phase's achieved fraction, per run
};

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
    for (const char* key : {"contiguity", "intercept_length", "mean_free_path"})  // 3D cells: contiguity alone
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

// The done runs of point p; the others listed in `left_out` by why.
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

// summary.png: modulus (or, for periodic runs, C11) against the x key, one series per
// value of the other keys, every realisation a point, each point's mean with its 95 % CI;
// the bounds as lines.
struct SummaryPlot {
  std::map<std::string, std::vector<Vec2>> by_series;
  std::map<std::string, std::pair<std::vector<Vec2>, std::vector<double>>> means;  // per series: mean, CI95
  std::map<double, std::array<double, 5>> bounds;  // x -> summed voigt, reuss, HS lower, HS upper; count
  bool c11 = false;
  std::string y_label;  // when not the modulus's
  double unit = 1e9;    // the values over this are plotted

  // The modulus (or C11) of the point's runs, with the bounds.
  void add(const PointRuns& pr, const std::vector<std::string>& keys, const Json& point, std::size_t x_key) {
    c11 = c11 || pr.modulus.empty();
    add_values(pr, pr.modulus.empty() ? pr.tensor[0] : pr.modulus, keys, point, x_key);
  }

  // Any per-run answer of the point's runs (`plotted`), without bounds unless they are the modulus's.
  void add_values(const PointRuns& pr, const std::vector<double>& plotted, const std::vector<std::string>& keys,
                  const Json& point, std::size_t x_key) {
    if (keys.empty() || plotted.empty()) return;
    std::string series;
    for (std::size_t k = 0; k < keys.size(); ++k)
      if (k != x_key) series += (series.empty() ? "" : ", ") + keys[k] + " " + point[keys[k]].get<std::string>();
    const double key_x = std::strtod(point[keys[x_key]].get<std::string>().c_str(), nullptr);
    const bool by_achieved = pr.achieved.size() == plotted.size() && !pr.achieved.empty();
    const double x = by_achieved ? summary_stats(pr.achieved)[0] : key_x;
    const std::string series_name = series.empty() ? "runs" : series;
    for (std::size_t k = 0; k < plotted.size(); ++k)
      by_series[series_name].push_back({by_achieved ? pr.achieved[k] : key_x, plotted[k] / unit});
    const std::array<double, 3> ps = summary_stats(plotted);
    means[series_name].first.push_back({x, ps[0] / unit});
    means[series_name].second.push_back(ps[2] / unit);
    if (!std::isnan(pr.voigt) && y_label.empty()) {
      auto& b = bounds[x];
      b[0] += pr.voigt / 1e9, b[1] += pr.reuss / 1e9, b[2] += pr.hs_lo / 1e9, b[3] += pr.hs_hi / 1e9, b[4] += 1;
    }
  }

  void write(const std::filesystem::path& file, const std::string& x_label) const {
    Plot plot{.x_label = x_label,
              .y_label = (y_label.empty() ? std::string(c11 ? "effective C11" : "effective modulus") + " (GPa)" : y_label) +
                         ": runs, their mean and 95 % CI",
              .series = {}};
    // Every realisation a small point; each point's mean with its 95 % CI as a bar.
    int colour = 0;
    for (const auto& [name, pts] : by_series) {
      plot.series.push_back({"", pts, false, colour});
      const auto& [mean, ci] = means.at(name);
      plot.series.push_back({name, mean, false, colour, ci});
      ++colour;
    }
    PlotSeries voigt_line{"Voigt", {}, true, 4}, reuss_line{"Reuss", {}, true, 5},
        hs_upper{"Hashin-Shtrikman", {}, true, 2}, hs_lower{"", {}, true, 2};
    for (const auto& [x, b] : bounds) {
      voigt_line.points.push_back({x, b[0] / b[4]});
      reuss_line.points.push_back({x, b[1] / b[4]});
      hs_lower.points.push_back({x, b[2] / b[4]});
      hs_upper.points.push_back({x, b[3] / b[4]});
    }
    if (!bounds.empty()) plot.series.insert(plot.series.end(), {voigt_line, reuss_line});
    if (!bounds.empty() && std::isfinite(hs_upper.points.front().y))
      plot.series.insert(plot.series.end(), {hs_upper, hs_lower});
    write_plot_png(file, plot);
  }
};

// One row of summary.csv: the point's values, its modulus columns, and (when any run has
// the tensor) the tensor's and then the extra columns.
struct CsvRow {
  std::string modulus, tensor, notes;
  std::map<std::string, std::array<double, 3>> extras;
};

// A text field of a CSV file, quoted where it holds a comma, a quote or a line break.
std::string csv_text(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

CsvRow csv_row(const PointRuns& pr, const std::vector<std::string>& keys, const Json& point) {
  CsvRow row;
  std::string warnings;
  for (const std::string& w : pr.warnings) warnings += (warnings.empty() ? "" : " | ") + w;
  row.notes = "," + pr.plane_state + "," + std::to_string(pr.warned) + "," + csv_text(warnings);
  const std::array<double, 3> s = summary_stats(pr.modulus);
  for (const auto& k : keys) row.modulus += point[k].get<std::string>() + ",";
  row.modulus += std::to_string(pr.found) + "," + num(s[0]) + "," + num(s[1]) + "," + num(s[2]) + "," + num(pr.voigt) +
                 "," + num(pr.reuss) + "," + num(pr.hs_lo) + "," + num(pr.hs_hi) + "," + num(pr.cells / pr.found) + "," +
                 num(pr.q_min);
  for (const std::vector<double>& v : pr.tensor)
    for (const double v3 : summary_stats(v)) row.tensor.append(",").append(num(v3));
  for (const auto& [name, values] : pr.extras) row.extras[name] = summary_stats(values);
  return row;
}

std::string summary_csv(const std::vector<CsvRow>& rows, const std::vector<std::string>& keys,
                        const std::vector<std::string>& extra_names, const TensorQuantities* tensor) {
  std::string csv;
  for (const auto& k : keys) csv += k + ",";
  csv += "runs,modulus_mean,modulus_std,modulus_ci95,voigt,reuss,hs_lower,hs_upper,cells_mean,q_min";
  // Without periodic runs the tensor's columns are left out.
  if (tensor)
    for (const auto& [group, q] : *tensor) {
      const std::string c = group == "anisotropy" ? q + "_anisotropy" : q;  // universal_anisotropy
      csv.append(",").append(c).append("_mean,").append(c).append("_std,").append(c).append("_ci95");
    }
  for (const std::string& name : extra_names) csv += "," + name + "_mean," + name + "_std," + name + "_ci95";
  csv += ",plane_state,runs_with_warnings,warnings\n";
  for (const CsvRow& row : rows) {
    csv += row.modulus + (tensor ? row.tensor : std::string());
    for (const std::string& name : extra_names) {
      const auto found = row.extras.find(name);
      const std::array<double, 3> v = found != row.extras.end() ? found->second : std::array<double, 3>{NAN, NAN, NAN};
      for (const double x : v) csv.append(",").append(num(x));
    }
    csv += row.notes + "\n";
  }
  return csv;
}

// The runs left out, as warnings; said before the summary is written, so nobody mistakes a
// partial summary for a whole one.
void warn_left_out(const LeftOut& left_out, std::size_t total, bool solve, const std::filesystem::path& dir) {
  Warnings warnings;
  auto list = [](const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t k = 0; k < names.size() && k < 8; ++k) text += (k ? ", " : "") + names[k];
    return text + (names.size() > 8 ? ", ..." : "");
  };
  if (!left_out.failed.empty())
    warnings.add("sweep --collect: " + std::to_string(left_out.failed.size()) + " of " + std::to_string(total) +
                 " runs failed and are left out: " + list(left_out.failed) + " (each kept as NAME.failed/, its log in " +
                 (dir / "logs").string() + ")");
  if (!left_out.stale.empty())
    warnings.add("sweep --collect: " + std::to_string(left_out.stale.size()) + " of " + std::to_string(total) +
                 " runs were made from another config than plan.json's and are left out: " + list(left_out.stale) +
                 " (run the sweep again)");
  if (!left_out.missing.empty())
    warnings.add("sweep --collect: " + std::to_string(left_out.missing.size()) + " of " + std::to_string(total) +
                 " runs are missing" + (solve ? " or unsolved" : "") + " and are left out: " + list(left_out.missing) +
                 " (not run yet or interrupted: run the sweep again)");
}

}  // namespace

void collect_sweep(const std::filesystem::path& dir, bool left_out_warnings) {
  const CollectedPlan plan = read_collected_plan(dir);
  const std::vector<std::string>& keys = plan.keys;
  // The plot's x: the first fraction key (else the first key); against the achieved
  // fraction of the swept phase (each run's report) where it is a phase's fraction.
  std::size_t x_key = 0;
  for (std::size_t k = keys.size(); k-- > 0;)
    if (!fraction_key_phase(keys[k]).empty()) x_key = k;
  const std::string x_phase = keys.empty() ? std::string() : fraction_key_phase(keys[x_key]);
  LeftOut left_out;
  std::vector<std::string> extra_names;  // in the order first met
  std::vector<CsvRow> rows;
  SummaryPlot plot;
  // A plot per further answer a sweep is run for: the moduli, the expansion, the phases'
  // residual stresses (summary_NAME.png).
  std::map<std::string, SummaryPlot> answers;
  auto answer_plot = [&](const std::string& name) -> std::pair<std::string, double> {
    if (name == "bulk_modulus") return {"effective bulk modulus K (GPa)", 1e9};
    if (name == "shear_modulus") return {"effective shear modulus G (GPa)", 1e9};
    if (name == "thermal_expansion_xx") return {"free thermal expansion, xx (1e-6 / K)", 1e-6};
    if (name.rfind("thermal_", 0) == 0 && name.size() > 8 && name.compare(name.size() - 8, 8, "_mean_xx") == 0)
      return {"residual stress, " + name.substr(8, name.size() - 16) + " mean xx (MPa)", 1e6};
    return {};
  };
  bool any_tensor = false;
  for (std::size_t p = 0; p < plan.points.size(); ++p) {
    const PointRuns pr = read_point_runs(dir, plan, p, x_phase, extra_names, left_out);
    if (pr.found == 0) continue;
    any_tensor = any_tensor || !pr.tensor[0].empty();
    plot.add(pr, keys, plan.points[p], x_key);
    for (const auto& [name, values] : pr.extras) {
      const auto [label, unit] = answer_plot(name);
      if (label.empty()) continue;
      SummaryPlot& a = answers[name];
      a.y_label = label;
      a.unit = unit;
      a.add_values(pr, values, keys, plan.points[p], x_key);
    }
    rows.push_back(csv_row(pr, keys, plan.points[p]));
  }
  const std::size_t total = plan.points.size() * static_cast<std::size_t>(plan.realisations);
  if (left_out_warnings) warn_left_out(left_out, total, plan.solve, dir);
  write_text_file(dir / "summary.csv",
                  summary_csv(rows, keys, extra_names, any_tensor ? &tensor_quantities(plan.dimensions) : nullptr));
  std::error_code ec;
  for (const std::string& name : entry_names(dir))  // answers no longer swept leave no picture behind
    if (name.rfind("summary_", 0) == 0 && name.size() > 4 && name.compare(name.size() - 4, 4, ".png") == 0)
      std::filesystem::remove(dir / name, ec);
  const std::string x_label = x_phase.empty() ? (keys.empty() ? std::string() : keys[x_key]) : "achieved fraction of " + x_phase;
  if (!plot.by_series.empty()) plot.write(dir / "summary.png", x_label);
  for (const auto& [name, a] : answers)
    if (!a.by_series.empty()) a.write(dir / ("summary_" + name + ".png"), x_label);
  std::printf("grainmesh sweep --collect: %zu points (%zu of %zu runs) in %s%s\n", rows.size(),
              total - left_out.failed.size() - left_out.stale.size() - left_out.missing.size(), total,
              (dir / "summary.csv").string().c_str(), plot.by_series.empty() ? "" : " and summary.png");
}

}  // namespace grainmesh
