// What a sweep's runs report, point by point, for its summary (sweep --collect): the plan
// as written (plan.json), each done run's report read (report_read.hpp: any schema) into
// the point's per-run answers, and the runs left out by why.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "pipelines/report.hpp"

namespace grainmesh {

// The periodic tensor's components and engineering constants, summarised when any run
// has them: (group in effective, name), of a 2D or a 3D cell.
using TensorQuantities = std::vector<std::pair<std::string, std::string>>;
const TensorQuantities& tensor_quantities(int dimensions);

// Mean, standard deviation and the half-width of the 95 % confidence interval of the mean.
std::array<double, 3> summary_stats(const std::vector<double>& v);

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

// DIR/plan.json read; throws IoError naming it when it is missing or not a sweep's plan.
CollectedPlan read_collected_plan(const std::filesystem::path& dir);

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

// The done runs of point p; the others listed in `left_out` by why.
PointRuns read_point_runs(const std::filesystem::path& dir, const CollectedPlan& plan, std::size_t p,
                          const std::string& x_phase, std::vector<std::string>& names, LeftOut& left_out);

}  // namespace grainmesh
