#include "pipelines/sweep_plan.hpp"

#include <cstdint>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/random.hpp"
#include "pipelines/run_config.hpp"
#include "pipelines/run_plan.hpp"

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

// FNV-1a, 64 bits.
std::uint64_t text_hash(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const unsigned char ch : text) h = (h ^ ch) * 0x100000001b3ull;
  return h;
}

// A point's identity: its key=value pairs in key order, whatever order the lists come in.
std::uint64_t point_hash(std::vector<std::string> pairs) {
  std::sort(pairs.begin(), pairs.end());
  std::string text;
  for (const std::string& p : pairs) text += p + "\n";
  return text_hash(text);
}

// The runs, first key slowest, each point's realisations in order.
void make_runs(const Config& base, const SweepOptions& o, SweepPlan& plan) {
  const std::vector<std::string>& keys = plan.keys;
  const std::vector<std::vector<std::string>>& values = plan.values;
  const std::uint64_t base_seed = base.unsigned_integer("tessellation.seed", 1);
  for (const auto& v : values) plan.points *= v.size();
  for (std::size_t p = 0; p < plan.points; ++p) {
    Json point = Json::object();
    std::vector<std::string> overrides, point_values(keys.size());
    std::size_t rest = p;
    for (std::size_t k = keys.size(); k-- > 0;) {
      const std::string& v = values[k][rest % values[k].size()];
      rest /= values[k].size();
      overrides.insert(overrides.begin(), keys[k] + "=" + v);
      point[keys[k]] = v;
      point_values[k] = v;
    }
    plan.point_values.push_back(point);
    const std::uint64_t identity = point_hash(overrides);
    for (int r = 0; r < plan.realisations; ++r) {
      std::vector<std::string> o2 = overrides;
      // From the point's values and the realisation alone: the same whichever shard runs it
      // and wherever the values stand in the lists; 53 bits, so a JSON number holds it exactly.
      const std::uint64_t seed = derived_seed(base_seed, static_cast<std::uint64_t>(r), identity) >> 11;
      o2.push_back("tessellation.seed=" + std::to_string(seed));
      if (cell_dimensions(base) == 2) o2.push_back("mesh.seed=" + std::to_string(seed));  // 3D meshes draw nothing
      // Runs side by side mesh on one thread each (the mesh is the same either way).
      if (o.jobs > 1 && !base.has("mesh.threads")) o2.push_back("mesh.threads=1");
      plan.runs.push_back({run_name(keys, point_values, r), p, r, seed, o2, {}});
    }
  }
}

}  // namespace

std::string run_name(const std::vector<std::string>& keys, const std::vector<std::string>& values, int realisation) {
  // Each key by its last part, or more of it where another swept key ends alike.
  auto tail = [](const std::string& key, int parts) {
    std::size_t at = key.size();
    for (int k = 0; k < parts && at != std::string::npos && at > 0; ++k) at = key.rfind('.', at - 1);
    return at == std::string::npos ? key : key.substr(at + 1);
  };
  std::string name;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    int parts = 1;
    for (bool clash = true; clash && parts < 8; ++parts) {
      clash = false;
      for (std::size_t j = 0; j < keys.size(); ++j)
        clash = clash || (j != k && tail(keys[j], parts) == tail(keys[k], parts));
      if (!clash) break;
    }
    std::string value = values[k];
    for (char& ch : value)
      if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '+' && ch != '-') ch = '_';
    name += (k ? "," : "") + tail(keys[k], parts) + "=" + value;
  }
  if (name.size() > 120) {
    std::vector<std::string> pairs;
    for (std::size_t k = 0; k < keys.size(); ++k) pairs.push_back(keys[k] + "=" + values[k]);
    char hash[24];
    std::snprintf(hash, sizeof hash, "p%016llx", static_cast<unsigned long long>(point_hash(pairs)));
    name = hash;
  }
  char r[16];
  std::snprintf(r, sizeof r, "r%02d", realisation);
  return name.empty() ? r : name + "-" + r;
}

SweepPlan make_sweep_plan(const Config& c, const SweepOptions& o) {
  SweepPlan plan;
  read_lists(c, plan);
  const Config base = c.subset(run_config_keys());
  plan.dimensions = cell_dimensions(base);
  make_runs(base, o, plan);
  const std::vector<std::string>& keys = plan.keys;
  plan.base_text = config_ini(base);
  for (SweepRun& r : plan.runs) {
    const Config run_config = Config::from_text(plan.base_text, c.source(), r.overrides);
    try {
      read_run_plan(run_config, o.solve);
    } catch (const ConfigError& e) {
      // The point's values are the sweep file's, not --set's: the message names the file.
      std::string point, why = e.what();
      for (std::size_t k = 0; k < keys.size(); ++k) point += (k ? ", " : "") + r.overrides[k];
      for (const std::string& given : std::vector<std::string>{"--set: ", c.source() + ": "})
        if (why.rfind(given, 0) == 0) why.erase(0, given.size());
      throw ConfigError(c.source() + ": the sweep's point " + point + ": " + why);
    }
    r.fingerprint = config_fingerprint(run_config);
  }

  return plan;
}

Json plan_json(const SweepPlan& plan, bool solve) {
  Json runs = Json::array();
  for (const SweepRun& r : plan.runs)
    runs.push_back({{"name", r.name}, {"point", r.point}, {"realisation", r.realisation}, {"seed", r.seed},
                    {"fingerprint", r.fingerprint}});
  return Json{{"format", "grainmesh-sweep"}, {"keys", plan.keys},  {"points", plan.point_values},
              {"realisations", plan.realisations}, {"solve", solve}, {"dimensions", plan.dimensions}, {"runs", runs}};
}

}  // namespace grainmesh
