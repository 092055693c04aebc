#include "pipelines/sweep_summary.hpp"

#include <cmath>
#include <cstdlib>

#include "common/format.hpp"
#include "view/picture.hpp"

namespace grainmesh {

namespace {

std::string num(double v) { return std::isnan(v) ? std::string() : to_text(v, 10); }

// A text field of a CSV file, quoted where it holds a comma, a quote or a line break.
std::string csv_text(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

}  // namespace

void SummaryPlot::add(const PointRuns& pr, const std::vector<std::string>& keys, const Json& point, std::size_t x_key) {
  c11 = c11 || pr.modulus.empty();
  add_values(pr, pr.modulus.empty() ? pr.tensor[0] : pr.modulus, keys, point, x_key);
}

void SummaryPlot::add_values(const PointRuns& pr, const std::vector<double>& plotted, const std::vector<std::string>& keys,
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

void SummaryPlot::write(const std::filesystem::path& file, const std::string& x_label) const {
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

}  // namespace grainmesh
