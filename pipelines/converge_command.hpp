// `grainmesh converge CONFIG -o DIR [--levels K] [--start N]`: a mesh convergence study
// of the effective quantities on nested levels. One tessellation (the config's seed),
// meshed once at N elements per grain and split k = 0 .. K-1 times (mesh.refine: the same
// geometry, each level half the element size of the one before), each run and solved as
// `run --solve` would (DIR/level-k/); DIR/convergence.csv and convergence.png with the
// quantities per level, their Richardson limit, observed order and the finest level's
// estimated error, and the coarsest level within 0.1 % of the limit; DIR/report.json last.
#pragma once

#include <filesystem>

#include "pipelines/config.hpp"

namespace grainmesh {

struct ConvergeOptions {
  int levels = 3;   // 3 to kMaxRefine + 1 (Richardson needs three)
  int start = 25;   // triangles (tetrahedra) per grain of the coarsest level, split once per level after it
};

// Throws ConfigError for fewer than 3 levels or more than kMaxRefine + 1, a start below 4,
// or a config that fixes the element size (mesh.size or mesh.h, mesh.boundary_size,
// mesh.junction_size, phase.NAME.size), which would not follow the levels, or sets
// mesh.refine.
void run_converge_command(const Config& config, const std::filesystem::path& out, const ConvergeOptions& options);

}  // namespace grainmesh
