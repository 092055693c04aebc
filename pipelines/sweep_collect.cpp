#include <cstdio>
#include <map>

#include "common/text_file.hpp"
#include "pipelines/directory.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/sweep_command.hpp"
#include "pipelines/sweep_runs.hpp"
#include "pipelines/sweep_summary.hpp"

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
