#include "pipelines/sweep_command.hpp"

#include <cstdio>
#include <map>
#include <set>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "pipelines/directory.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/report_read.hpp"
#include "pipelines/sweep_dir.hpp"
#include "pipelines/sweep_pool.hpp"

namespace grainmesh {

namespace {

// This shard's runs to do, how many of them are done but of another config, and the
// runs no longer planned that were moved to retired/ or back from it.
struct ShardWork {
  std::vector<const SweepRun*> todo;
  std::size_t changed = 0;
  std::vector<std::string> retired, restored;
};

ShardWork shard_work(const SweepPlan& plan, const std::filesystem::path& dir, const SweepOptions& o) {
  // This shard's runs that are not done, or were made from another config. What an
  // interrupted or changed sweep left of them — a run directory without a complete report
  // or of an old config, a failed run's directory, the staging directory of a killed run —
  // is removed: the sweep owns them (other shards' runs, which may be running, are not
  // touched). A run the plan no longer has (a list was shortened) is finished work and is
  // kept: moved to retired/, and back should the plan name it again.
  ShardWork work;
  std::set<std::string> mine, planned;
  const std::vector<SweepRun>& runs = plan.runs;
  std::error_code ec;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    planned.insert(runs[i].name);
    if (static_cast<int>(i % static_cast<std::size_t>(o.shards)) != o.shard - 1) continue;
    const std::filesystem::path kept = dir / "retired" / runs[i].name;
    if (!std::filesystem::exists(dir / runs[i].name, ec) && std::filesystem::exists(kept / "report.json", ec)) {
      std::filesystem::rename(kept, dir / runs[i].name, ec);
      if (!ec) work.restored.push_back(runs[i].name);
    }
    const RunStatus status = run_status(dir / runs[i].name, o.solve, runs[i].fingerprint);
    if (status == RunStatus::done) continue;
    work.changed += status == RunStatus::stale ? 1 : 0;
    work.todo.push_back(&runs[i]);
    mine.insert(runs[i].name);
  }
  for (const std::string& name : entry_names(dir)) {
    if (sweep_entry(name, {})) continue;  // the sweep's own files
    const std::string run = run_of_entry(name);
    if (run.empty()) continue;
    if (mine.count(run)) {
      std::filesystem::remove_all(dir / name, ec);
    } else if (!planned.count(run)) {
      if (name[0] == '.') {  // a killed run's staging: nothing finished in it
        std::filesystem::remove_all(dir / name, ec);
        continue;
      }
      std::filesystem::create_directories(dir / "retired", ec);
      std::filesystem::remove_all(dir / "retired" / name, ec);  // an older copy of the same run
      std::filesystem::rename(dir / name, dir / "retired" / name, ec);
      if (!ec) work.retired.push_back(name);
    }
  }
  return work;
}

// The warnings of the runs just made, on stderr: one line per run that has any (its first
// and how many), ten at most; the rest counted. Every run's are in its report.json and,
// per point, in summary.csv.
void warn_run_warnings(const std::vector<const SweepRun*>& runs, const std::filesystem::path& dir) {
  int shown = 0, more = 0;
  for (const SweepRun* r : runs) {
    std::vector<std::string> warnings;
    try {
      const Json report = read_report(dir / r->name / "report.json");
      if (report.contains("warnings")) warnings = report["warnings"].get<std::vector<std::string>>();
    } catch (const std::exception&) {
      continue;  // a failed run: said below
    }
    if (warnings.empty()) continue;
    if (shown == 10) {
      ++more;
      continue;
    }
    ++shown;
    std::fprintf(stderr, "grainmesh: warning: sweep: %s: %s%s\n", r->name.c_str(), warnings.front().c_str(),
                 warnings.size() > 1 ? (" (and " + std::to_string(warnings.size() - 1) + " more)").c_str() : "");
  }
  if (more > 0)
    std::fprintf(stderr, "grainmesh: warning: sweep: %d more runs have warnings (their report.json; summary.csv)\n", more);
}

}  // namespace

void run_sweep_command(const Config& c, const std::filesystem::path& dir, const SweepOptions& o) {
  const SweepPlan plan = make_sweep_plan(c, o);
  check_sweep_dir(dir, plan);
  set_interrupt_message("the runs that finished are kept in " + dir.string() + "; run the sweep again to finish it");
  std::error_code ec;
  std::filesystem::create_directories(dir / "logs", ec);
  if (ec) throw IoError(dir.string() + ": cannot create the sweep's directory: " + ec.message());
  write_json(dir / "plan.json", plan_json(plan, o.solve));
  const ShardWork work = shard_work(plan, dir, o);
  const std::vector<const SweepRun*>& todo = work.todo;
  const PoolResult result = run_pool(todo, plan, c.source(), dir, o);
  const std::map<std::string, int>& failed = result.failed;
  std::printf("grainmesh sweep: %zu points x %d realisations = %zu runs; this shard (%d/%d) ran %zu (%zu of them "
              "again, their config changed), %zu were done already\n  in %s (plan.json, one directory per run, logs/)\n",
              plan.points, plan.realisations, plan.runs.size(), o.shard, o.shards, todo.size(), work.changed,
              (plan.runs.size() + o.shards - o.shard) / o.shards - todo.size(), dir.string().c_str());
  if (!work.retired.empty())
    std::printf("  %zu run%s no longer in the plan kept in %s\n", work.retired.size(), work.retired.size() > 1 ? "s" : "",
                (dir / "retired").string().c_str());
  if (!work.restored.empty())
    std::printf("  %zu run%s planned again taken back from retired/\n", work.restored.size(),
                work.restored.size() > 1 ? "s" : "");
  warn_run_warnings(todo, dir);
  // The summary always matches the runs there are: rewritten whenever they change.
  collect_sweep(dir, failed.empty());
  if (!failed.empty()) {
    // The runs that failed, and what the first to fail said (with its exit code).
    std::string names;
    for (const auto& [name, code] : failed)
      if (names.size() < 80) names += (names.empty() ? "" : ", ") + name;
    if (names.size() >= 80) names += ", ...";
    const std::string why = failed.size() == 1 ? names + ": " + result.first_failure
                                               : names + "; " + result.first_failed + " first: " + result.first_failure;
    throw_error(failed.at(result.first_failed), "sweep: " + std::to_string(failed.size()) + " of " +
                                             std::to_string(todo.size()) + " runs failed (" + why +
                                             "); their logs are in " + (dir / "logs").string() + " (run the sweep again to retry them)");
  }
}

}  // namespace grainmesh
