#include "pipelines/convergence_study.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/format.hpp"
#include "view/picture.hpp"

namespace grainmesh {

const char* per_grain_name(int dimensions) { return dimensions == 3 ? "tets_per_grain" : "triangles_per_grain"; }

namespace {

// The finest level's estimated error, relative, and its basis (Study::errors).
std::pair<double, const char*> finest_error(const std::vector<double>& f, const std::optional<double>& reference,
                                            const RichardsonEstimate& e) {
  const double finest = f.back();
  if (reference) return {*reference, "reference"};
  if (e.asymptotic) return {std::abs(finest - e.limit) / std::abs(e.limit), "richardson"};
  const auto [low, high] = std::minmax_element(f.begin(), f.end());
  return {kUnorderedErrorFactor * (*high - *low) / std::abs(finest), "range"};
}

}  // namespace

Study study_of(const Levels& l) {
  const std::vector<std::string>& names = l.names;
  const std::vector<std::vector<double>>& values = l.values;
  const std::vector<double>& tpg = l.tpg;
  Study st;
  Json& study = st.json;
  std::vector<RichardsonEstimate>& estimates = st.estimates;
  std::vector<std::optional<int>>& within = st.within;
  for (std::size_t i = 0; i < names.size(); ++i) {
    estimates.push_back(richardson(values[i], kLevelRatio));
    const auto [error, basis] = finest_error(values[i], l.reference_estimates[i].back(), estimates.back());
    st.errors.push_back(error);
    st.bases.push_back(basis);
    within.push_back(first_within(values[i], estimates.back().limit, kWithin));
    Json s{{"values", values[i]},
           {"limit", estimates.back().limit},
           {"error_estimate", error},
           {"error_basis", basis},
           {"asymptotic", estimates.back().asymptotic},
           {"settled", estimates.back().settled},
           {"order", estimates.back().order ? Json(*estimates.back().order) : Json(nullptr)},
           {"coarsest_within_0.1_percent",
            within.back() ? Json(static_cast<int>(tpg[static_cast<std::size_t>(*within.back())])) : Json(nullptr)}};
    study[names[i]] = s;
  }

  return st;
}

std::string convergence_csv(const Levels& l, const Study& st) {
  const std::vector<std::string>& names = l.names;
  const std::vector<std::vector<double>>& values = l.values;
  const std::vector<double>&cells = l.cells, &tpg = l.tpg, &seconds = l.seconds;
  const std::vector<RichardsonEstimate>& estimates = st.estimates;
  const std::vector<std::optional<int>>& within = st.within;
  std::string csv = std::string("level,") + per_grain_name(l.dimensions) + ",cells,seconds";
  for (const std::string& n : names) csv.append(",").append(n);
  csv += "\n";
  for (std::size_t k = 0; k < tpg.size(); ++k) {
    csv += std::to_string(k) + "," + to_text(tpg[k]) + "," + to_text(cells[k]) + "," + to_text(seconds[k], 4);
    for (const auto& v : values) csv.append(",").append(to_text(v[k], 10));
    csv += "\n";
  }
  auto row = [&](const std::string& label, auto cell) {
    csv += label + ",,,";
    for (std::size_t i = 0; i < names.size(); ++i) csv.append(",").append(cell(i));
    csv += "\n";
  };
  row("richardson_limit", [&](std::size_t i) { return to_text(estimates[i].limit, 10); });
  row("observed_order", [&](std::size_t i) { return estimates[i].order ? to_text(*estimates[i].order, 3) : std::string(); });
  row("error_estimate", [&](std::size_t i) { return to_text(st.errors[i], 3); });
  row("coarsest_within_0.1_percent",
      [&](std::size_t i) { return within[i] ? to_text(tpg[static_cast<std::size_t>(*within[i])]) : std::string(); });

  return csv;
}

void write_convergence_png(const std::filesystem::path& file, const Levels& l, const Study& st) {
  const std::vector<std::string>& names = l.names;
  const std::vector<std::vector<double>>& values = l.values;
  const std::vector<double>& cells = l.cells;
  const std::vector<RichardsonEstimate>& estimates = st.estimates;
  const bool mixed = names.front() == "modulus";
  Plot plot{.x_label = "cells",
            .y_label = mixed ? "modulus: deviation from the Richardson limit (%)" : "deviation from the Richardson limit (%)",
            .series = {}};
  for (std::size_t i = 0; i < names.size(); ++i) {
    const double limit = estimates[mixed ? 0 : i].limit;
    PlotSeries line{.name = names[i], .points = {}, .line = true, .colour = static_cast<int>(i)};
    for (std::size_t k = 0; k < cells.size(); ++k) line.points.push_back({cells[k], 100.0 * (values[i][k] / limit - 1.0)});
    PlotSeries dots = line;
    dots.name.clear();
    dots.line = false;
    plot.series.insert(plot.series.end(), {line, dots});
  }
  const int band_colour = 5;  // the plot palette's last: after every quantity's
  plot.series.push_back({.name = "+/- 0.1 %", .points = {{cells.front(), 0.1}, {cells.back(), 0.1}}, .line = true,
                         .colour = band_colour});
  plot.series.push_back({.name = "", .points = {{cells.front(), -0.1}, {cells.back(), -0.1}}, .line = true,
                         .colour = band_colour});
  write_plot_png(file, plot);

}

}  // namespace grainmesh
