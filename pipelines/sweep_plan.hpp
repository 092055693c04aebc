// A sweep's plan: the runs of the cartesian product of the [sweep] lists (each point
// `realisations` times), each run's config checked and fingerprinted. A run's directory
// name and its seed follow from its point's values and its realisation, never from where
// the values stand in the lists: editing a list re-runs no unchanged point.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "pipelines/config.hpp"
#include "pipelines/report.hpp"

namespace grainmesh {

// How a sweep runs: its runs at a time, its shard, whether it solves.
struct SweepOptions {
  int jobs = 1;            // runs at a time
  int shard = 1, shards = 1;  // run the runs whose index % shards == shard - 1
  bool solve = false;
};

// One run of the plan: its directory's name (run_name), its point (index into the plan's
// points, in list order) and realisation, its seed, the overrides of the base config that
// make it, and its resolved config's fingerprint (a changed sweep reruns what changed).
struct SweepRun {
  std::string name;
  std::size_t point;
  int realisation;
  std::uint64_t seed = 0;
  std::vector<std::string> overrides;
  std::string fingerprint;
};

struct SweepPlan {
  std::vector<std::string> keys;                  // the swept run keys, first slowest
  std::vector<std::vector<std::string>> values;   // each key's values
  int realisations = 1;
  std::size_t points = 1;
  Json point_values = Json::array();              // per point {KEY: value}
  std::string base_text;                          // the base config (config.ini form)
  std::vector<SweepRun> runs;
  int dimensions = 2;                             // 3 for a 3D base config (domain.depth)
};

// The plan of a sweep config: every sweep.KEY names a run key (or is sweep.realisations);
// every run's config checked before any is started (the mesh keys that need the
// tessellation excepted). Throws ConfigError naming the key or the point.
SweepPlan make_sweep_plan(const Config& config, const SweepOptions& options);

// plan.json: the format, keys, points, realisations, whether solved, the cell's
// dimensions, and every run's name, point, realisation, seed and fingerprint.
Json plan_json(const SweepPlan& plan, bool solve);

// The name of a run: its point's values key by key, each key by its last part (its last
// two, or all of it, where swept keys end alike), the values with any character but
// letters, digits and ".+-" made '_', then its realisation: "fraction=0.1,grains=30-r02";
// "r02" without swept keys. A name above 120 characters becomes "p" and a hash of the
// values instead.
std::string run_name(const std::vector<std::string>& keys, const std::vector<std::string>& values, int realisation);

}  // namespace grainmesh
