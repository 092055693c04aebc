// `grainmesh sweep SWEEP.ini -o DIR [--jobs N] [--shard I/N] [--solve]`: the cartesian
// product of the [sweep] section's value lists, each point run `realisations` times with
// seeds derived from the base seed, point and realisation; runs whose report is complete
// are skipped, so an interrupted sweep resumes. `grainmesh sweep --collect DIR` merges
// the reports into DIR/summary.csv, one row per point with the mean, standard deviation
// and 95 % confidence interval over its realisations.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "pipelines/config.hpp"

namespace grainmesh {

struct SweepOptions {
  int jobs = 1;            // runs at a time
  int shard = 1, shards = 1;  // run the runs whose index % shards == shard - 1
  bool solve = false;
};

void run_sweep_command(const Config& config, const std::filesystem::path& dir, const SweepOptions& options);
void collect_sweep(const std::filesystem::path& dir);

}  // namespace grainmesh
