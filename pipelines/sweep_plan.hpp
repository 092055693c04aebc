// A sweep's plan and directory: the runs of the cartesian product of the [sweep] lists
// (each point `realisations` times), each run's config checked and fingerprinted; where a
// run stands in the directory; which names the directory may hold. A run's directory
// name and its seed follow from its point's values and its realisation, never from where
// the values stand in the lists: editing a list re-runs no unchanged point.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <set>
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

// Where a run of the plan stands: its report (written last) is missing or unreadable, was
// made from another config than the plan now asks for (its fingerprint), lacks the
// solution a --solve sweep needs, or is done.
enum class RunStatus { missing, stale, unsolved, done };
RunStatus run_status(const std::filesystem::path& run_dir, bool solve, const std::string& fingerprint);

// The run an entry of a sweep directory belongs to: NAME for NAME, NAME.failed and the
// hidden .NAME.partial-PID and .NAME.old-PID; empty for any other.
std::string run_of_entry(const std::string& entry);

// The names a sweep directory holds besides its runs' (`runs`, by run_of_entry): plan.json,
// logs/, retired/ (runs no longer in the plan, kept), summary.csv, summary*.png, and while
// they are written their temporary files.
bool sweep_entry(const std::string& name, const std::set<std::string>& runs);

// The runs an earlier sweep in `dir` planned (its plan.json); empty when there is none.
std::set<std::string> planned_runs(const std::filesystem::path& dir);

// A sweep writes into DIR only when DIR is new, empty, or an earlier sweep's directory
// holding nothing but what the earlier or this plan names; never the current directory.
// Throws IoError naming why.
void check_sweep_dir(const std::filesystem::path& dir, const SweepPlan& plan);


}  // namespace grainmesh
