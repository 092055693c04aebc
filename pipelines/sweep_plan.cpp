#include "pipelines/sweep_plan.hpp"

#include <cstdint>
#include <cstdio>
#include <sstream>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/random.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/run_config.hpp"

namespace grainmesh {
namespace {

// The swept keys and their values, and the realisations, from the sweep.* keys.
void read_lists(const Config& c, SweepPlan& plan) {
  // The sweep's lists: every sweep.KEY except its own settings names a run key.
  const std::vector<std::string> run_keys = run_config_keys();
  for (const auto& [key, value] : c.entries()) {
    if (key.rfind("sweep.", 0) != 0) continue;
    const std::string name = key.substr(6);
    if (name == "realisations") {
      const long long k = c.integer(key, 1);
      if (k < 1 || k > 100000) c.fail(key, "must be between 1 and 100000");
      plan.realisations = static_cast<int>(k);
      continue;
    }
    const Config probe = Config::from_text("", c.source(), {name + "=x"});
    try {
      probe.check_keys(run_keys);
    } catch (const ConfigError&) {
      c.fail(key, "names no config key of a run ('" + name + "')");
    }
    std::vector<std::string> list;
    std::stringstream in(value);
    for (std::string item; std::getline(in, item, ',');)
      if (!trimmed(item).empty()) list.push_back(trimmed(item));
    if (list.empty()) c.fail(key, "gives no values");
    plan.keys.push_back(name);
    plan.values.push_back(list);
  }
  std::vector<std::string> known = run_keys;
  for (const char* k : {"sweep.*", "sweep.*.*", "sweep.*.*.*"}) known.push_back(k);
  c.check_keys(known);

}

// The runs, first key slowest, each point's realisations in order.
void make_runs(const Config& base, const SweepOptions& o, SweepPlan& plan) {
  const std::vector<std::string>& keys = plan.keys;
  const std::vector<std::vector<std::string>>& values = plan.values;
  const std::uint64_t base_seed = base.unsigned_integer("tessellation.seed", 1);
  for (const auto& v : values) plan.points *= v.size();
  for (std::size_t p = 0; p < plan.points; ++p) {
    Json point = Json::object();
    std::vector<std::string> overrides;
    std::size_t rest = p;
    for (std::size_t k = keys.size(); k-- > 0;) {
      const std::string& v = values[k][rest % values[k].size()];
      rest /= values[k].size();
      overrides.insert(overrides.begin(), keys[k] + "=" + v);
      point[keys[k]] = v;
    }
    plan.point_values.push_back(point);
    for (int r = 0; r < plan.realisations; ++r) {
      std::vector<std::string> o2 = overrides;
      // The same whichever shard runs it; 53 bits, so a JSON number holds it exactly.
      const std::uint64_t seed = derived_seed(base_seed, static_cast<std::uint64_t>(r), p) >> 11;
      o2.push_back("tessellation.seed=" + std::to_string(seed));
      if (!base.has("domain.depth")) o2.push_back("mesh.seed=" + std::to_string(seed));  // 3D meshes draw nothing
      // Runs side by side mesh on one thread each (the mesh is the same either way).
      if (o.jobs > 1 && !base.has("mesh.threads")) o2.push_back("mesh.threads=1");
      plan.runs.push_back({run_name(p, r), p, r, o2, {}});
    }
  }
}

}  // namespace

std::string run_name(std::size_t point, int realisation) {
  char name[64];
  std::snprintf(name, sizeof name, "p%03zu-r%02d", point, realisation);
  return name;
}

SweepPlan make_sweep_plan(const Config& c, const SweepOptions& o) {
  SweepPlan plan;
  read_lists(c, plan);
  const Config base = c.subset(run_config_keys());
  plan.dimensions = base.has("domain.depth") ? 3 : 2;
  make_runs(base, o, plan);
  const std::vector<std::string>& keys = plan.keys;
  plan.base_text = config_ini(base);
  for (SweepRun& r : plan.runs) {
    const Config run_config = Config::from_text(plan.base_text, c.source(), r.overrides);
    try {
      check_run_config(run_config);
    } catch (const ConfigError& e) {
      std::string point;
      for (std::size_t k = 0; k < keys.size(); ++k) point += (k ? ", " : "") + r.overrides[k];
      throw ConfigError(c.source() + ": the sweep's point " + point + ": " + e.what());
    }
    r.fingerprint = config_fingerprint(run_config);
  }

  return plan;
}

Json plan_json(const SweepPlan& plan, bool solve) {
  Json runs = Json::array();
  for (const SweepRun& r : plan.runs) runs.push_back({{"name", r.name}, {"fingerprint", r.fingerprint}});
  return Json{{"format", "grainmesh-sweep"}, {"keys", plan.keys},  {"points", plan.point_values},
              {"realisations", plan.realisations}, {"solve", solve}, {"dimensions", plan.dimensions}, {"runs", runs}};
}

Json read_json(const std::filesystem::path& file) {
  const std::string text = read_text_file(file);
  try {
    return Json::parse(text);
  } catch (const Json::exception& e) {
    throw IoError(file.string() + ": not valid JSON: " + e.what());
  }
}

// Where a run of the plan stands: its report (written last) is missing or unreadable, was
// made from another config than the plan now asks for (its fingerprint), lacks the
// solution a --solve sweep needs, or is done.
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

// The names a sweep directory holds: plan.json, logs/, summary.{csv,png}, one directory per
// run (pPPP-rRR), a failed run's pPPP-rRR.failed, and while they run, hidden staging
// directories and temporary files.
bool sweep_entry(const std::string& name) {
  if (name == "plan.json" || name == "logs" || name == "summary.csv" || name == "summary.png") return true;
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".tmp") == 0) return sweep_entry(name.substr(0, name.size() - 4));
  std::string run = name;
  if (!run.empty() && run[0] == '.') {  // .pPPP-rRR.partial-PID, .pPPP-rRR.old-PID
    const auto dot = run.find('.', 1);
    if (dot == std::string::npos) return false;
    run = run.substr(1, dot - 1);
  } else if (run.size() > 7 && run.compare(run.size() - 7, 7, ".failed") == 0) {
    run.resize(run.size() - 7);
  }
  unsigned p = 0, r = 0;
  char tail = 0;
  return std::sscanf(run.c_str(), "p%u-r%u%c", &p, &r, &tail) == 2 && run[0] == 'p';
}

// A sweep writes into DIR only when DIR is new, empty, or an earlier sweep's directory
// holding nothing else; never the current directory. Throws IoError naming why.
void check_sweep_dir(const std::filesystem::path& dir) {
  if (!occupied_directory(dir)) return;
  const std::string where = std::filesystem::absolute(dir).lexically_normal().string();
  bool ours = false;
  try {
    ours = read_json(dir / "plan.json").value("format", "") == "grainmesh-sweep";
  } catch (const IoError&) {
  }
  if (!ours) throw IoError(where + ": exists and is not a grainmesh sweep (no plan.json); refusing to write into it");
  for (const std::string& name : entry_names(dir))
    if (!sweep_entry(name))
      throw IoError(where + ": holds '" + name + "', which grainmesh sweep did not write; refusing to write into it");
}

}  // namespace grainmesh
