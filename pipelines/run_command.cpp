#include "pipelines/run_command.hpp"

#include <unistd.h>

#include <cstdio>
#include <memory>
#include <variant>

#include "common/errors.hpp"
#include "common/memory.hpp"
#include "pipelines/cell_run.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report_json.hpp"

namespace grainmesh {

namespace {

// Each stage's seconds and peak resident memory (the solve's with the solver's
// processes), in MiB, by stage name.
class StageLog {
 public:
  void begin(bool with_children = false) {
    clock_ = Clock::now();
    meter_ = std::make_unique<StageMemory>(with_children);
  }
  // The stage's seconds, now; its memory once it ends.
  void time(const char* name) { seconds_[name] = since(clock_); }
  void end(const char* name) {
    memory_[name] = meter_->peak_mib();
    meter_.reset();
  }
  Json& seconds() { return seconds_; }
  const Json& memory() const { return memory_; }
  // The largest stage's.
  double peak_mib() const {
    double most = 0.0;
    for (const auto& [stage, value] : memory_.items()) most = std::max(most, value.get<double>());
    return most;
  }

 private:
  Clock::time_point clock_;
  std::unique_ptr<StageMemory> meter_;
  Json seconds_ = Json::object(), memory_ = Json::object();
};

// The stages' figures into report.json, at its end.
void add_stage_figures(Json& report, const StageLog& log, Json seconds) {
  report["seconds"] = std::move(seconds);
  report["memory_mib"] = log.memory();
  report["peak_memory_mib"] = log.peak_mib();
}

// The solve and its answer, also into `report` (effective, stresses), its warnings into
// `warnings`. A solve that fails keeps the staged output as OUT.failed, its report saying
// why, and throws.
RunAnswer solve_stage(CellRun& cell, const RunPlan& plan, StagedOutput& staged, const Deadline& deadline, StageLog& log,
                 Json& report, Warnings& warnings) {
  std::vector<std::string> solve_warnings;
  if (plan.solve) check_case_mesh(staged.dir(), deadline, report, warnings);
  try {
    RunAnswer answer = cell.solve(staged.dir(), staged, solve_warnings);
    std::visit(
        [&](const auto& a) {
          report["effective"] = effective_json(a, staged.dir());
          if (plan.solve) report["effective"]["processes"] = plan.foam.processes;
          if (!a.stresses.empty()) report["stresses"] = stresses_json(a);
        },
        answer);
    for (const std::string& w : solve_warnings) warnings.add(w);
    return answer;
  } catch (const SolveError& err) {
    // Kept for a look: the cases with the solver's logs, as OUT.failed.
    log.end("solve");
    add_stage_figures(report, log, log.seconds());
    report["failed"] = err.what();
    try {
      write_report(staged, report, warnings);
      staged.keep_as_failed();
    } catch (const IoError& io) {
      throw SolveError(std::string(err.what()) + " (but it could not be kept: " + io.what() + ")");
    }
    throw;
  }
}

}  // namespace

RunResult run_run_command(const Config& config, const std::filesystem::path& out, bool solve, bool quiet, bool summary) {
  const RunPlan plan = read_run_plan(config, solve);
  return run_plan(plan, out, quiet, summary);
}

RunResult run_plan(const RunPlan& plan, const std::filesystem::path& out, bool quiet, bool summary) {
  if (const auto* jobs = std::get_if<CellJobs<2>>(&plan.cell))
    return run_cell(*make_cell_run(plan, *jobs), plan, jobs->tessellate.options.deadline, out, quiet, summary);
  const auto& jobs = std::get<CellJobs<3>>(plan.cell);
  return run_cell(*make_cell_run(plan, jobs), plan, jobs.tessellate.options.deadline, out, quiet, summary);
}

RunResult run_cell(CellRun& cell, const RunPlan& plan, const Deadline& deadline, const std::filesystem::path& out, bool quiet,
              bool summary) {
  claim_output(out, "run");
  Warnings warnings;
  for (const std::string& w : plan.warnings) warnings.add(w);
  const auto start = Clock::now();
  const StageLine stage(!quiet && isatty(STDERR_FILENO) != 0, start);
  StageLog log;

  log.begin();
  stage.show("tessellating");
  cell.tessellate(warnings);
  log.time("tessellate");
  log.end("tessellate");
  stage.end();

  log.begin();
  cell.mesh(stage, warnings);
  log.time("mesh");
  stage.end();
  StagedOutput staged(out, "run");
  const std::filesystem::path dir = staged.dir();
  Json report{{"config", plan.source}, {"config_fingerprint", plan.fingerprint}};
  report.update(cell.write_geometry(dir, warnings));
  log.end("mesh");

  log.begin();
  stage.show("exporting");
  const std::vector<std::string> case_dirs = cell.write_cases(dir, warnings);
  log.time("export");
  log.end("export");
  write_text_file(dir / "config.ini", plan.resolved_ini);
  report["case"] = case_dirs.size() == 1 ? Json(case_dirs[0]) : Json(case_dirs);
  report.update(cell.case_fields());
  report["solved"] = plan.solve;
  add_time_limit(report, deadline);

  RunResult result;
  result.solved_cells = cell.solved_cells();
  if (plan.answers()) {
    log.begin(/*with_children=*/true);
    stage.show(cell.solving());
    result.answer = solve_stage(cell, plan, staged, deadline, log, report, warnings);
    log.time("solve");
    log.end("solve");
    stage.end();
  }
  if (!plan.keep_cases) {
    for (const std::string& name : case_dirs) std::filesystem::remove_all(dir / name);
    report["cases"] = "dropped once solved (output.cases = answers)";
  }
  result.seconds = since(start);
  log.seconds()["total"] = result.seconds;
  add_stage_figures(report, log, log.seconds());
  result.report = write_report(staged, report, warnings);
  staged.commit();
  stage.end();
  if (!summary) return result;
  cell.print_summary(out, {.tessellate = log.seconds()["tessellate"].get<double>(), .total = result.seconds},
                     result.answer ? &*result.answer : nullptr);
  if (!warnings.all().empty())
    std::printf("  %zu warning%s (stderr and report.json)\n", warnings.all().size(), warnings.all().size() > 1 ? "s" : "");
  return result;
}

}  // namespace grainmesh
