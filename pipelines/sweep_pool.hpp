// A sweep's runs as child processes, some at a time: each run's output in its log, its
// error as its exit code, progress on a terminal; an interrupted or killed sweep takes its
// runs with it.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "pipelines/sweep_plan.hpp"

namespace grainmesh {

// What the runs came to: each failed run's exit code, and the first to fail with what it
// said or how it ended.
struct PoolResult {
  std::map<std::string, int> failed;
  std::string first_failed, first_failure;
};

// Runs `todo`, o.jobs at a time, each a child process with its output in logs/NAME.log
// and its error as its exit code; progress on a terminal.
PoolResult run_pool(const std::vector<const SweepRun*>& todo, const SweepPlan& plan, const std::string& source,
                    const std::filesystem::path& dir, const SweepOptions& o);

}  // namespace grainmesh
