// `grainmesh sweep SWEEP.ini -o DIR [--jobs N] [--shard I/N] [--solve]`: the cartesian
// product of the [sweep] section's value lists, each point run `realisations` times with
// seeds derived from the base seed, the point's values and the realisation, in a
// directory named by them (sweep_plan.hpp); runs whose report is complete are skipped, so
// an interrupted or edited sweep resumes; runs no longer planned are kept in DIR/retired/.
// Every sweep ends by writing DIR/summary.csv (and its plots), one row per point with the
// mean, standard deviation and 95 % confidence interval over its realisations;
// `grainmesh sweep --collect DIR` writes them again.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "pipelines/config.hpp"
#include "pipelines/sweep_plan.hpp"

namespace grainmesh {

void run_sweep_command(const Config& config, const std::filesystem::path& dir, const SweepOptions& options);
// Writes DIR/summary.csv and its plots from the runs there. `left_out_warnings`: the runs
// missing, failed or stale are warnings on stderr (a sweep that has just run says which
// of its own failed, and leaves them out).
void collect_sweep(const std::filesystem::path& dir, bool left_out_warnings = true);

}  // namespace grainmesh
