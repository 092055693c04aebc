// A mesh convergence study's levels and what they show (grainmesh converge): each
// quantity's Richardson limit and observed order, the coarsest level within kWithin of
// the limit, and the study's files, convergence.csv and convergence.png.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/richardson.hpp"
#include "pipelines/report.hpp"

namespace grainmesh {

// Relative tolerance of "converged" in the study.
inline constexpr double kWithin = 1e-3;

// The runs of the study's levels: each quantity's value per level, the levels' cells,
// triangles per grain and seconds, and their entries in the report.
struct Levels {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;  // [quantity][level]
  std::vector<double> cells, tpg, seconds;
  int dimensions = 2;
  Json json = Json::array();
};

// The column of the levels' elements per grain in convergence.csv and the report.
const char* per_grain_name(int dimensions);

// Each quantity's Richardson estimate and the coarsest level within kWithin of its limit;
// `json` the report's study.
struct Study {
  std::vector<RichardsonEstimate> estimates;
  std::vector<std::optional<int>> within;
  Json json = Json::object();
};
Study study_of(const Levels& l);

// convergence.csv: a row per level, then the limit, the order and the coarsest level
// within 0.1 % of the limit (in elements per grain).
std::string convergence_csv(const Levels& l, const Study& st);

// convergence.png: each quantity's distance from its limit, in per cent, over the cells;
// under mixed both estimators of the modulus from the traction value's limit, which the
// area average approaches from above.
void write_convergence_png(const std::filesystem::path& file, const Levels& l, const Study& st);

}  // namespace grainmesh
