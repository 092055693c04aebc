#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "export/picture.hpp"
#include "pipelines/report.hpp"
#include "pipelines/sweep_command.hpp"
#include "pipelines/sweep_plan.hpp"

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

}  // namespace

void collect_sweep(const std::filesystem::path& dir) {
  const Json plan = read_json(dir / "plan.json");
  const auto keys = plan.at("keys").get<std::vector<std::string>>();
  // Checked before the cast: nlohmann's get<int>() of 1e80 is undefined behaviour.
  const Json& count = plan.at("realisations");
  if (!count.is_number_integer() || count.get<std::int64_t>() < 1 || count.get<std::int64_t>() > 100000)
    throw IoError((dir / "plan.json").string() + ": realisations is " + count.dump() + ", not a count from 1 to 100000");
  const int realisations = static_cast<int>(count.get<std::int64_t>());
  // Each run's fingerprint, by name: a run made from another config is not counted.
  std::map<std::string, std::string> fingerprint;
  const Json& listed = plan.contains("runs") ? plan["runs"] : Json();
  if (!listed.is_array())
    throw IoError((dir / "plan.json").string() + ": no list of runs (an older grainmesh wrote it); run the sweep again");
  for (const Json& r : listed) fingerprint[r.at("name").get<std::string>()] = r.at("fingerprint").get<std::string>();
  const bool solve = plan.value("solve", false);
  std::vector<std::string> missing, failed, stale;
  // Student's t at 97.5 % for n - 1 degrees of freedom (n up to 31; 1.96 beyond).
  static const double t975[] = {0,     12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                2.201, 2.179,  2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080,
                                2.074, 2.069,  2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  // The periodic tensor's components and engineering constants, summarised when any run
  // has them.
  static const std::vector<std::pair<std::string, std::string>> kTensor{
      {"stiffness", "C11"},  {"stiffness", "C22"},  {"stiffness", "C12"},    {"stiffness", "C21"},
      {"stiffness", "C66"},  {"stiffness", "C16"},  {"stiffness", "C26"},    {"engineering", "E_x"},
      {"engineering", "E_y"}, {"engineering", "nu_xy"}, {"engineering", "nu_yx"}, {"engineering", "G_xy"}};
  // Mean, standard deviation and the half-width of the 95 % confidence interval of the mean.
  auto stats = [&](const std::vector<double>& v) -> std::array<double, 3> {
    if (v.empty()) return {NAN, NAN, NAN};
    double mean = 0.0;
    for (double m : v) mean += m;
    mean /= static_cast<double>(v.size());
    if (v.size() < 2) return {mean, NAN, NAN};
    double ss = 0.0;
    for (double m : v) ss += (m - mean) * (m - mean);
    const double sd = std::sqrt(ss / static_cast<double>(v.size() - 1));
    const std::size_t dof = v.size() - 1;
    return {mean, sd, (dof <= 30 ? t975[dof] : 1.96) * sd / std::sqrt(static_cast<double>(v.size()))};
  };
  auto num = [](double v) { return std::isnan(v) ? std::string() : to_text(v, 10); };
  // The rows, and each row's tensor columns: written once it is known whether any run has them.
  std::vector<std::pair<std::string, std::string>> lines;
  // Per-run numbers summarised per point, by column name, the names in the order first
  // met: the WC-Co descriptors (e.g. contiguity_WC), the phase stresses (e.g.
  // mixed_WC_mean_xx, mixed_WC_von_mises_p99, thermal_Co_mean_yy) and the thermal
  // expansion (thermal_expansion_a11).
  std::vector<std::map<std::string, std::array<double, 3>>> extra_rows;
  std::vector<std::string> extra_names;
  bool any_tensor = false;
  std::size_t rows = 0;
  const auto& points = plan.at("points");
  // The plot: modulus (or, for periodic runs, C11) against the first fraction key (else
  // the first key), one series per value of the other keys, every realisation a point;
  // the bounds as lines.
  std::size_t x_key = 0;
  for (std::size_t k = keys.size(); k-- > 0;)
    if (!fraction_key_phase(keys[k]).empty()) x_key = k;
  std::map<std::string, std::vector<Vec2>> by_series;
  std::map<std::string, std::pair<std::vector<Vec2>, std::vector<double>>> means;  // per series: mean, CI95
  std::map<double, std::array<double, 5>> bounds;  // x -> summed voigt, reuss, HS lower, HS upper; count
  // Against the achieved fraction of the swept phase (each run's report) where the x key
  // is a phase's fraction; else against the key's value.
  const std::string x_phase = keys.empty() ? std::string() : fraction_key_phase(keys[x_key]);
  bool plotted_c11 = false;
  for (std::size_t p = 0; p < points.size(); ++p) {
    std::vector<double> modulus;
    std::vector<std::vector<double>> tensor(kTensor.size());
    std::map<std::string, std::vector<double>> extras;
    auto add = [&](const std::string& name, const Json& value) {
      if (std::find(extra_names.begin(), extra_names.end(), name) == extra_names.end()) extra_names.push_back(name);
      if (value.is_number()) extras[name].push_back(value.get<double>());
    };
    double voigt = NAN, reuss = NAN, hs_lo = NAN, hs_hi = NAN, cells = 0.0, q_min = 1.0;
    std::vector<double> achieved;  // the swept phase's achieved fraction, per run
    int found = 0;
    for (int r = 0; r < realisations; ++r) {
      const std::string name = run_name(p, r);
      const RunStatus status = run_status(dir / name, solve, fingerprint[name]);
      if (status != RunStatus::done) {
        std::error_code ec;
        (std::filesystem::exists(dir / (name + ".failed"), ec) ? failed
         : status == RunStatus::stale                          ? stale
                                                               : missing)
            .push_back(name);
        continue;
      }
      const Json j = read_json(dir / name / "report.json");
      ++found;
      cells += j["mesh"]["cells"].get<double>();
      q_min = std::min(q_min, j["mesh"]["q_min"].get<double>());
      for (const Json& phase : j["phases"])
        if (!x_phase.empty() && phase["name"] == x_phase) achieved.push_back(phase["achieved_fraction"].get<double>());
      if (j.contains("statistics"))
        for (const char* key : {"contiguity", "intercept_length", "mean_free_path"})
          for (const auto& [phase, value] : j["statistics"][key].items()) add(std::string(key) + "_" + phase, value);
      if (j.contains("stresses"))
        for (const auto& [load, phases] : j["stresses"].items()) {
          // The loaded component; both in-plane normal ones of the thermal residual.
          const std::vector<std::string> components =
              load == "thermal" ? std::vector<std::string>{"xx", "yy"}
                                : std::vector<std::string>{load == "yy" ? "yy" : load == "xy" ? "xy" : "xx"};
          for (const auto& [phase, s] : phases.items()) {
            for (const std::string& component : components)
              add(load + "_" + phase + "_mean_" + component, s["mean"][component]);
            add(load + "_" + phase + "_von_mises_p99", s["von_mises"]["p99"]);
          }
        }
      if (!j.contains("effective")) continue;
      const Json& e = j["effective"];
      if (e.contains("thermal_expansion"))
        for (const char* a : {"a11", "a22", "a12"}) add(std::string("thermal_expansion_") + a, e["thermal_expansion"][a]);
      if (e.contains("stiffness")) {
        any_tensor = true;
        for (std::size_t q = 0; q < kTensor.size(); ++q)
          tensor[q].push_back(e[kTensor[q].first][kTensor[q].second].get<double>());
        continue;
      }
      modulus.push_back(e["modulus"].get<double>());
      voigt = e.value("voigt", NAN);
      reuss = e.value("reuss", NAN);
      if (e.contains("hashin_shtrikman")) {
        hs_lo = e["hashin_shtrikman"]["lower"].get<double>();
        hs_hi = e["hashin_shtrikman"]["upper"].get<double>();
      }
    }
    if (found == 0) continue;
    const std::vector<double>& plotted = modulus.empty() ? tensor[0] : modulus;
    plotted_c11 = plotted_c11 || modulus.empty();
    if (!keys.empty() && !plotted.empty()) {
      std::string series;
      for (std::size_t k = 0; k < keys.size(); ++k)
        if (k != x_key) series += (series.empty() ? "" : ", ") + keys[k] + " " + points[p][keys[k]].get<std::string>();
      const double key_x = std::strtod(points[p][keys[x_key]].get<std::string>().c_str(), nullptr);
      const bool by_achieved = achieved.size() == plotted.size() && !achieved.empty();
      const double x = by_achieved ? stats(achieved)[0] : key_x;
      const std::string series_name = series.empty() ? "runs" : series;
      for (std::size_t k = 0; k < plotted.size(); ++k)
        by_series[series_name].push_back({by_achieved ? achieved[k] : key_x, plotted[k] / 1e9});
      const std::array<double, 3> ps = stats(plotted);
      means[series_name].first.push_back({x, ps[0] / 1e9});
      means[series_name].second.push_back(ps[2] / 1e9);
      if (!std::isnan(voigt)) {
        auto& b = bounds[x];
        b[0] += voigt / 1e9, b[1] += reuss / 1e9, b[2] += hs_lo / 1e9, b[3] += hs_hi / 1e9, b[4] += 1;
      }
    }
    const std::array<double, 3> s = stats(modulus);
    std::string line;
    for (const auto& k : keys) line += points[p][k].get<std::string>() + ",";
    line += std::to_string(found) + "," + num(s[0]) + "," + num(s[1]) + "," + num(s[2]) + "," + num(voigt) + "," +
            num(reuss) + "," + num(hs_lo) + "," + num(hs_hi) + "," + num(cells / found) + "," + num(q_min);
    std::string tensor_columns;
    for (const std::vector<double>& v : tensor) {
      const std::array<double, 3> ts = stats(v);
      for (const double v3 : ts) tensor_columns.append(",").append(num(v3));
    }
    lines.emplace_back(line, tensor_columns);
    extra_rows.emplace_back();
    for (const auto& [name, values] : extras) extra_rows.back()[name] = stats(values);
    ++rows;
  }
  std::string csv;
  for (const auto& k : keys) csv += k + ",";
  csv += "runs,modulus_mean,modulus_std,modulus_ci95,voigt,reuss,hs_lower,hs_upper,cells_mean,q_min";
  // Without periodic runs the tensor's columns are left out.
  if (any_tensor)
    for (const auto& [group, q] : kTensor) csv.append(",").append(q).append("_mean,").append(q).append("_std,").append(q).append("_ci95");
  for (const std::string& name : extra_names) csv += "," + name + "_mean," + name + "_std," + name + "_ci95";
  csv += "\n";
  for (std::size_t row = 0; row < lines.size(); ++row) {
    csv += lines[row].first + (any_tensor ? lines[row].second : std::string());
    for (const std::string& name : extra_names) {
      const auto found = extra_rows[row].find(name);
      const std::array<double, 3> v = found != extra_rows[row].end() ? found->second : std::array<double, 3>{NAN, NAN, NAN};
      for (const double x : v) csv.append(",").append(num(x));
    }
    csv += "\n";
  }
  // Said before the summary is written, so nobody mistakes a partial summary for a whole one.
  Warnings warnings;
  auto list = [](const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t k = 0; k < names.size() && k < 8; ++k) text += (k ? ", " : "") + names[k];
    return text + (names.size() > 8 ? ", ..." : "");
  };
  const std::size_t total = points.size() * static_cast<std::size_t>(realisations);
  if (!failed.empty())
    warnings.add("sweep --collect: " + std::to_string(failed.size()) + " of " + std::to_string(total) +
                 " runs failed and are left out: " + list(failed) + " (each kept as NAME.failed/, its log in " +
                 (dir / "logs").string() + ")");
  if (!stale.empty())
    warnings.add("sweep --collect: " + std::to_string(stale.size()) + " of " + std::to_string(total) +
                 " runs were made from another config than plan.json's and are left out: " + list(stale) +
                 " (run the sweep again)");
  if (!missing.empty())
    warnings.add("sweep --collect: " + std::to_string(missing.size()) + " of " + std::to_string(total) +
                 " runs are missing" + (solve ? " or unsolved" : "") + " and are left out: " + list(missing) +
                 " (not run yet or interrupted: run the sweep again)");
  write_text_file(dir / "summary.csv", csv);
  if (!by_series.empty()) {
    Plot plot{.x_label = x_phase.empty() ? keys[x_key] : "achieved fraction of " + x_phase,
              .y_label = std::string(plotted_c11 ? "effective C11" : "effective modulus") +
                         " (GPa): runs, their mean and 95 % CI",
              .series = {}};
    // Every realisation a small point; each point's mean with its 95 % CI as a bar.
    int colour = 0;
    for (auto& [name, pts] : by_series) {
      plot.series.push_back({"", pts, false, colour});
      const auto& [mean, ci] = means[name];
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
    write_plot_png(dir / "summary.png", plot);
  }
  std::printf("grainmesh sweep --collect: %zu points (%zu of %zu runs) in %s%s\n", rows,
              total - failed.size() - stale.size() - missing.size(), total, (dir / "summary.csv").string().c_str(),
              by_series.empty() ? "" : " and summary.png");
}

}  // namespace grainmesh
