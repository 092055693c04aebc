#include "pipelines/sweep_dir.hpp"

#include "common/errors.hpp"
#include "pipelines/directory.hpp"
#include "pipelines/report.hpp"

namespace grainmesh {

RunStatus run_status(const std::filesystem::path& run_dir, bool solve, const std::string& fingerprint) {
  std::error_code ec;
  if (!std::filesystem::exists(run_dir / "report.json", ec)) return RunStatus::missing;
  try {
    const Json r = read_json(run_dir / "report.json");
    if (r.value("command", "") != "run") return RunStatus::missing;
    if (r.value("config_fingerprint", "") != fingerprint) return RunStatus::stale;
    return solve && !r.contains("effective") ? RunStatus::unsolved : RunStatus::done;
  } catch (const IoError&) {
    return RunStatus::missing;
  }
}

std::string run_of_entry(const std::string& entry) {
  static const std::string failed = ".failed";
  if (!entry.empty() && entry[0] == '.') {  // .NAME.partial-PID, .NAME.old-PID (NAME may hold dots)
    for (const char* tag : {".partial-", ".old-"}) {
      const auto at = entry.rfind(tag);
      if (at != std::string::npos && at > 1) return entry.substr(1, at - 1);
    }
    return {};
  }
  if (entry.size() > failed.size() && entry.compare(entry.size() - failed.size(), failed.size(), failed) == 0)
    return entry.substr(0, entry.size() - failed.size());
  return entry;
}

bool sweep_entry(const std::string& name, const std::set<std::string>& runs) {
  if (name == "plan.json" || name == "logs" || name == "retired" || name == "summary.csv") return true;
  if (name.rfind("summary", 0) == 0 && name.size() > 4 && name.compare(name.size() - 4, 4, ".png") == 0) return true;
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".tmp") == 0) {  // FILE.tmp, FILE.PID.tmp
    std::string file = name.substr(0, name.size() - 4);
    const auto dot = file.rfind('.');
    if (dot != std::string::npos && file.find_first_not_of("0123456789", dot + 1) == std::string::npos) file.resize(dot);
    return sweep_entry(file, runs);
  }
  const std::string run = run_of_entry(name);
  return !run.empty() && runs.count(run) > 0;
}

std::set<std::string> planned_runs(const std::filesystem::path& dir) {
  std::set<std::string> names;
  try {
    const Json plan = read_json(dir / "plan.json");
    if (plan.contains("runs") && plan["runs"].is_array())
      for (const Json& r : plan["runs"])
        if (r.contains("name") && r["name"].is_string()) names.insert(r["name"].get<std::string>());
  } catch (const IoError&) {
  }
  return names;
}

void check_sweep_dir(const std::filesystem::path& dir, const SweepPlan& plan) {
  if (!occupied_directory(dir)) return;
  const std::string where = std::filesystem::absolute(dir).lexically_normal().string();
  bool ours = false;
  try {
    ours = read_json(dir / "plan.json").value("format", "") == "grainmesh-sweep";
  } catch (const IoError&) {
  }
  if (!ours) throw IoError(where + ": exists and is not a grainmesh sweep (no plan.json); refusing to write into it");
  std::set<std::string> runs = planned_runs(dir);
  for (const SweepRun& r : plan.runs) runs.insert(r.name);
  for (const std::string& name : entry_names(dir))
    if (!sweep_entry(name, runs))
      throw IoError(where + ": holds '" + name + "', which grainmesh sweep did not write; refusing to write into it");
}

}  // namespace grainmesh
