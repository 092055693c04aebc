// `grainmesh run [CONFIG] -o OUT`: tessellate, mesh and export in one process, from one
// config (or the embedded default, data/default.ini), on a plane or a solid cell alike.
// Writes OUT/tessellation.json, the tessellation's and the mesh's files and pictures, the
// OpenFOAM cases (the mixed load's case/, or the periodic load cases' case_NAME/),
// config.ini (the resolved config, which repeats the run exactly) and report.json, last;
// with --solve the cases are solved and homogenised too (solve_cell.hpp).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>

#include "pipelines/config.hpp"
#include "pipelines/report.hpp"
#include "pipelines/run_plan.hpp"
#include "pipelines/solve_cell.hpp"

namespace grainmesh {

// What a run made: report.json as written, the answer when solved, the cells the cases
// were solved on and the run's seconds.
struct RunResult {
  Json report;
  std::optional<RunAnswer> answer;
  std::size_t solved_cells = 0;
  double seconds = 0.0;
};

// Reads the run's plan from `config` (read_run_plan: every key checked before
// any work) and runs it. With `solve`, also runs solidDisplacementFoam on the cases and
// homogenises (report.json "effective"); a run that does not converge fails.
// A terminal shows the stage and the meshing's progress on stderr unless `quiet`; the
// summary goes to stdout when `summary`.
RunResult run_run_command(const Config& config, const std::filesystem::path& out, bool solve = false, bool quiet = false,
                     bool summary = true);

// Runs a plan on its cell (a plane or a solid one: cell_run.hpp).
RunResult run_plan(const RunPlan& plan, const std::filesystem::path& out, bool quiet = false, bool summary = true);

class CellRun;
// The one run driver of plane and solid cells: `cell`'s stages in order, timed, their
// output staged and committed with report.json last; `deadline` the run's time limit.
RunResult run_cell(CellRun& cell, const RunPlan& plan, const Deadline& deadline, const std::filesystem::path& out, bool quiet,
              bool summary);

}  // namespace grainmesh
