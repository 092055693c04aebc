// A sweep's directory: where a run of the plan stands in it, which names it may hold, and
// whether a sweep may write into it (sweep_plan.hpp makes the plan).
#pragma once

#include <filesystem>
#include <set>
#include <string>

#include "pipelines/sweep_plan.hpp"

namespace grainmesh {

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
