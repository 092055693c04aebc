// A sweep's plan and directory: the runs of the cartesian product of the [sweep] lists
// (each point `realisations` times, seeds derived from the base seed, point and
// realisation), each run's config checked and fingerprinted; where a run stands in the
// directory; which names the directory may hold.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "pipelines/config.hpp"
#include "pipelines/report.hpp"
#include "pipelines/sweep_command.hpp"

namespace grainmesh {

// One run of the plan: its directory's name (pPPP-rRR), its point and realisation, the
// overrides of the base config that make it, and its resolved config's fingerprint (a
// changed sweep reruns what changed).
struct SweepRun {
  std::string name;
  std::size_t point;
  int realisation;
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
// dimensions, and every run's name and fingerprint.
Json plan_json(const SweepPlan& plan, bool solve);

// The name of the run of point `point`, realisation `realisation`: pPPP-rRR.
std::string run_name(std::size_t point, int realisation);

// Where a run of the plan stands: its report (written last) is missing or unreadable, was
// made from another config than the plan now asks for (its fingerprint), lacks the
// solution a --solve sweep needs, or is done.
enum class RunStatus { missing, stale, unsolved, done };
RunStatus run_status(const std::filesystem::path& run_dir, bool solve, const std::string& fingerprint);

// The names a sweep directory holds: plan.json, logs/, summary.{csv,png}, one directory per
// run (pPPP-rRR), a failed run's pPPP-rRR.failed, and while they run, hidden staging
// directories and temporary files.
bool sweep_entry(const std::string& name);

// A sweep writes into DIR only when DIR is new, empty, or an earlier sweep's directory
// holding nothing else; never the current directory. Throws IoError naming why.
void check_sweep_dir(const std::filesystem::path& dir);

// A JSON file read; IoError naming it when it cannot be read or parsed.
Json read_json(const std::filesystem::path& file);

}  // namespace grainmesh
