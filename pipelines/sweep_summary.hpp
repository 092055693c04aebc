// A sweep's summary from its points' runs (sweep_runs.hpp): summary.csv, one row per point
// with the mean, standard deviation and 95 % confidence interval over its realisations,
// and the plots of the modulus (or C11) and of further answers against the swept key.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/geometry.hpp"
#include "pipelines/report.hpp"
#include "pipelines/sweep_runs.hpp"

namespace grainmesh {

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
  void add(const PointRuns& pr, const std::vector<std::string>& keys, const Json& point, std::size_t x_key);
  // Any per-run answer of the point's runs (`plotted`), without bounds unless they are the modulus's.
  void add_values(const PointRuns& pr, const std::vector<double>& plotted, const std::vector<std::string>& keys,
                  const Json& point, std::size_t x_key);
  void write(const std::filesystem::path& file, const std::string& x_label) const;
};

// One row of summary.csv: the point's values, its modulus columns, and (when any run has
// the tensor) the tensor's and then the extra columns.
struct CsvRow {
  std::string modulus, tensor, notes;
  std::map<std::string, std::array<double, 3>> extras;
};

// The row of point `point` (its values of `keys`) from its runs.
CsvRow csv_row(const PointRuns& pr, const std::vector<std::string>& keys, const Json& point);

// summary.csv: a header, then the rows; the tensor's columns when `tensor` is given (any
// run periodic), then the extra columns in the order of `extra_names`.
std::string summary_csv(const std::vector<CsvRow>& rows, const std::vector<std::string>& keys,
                        const std::vector<std::string>& extra_names, const TensorQuantities* tensor);

}  // namespace grainmesh
