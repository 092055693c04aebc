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

// The levels' ratio of element sizes: nested refinement halves them.
inline constexpr double kLevelRatio = 2.0;

// The runs of the study's levels: each quantity's value per level, the levels' cells,
// triangles per grain and seconds, and their entries in the report.
struct Levels {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;  // [quantity][level]
  // [quantity][level]: the level's error estimate from the finite-element reference
  // solved beside it (homogenise.reference = fe: its error against it plus the
  // reference's own estimate), relative; none without it.
  std::vector<std::vector<std::optional<double>>> reference_estimates;
  std::vector<double> cells, tpg, seconds;
  int dimensions = 2;
  Json json = Json::array();
};

// The column of the levels' elements per grain in convergence.csv and the report.
const char* per_grain_name(int dimensions);

// Where a quantity's levels do not converge monotonically, the finest level's error is
// estimated as this many times their range (largest minus smallest): a rule, not a
// measurement (measured on the default cell's OpenFOAM levels: the error 0.76 to 2.5 times
// the range; docs/converge.md).
inline constexpr double kUnorderedErrorFactor = 3.0;

// Each quantity's Richardson estimate, the finest level's estimated error (relative: its
// estimate from the reference where that was solved beside it, else its distance from the
// limit, or where the last three levels do not converge monotonically
// kUnorderedErrorFactor times the levels' range) and the coarsest level within kWithin of
// its limit; `json` the report's study (`error_basis`: reference, richardson or range).
struct Study {
  std::vector<RichardsonEstimate> estimates;
  std::vector<double> errors;
  std::vector<std::string> bases;  // each error's: "reference", "richardson" or "range"
  std::vector<std::optional<int>> within;
  Json json = Json::object();
};
Study study_of(const Levels& l);

// convergence.csv: a row per level, then the limit, the order, the finest level's
// estimated error and the coarsest level within 0.1 % of the limit (in elements per grain).
std::string convergence_csv(const Levels& l, const Study& st);

// convergence.png: each quantity's distance from its limit, in per cent, over the cells;
// under mixed both estimators of the modulus from the traction value's limit, which the
// area average approaches from above.
void write_convergence_png(const std::filesystem::path& file, const Levels& l, const Study& st);

}  // namespace grainmesh
