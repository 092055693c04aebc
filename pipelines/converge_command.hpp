// `grainmesh converge CONFIG -o DIR [--levels K] [--start N]`: a mesh convergence study
// of the effective quantities. One tessellation (the config's seed), meshed at K
// densities (mesh.triangles_per_grain N, 2N, 4N, ...), each run and solved as `run
// --solve` would (DIR/tpg-N/); DIR/convergence.csv and convergence.png with the
// quantities per level, their Richardson limit and observed order, and the coarsest
// level within 0.1 % of the limit; DIR/report.json last.
#pragma once

#include <filesystem>

#include "pipelines/config.hpp"

namespace grainmesh {

struct ConvergeOptions {
  int levels = 5;   // at least 3 (Richardson needs three)
  int start = 25;   // triangles per grain of the coarsest level
};

// Throws ConfigError for fewer than 3 levels, a start below 4, or a config that fixes
// the element size (mesh.size or mesh.h, mesh.boundary_size, mesh.junction_size, phase.NAME.size),
// which would not follow the levels.
void run_converge_command(const Config& config, const std::filesystem::path& out, const ConvergeOptions& options);

}  // namespace grainmesh
