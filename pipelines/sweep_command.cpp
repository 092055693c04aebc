#include "pipelines/sweep_command.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "export/picture.hpp"
#include "pipelines/output_dir.hpp"
#include "common/process.hpp"
#include "common/random.hpp"
#include "pipelines/report.hpp"
#include "pipelines/run_command.hpp"

namespace grainmesh {

namespace {

std::string trimmed(std::string s) {
  s.erase(0, s.find_first_not_of(" \t"));
  s.erase(s.find_last_not_of(" \t") + 1);
  return s;
}

// Why a run ended as it did (its wait status): its log's error line, or its last line,
// or the signal that ended it.
std::string run_failure(const std::filesystem::path& log, int status) {
  std::ifstream in(log);
  std::string last;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(kErrorPrefix, 0) == 0) return line.substr(kErrorPrefix.size());
    if (!trimmed(line).empty()) last = trimmed(line);
  }
  if (WIFSIGNALED(status)) return "ended by signal " + std::to_string(WTERMSIG(status)) + (last.empty() ? "" : " after \"" + last + "\"");
  return last.empty() ? "exit code " + std::to_string(WEXITSTATUS(status)) : last;
}

std::string run_name(std::size_t point, int realisation) {
  char name[64];
  std::snprintf(name, sizeof name, "p%03zu-r%02d", point, realisation);
  return name;
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
enum class RunStatus { missing, stale, unsolved, done };
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

}  // namespace

void run_sweep_command(const Config& c, const std::filesystem::path& dir, const SweepOptions& o) {
  // The sweep's lists: every sweep.KEY except its own settings names a run key.
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> values;
  const std::vector<std::string> run_keys = run_config_keys();
  int realisations = 1;
  for (const auto& [key, value] : c.entries()) {
    if (key.rfind("sweep.", 0) != 0) continue;
    const std::string name = key.substr(6);
    if (name == "realisations") {
      const long long k = c.integer(key, 1);
      if (k < 1 || k > 100000) c.fail(key, "must be between 1 and 100000");
      realisations = static_cast<int>(k);
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
    keys.push_back(name);
    values.push_back(list);
  }
  std::vector<std::string> known = run_keys;
  for (const char* k : {"sweep.*", "sweep.*.*", "sweep.*.*.*"}) known.push_back(k);
  c.check_keys(known);
  const Config base = c.subset(run_keys);
  const std::uint64_t base_seed = base.unsigned_integer("tessellation.seed", 1);

  // The points, first key slowest; each realisation a run.
  std::size_t points = 1;
  for (const auto& v : values) points *= v.size();
  struct Run {
    std::string name;
    std::size_t point;
    int realisation;
    std::vector<std::string> overrides;
    std::string fingerprint;  // of its resolved config: a changed sweep reruns what changed
  };
  std::vector<Run> runs;
  Json plan_points = Json::array();
  for (std::size_t p = 0; p < points; ++p) {
    Json point = Json::object();
    std::vector<std::string> overrides;
    std::size_t rest = p;
    for (std::size_t k = keys.size(); k-- > 0;) {
      const std::string& v = values[k][rest % values[k].size()];
      rest /= values[k].size();
      overrides.insert(overrides.begin(), keys[k] + "=" + v);
      point[keys[k]] = v;
    }
    plan_points.push_back(point);
    for (int r = 0; r < realisations; ++r) {
      std::vector<std::string> o2 = overrides;
      // The same whichever shard runs it; 53 bits, so a JSON number holds it exactly.
      const std::uint64_t seed = derived_seed(base_seed, static_cast<std::uint64_t>(r), p) >> 11;
      o2.push_back("tessellation.seed=" + std::to_string(seed));
      o2.push_back("mesh.seed=" + std::to_string(seed));
      // Runs side by side mesh on one thread each (the mesh is the same either way).
      if (o.jobs > 1 && !base.has("mesh.threads")) o2.push_back("mesh.threads=1");
      runs.push_back({run_name(p, r), p, r, o2, {}});
    }
  }
  // Every run's config is checked before any is started (the mesh keys that need the
  // tessellation excepted).
  const std::string base_text = config_ini(base);
  Json plan_runs = Json::array();
  for (Run& r : runs) {
    const Config run_config = Config::from_text(base_text, c.source(), r.overrides);
    try {
      check_run_config(run_config);
    } catch (const ConfigError& e) {
      std::string point;
      for (std::size_t k = 0; k < keys.size(); ++k) point += (k ? ", " : "") + r.overrides[k];
      throw ConfigError(c.source() + ": the sweep's point " + point + ": " + e.what());
    }
    r.fingerprint = config_fingerprint(run_config);
    plan_runs.push_back({{"name", r.name}, {"fingerprint", r.fingerprint}});
  }

  check_sweep_dir(dir);
  std::error_code ec;
  std::filesystem::create_directories(dir / "logs", ec);
  if (ec) throw IoError(dir.string() + ": cannot create the sweep's directory: " + ec.message());
  write_json(dir / "plan.json", Json{{"format", "grainmesh-sweep"},
                                     {"keys", keys},
                                     {"points", plan_points},
                                     {"realisations", realisations},
                                     {"solve", o.solve},
                                     {"runs", plan_runs}});

  // This shard's runs that are not done, or were made from another config. What an
  // interrupted or changed sweep left of them — a run directory without a complete report
  // or of an old config, a failed run's directory, the staging directory of a killed run —
  // is removed: the sweep owns them (other shards' runs, which may be running, are not
  // touched). So are runs the plan no longer has (a list was shortened).
  std::vector<const Run*> todo;
  std::set<std::string> mine, planned;
  std::size_t changed = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    planned.insert(runs[i].name);
    if (static_cast<int>(i % static_cast<std::size_t>(o.shards)) != o.shard - 1) continue;
    const RunStatus status = run_status(dir / runs[i].name, o.solve, runs[i].fingerprint);
    if (status == RunStatus::done) continue;
    changed += status == RunStatus::stale ? 1 : 0;
    todo.push_back(&runs[i]);
    mine.insert(runs[i].name);
  }
  for (const std::string& name : entry_names(dir)) {
    // NAME, NAME.failed, .NAME.partial-PID, .NAME.old-PID
    std::string run = name[0] == '.' ? name.substr(1, name.find('.', 1) - 1) : name.substr(0, name.find('.'));
    if (run == name && !sweep_entry(name)) continue;
    if (run[0] != 'p' || !sweep_entry(run)) continue;
    if (mine.count(run) || !planned.count(run)) std::filesystem::remove_all(dir / name, ec);
  }
  const bool terminal = isatty(STDERR_FILENO) != 0;
  const auto start = std::chrono::steady_clock::now();
  std::size_t done = 0, next = 0;
  std::map<std::string, int> failed;  // run -> its exit code
  std::string first_failed, first_failure;  // the first run to fail, and what it said or how it ended
  std::map<pid_t, const Run*> running;
  auto progress = [&] {
    if (!terminal) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double left = done > 0 ? elapsed / static_cast<double>(done) * static_cast<double>(todo.size() - done) : 0.0;
    std::fprintf(stderr, "\rgrainmesh sweep: %zu / %zu runs, %.0f s elapsed, ~%.0f s left   ", done, todo.size(),
                 elapsed, left);
    std::fflush(stderr);
  };
  std::fflush(stdout);
  while (next < todo.size() || !running.empty()) {
    while (next < todo.size() && static_cast<int>(running.size()) < o.jobs) {
      const Run* r = todo[next++];
      const pid_t parent = getpid();
      const pid_t pid = fork();
      if (pid < 0) throw IoError("sweep: cannot start a run (fork failed)");
      if (pid == 0) {
        // A killed sweep takes its runs with it: none finishes behind a resumed sweep's back.
        die_with_parent(parent);
        // The run: its output to its log, its errors as its exit code.
        if (!std::freopen((dir / "logs" / (r->name + ".log")).c_str(), "w", stdout)) _exit(4);
        dup2(STDOUT_FILENO, STDERR_FILENO);
        int code = 0;
        try {
          run_run_command(Config::from_text(base_text, c.source(), r->overrides), dir / r->name, o.solve, true);
        } catch (const std::exception& e) {
          std::printf("%s%s\n", kErrorPrefix.data(), e.what());
          code = exit_code_of(e);
        }
        std::fflush(stdout);
        _exit(code);
      }
      running[pid] = r;
    }
    progress();
    int status = 0;
    const pid_t pid = wait(&status);
    if (pid < 0) break;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      const std::string& name = running[pid]->name;
      failed[name] = WIFEXITED(status) ? WEXITSTATUS(status) : kExitInternal;
      if (first_failed.empty()) {
        first_failed = name;
        first_failure = run_failure(dir / "logs" / (name + ".log"), status);
      }
    }
    running.erase(pid);
    ++done;
  }
  progress();
  if (terminal) std::fprintf(stderr, "\n");
  std::printf("grainmesh sweep: %zu points x %d realisations = %zu runs; this shard (%d/%d) ran %zu (%zu of them "
              "again, their config changed), %zu were done already\n  in %s (plan.json, one directory per run, logs/)\n",
              points, realisations, runs.size(), o.shard, o.shards, todo.size(), changed,
              (runs.size() + o.shards - o.shard) / o.shards - todo.size(), dir.string().c_str());
  if (!failed.empty()) {
    // The runs that failed, and what the first to fail said (with its exit code).
    std::string names;
    for (const auto& [name, code] : failed)
      if (names.size() < 80) names += (names.empty() ? "" : ", ") + name;
    if (names.size() >= 80) names += ", ...";
    const std::string why = failed.size() == 1 ? names + ": " + first_failure
                                               : names + "; " + first_failed + " first: " + first_failure;
    throw_error(failed.at(first_failed), "sweep: " + std::to_string(failed.size()) + " of " +
                                             std::to_string(todo.size()) + " runs failed (" + why +
                                             "); their logs are in " + (dir / "logs").string() + " (run the sweep again to retry them)");
  }
}

namespace {

// NAME of a key phase.NAME.fraction; empty for any other key.
std::string fraction_key_phase(const std::string& key) {
  const std::string head = "phase.", tail = ".fraction";
  if (key.size() <= head.size() + tail.size() || key.rfind(head, 0) != 0 ||
      key.compare(key.size() - tail.size(), tail.size(), tail) != 0)
    return {};
  return key.substr(head.size(), key.size() - head.size() - tail.size());
}

}  // namespace

void collect_sweep(const std::filesystem::path& dir) {
  const Json plan = read_json(dir / "plan.json");
  const auto keys = plan.at("keys").get<std::vector<std::string>>();
  // Checked before the cast: nlohmann's get<int>() of 1e80 is undefined behaviour.
  const Json& count = plan.at("realisations");
  if (!count.is_number_integer() || count.get<std::int64_t>() < 1 || count.get<std::int64_t>() > 100000)
    throw IoError((dir / "plan.json").string() + ": realisations is " + count.dump() + ", not a count from 1 to 100000");
  const int realisations = static_cast<int>(count.get<std::int64_t>());
  // Each run's fingerprint, by name: a run made from another config is not counted.
  std::map<std::string, std::string> fingerprint;
  const Json& listed = plan.contains("runs") ? plan["runs"] : Json();
  if (!listed.is_array())
    throw IoError((dir / "plan.json").string() + ": no list of runs (an older grainmesh wrote it); run the sweep again");
  for (const Json& r : listed) fingerprint[r.at("name").get<std::string>()] = r.at("fingerprint").get<std::string>();
  const bool solve = plan.value("solve", false);
  std::vector<std::string> missing, failed, stale;
  // Student's t at 97.5 % for n - 1 degrees of freedom (n up to 31; 1.96 beyond).
  static const double t975[] = {0,     12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                2.201, 2.179,  2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080,
                                2.074, 2.069,  2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  // The periodic tensor's components and engineering constants, summarised when any run
  // has them.
  static const std::vector<std::pair<std::string, std::string>> kTensor{
      {"stiffness", "C11"},  {"stiffness", "C22"},  {"stiffness", "C12"},    {"stiffness", "C21"},
      {"stiffness", "C66"},  {"stiffness", "C16"},  {"stiffness", "C26"},    {"engineering", "E_x"},
      {"engineering", "E_y"}, {"engineering", "nu_xy"}, {"engineering", "nu_yx"}, {"engineering", "G_xy"}};
  // Mean, standard deviation and the half-width of the 95 % confidence interval of the mean.
  auto stats = [&](const std::vector<double>& v) -> std::array<double, 3> {
    if (v.empty()) return {NAN, NAN, NAN};
    double mean = 0.0;
    for (double m : v) mean += m;
    mean /= static_cast<double>(v.size());
    if (v.size() < 2) return {mean, NAN, NAN};
    double ss = 0.0;
    for (double m : v) ss += (m - mean) * (m - mean);
    const double sd = std::sqrt(ss / static_cast<double>(v.size() - 1));
    const std::size_t dof = v.size() - 1;
    return {mean, sd, (dof <= 30 ? t975[dof] : 1.96) * sd / std::sqrt(static_cast<double>(v.size()))};
  };
  auto num = [](double v) { return std::isnan(v) ? std::string() : to_text(v, 10); };
  // The rows, and each row's tensor columns: written once it is known whether any run has them.
  std::vector<std::pair<std::string, std::string>> lines;
  // Per-run numbers summarised per point, by column name, the names in the order first
  // met: the WC-Co descriptors (e.g. contiguity_WC), the phase stresses (e.g.
  // mixed_WC_mean_xx, mixed_WC_von_mises_p99, thermal_Co_mean_yy) and the thermal
  // expansion (thermal_expansion_a11).
  std::vector<std::map<std::string, std::array<double, 3>>> extra_rows;
  std::vector<std::string> extra_names;
  bool any_tensor = false;
  std::size_t rows = 0;
  const auto& points = plan.at("points");
  // The plot: modulus (or, for periodic runs, C11) against the first fraction key (else
  // the first key), one series per value of the other keys, every realisation a point;
  // the bounds as lines.
  std::size_t x_key = 0;
  for (std::size_t k = keys.size(); k-- > 0;)
    if (!fraction_key_phase(keys[k]).empty()) x_key = k;
  std::map<std::string, std::vector<Vec2>> by_series;
  std::map<std::string, std::pair<std::vector<Vec2>, std::vector<double>>> means;  // per series: mean, CI95
  std::map<double, std::array<double, 5>> bounds;  // x -> summed voigt, reuss, HS lower, HS upper; count
  // Against the achieved fraction of the swept phase (each run's report) where the x key
  // is a phase's fraction; else against the key's value.
  const std::string x_phase = keys.empty() ? std::string() : fraction_key_phase(keys[x_key]);
  bool plotted_c11 = false;
  for (std::size_t p = 0; p < points.size(); ++p) {
    std::vector<double> modulus;
    std::vector<std::vector<double>> tensor(kTensor.size());
    std::map<std::string, std::vector<double>> extras;
    auto add = [&](const std::string& name, const Json& value) {
      if (std::find(extra_names.begin(), extra_names.end(), name) == extra_names.end()) extra_names.push_back(name);
      if (value.is_number()) extras[name].push_back(value.get<double>());
    };
    double voigt = NAN, reuss = NAN, hs_lo = NAN, hs_hi = NAN, cells = 0.0, q_min = 1.0;
    std::vector<double> achieved;  // the swept phase's achieved fraction, per run
    int found = 0;
    for (int r = 0; r < realisations; ++r) {
      const std::string name = run_name(p, r);
      const RunStatus status = run_status(dir / name, solve, fingerprint[name]);
      if (status != RunStatus::done) {
        std::error_code ec;
        (std::filesystem::exists(dir / (name + ".failed"), ec) ? failed
         : status == RunStatus::stale                          ? stale
                                                               : missing)
            .push_back(name);
        continue;
      }
      const Json j = read_json(dir / name / "report.json");
      ++found;
      cells += j["mesh"]["cells"].get<double>();
      q_min = std::min(q_min, j["mesh"]["q_min"].get<double>());
      for (const Json& phase : j["phases"])
        if (!x_phase.empty() && phase["name"] == x_phase) achieved.push_back(phase["achieved_fraction"].get<double>());
      if (j.contains("statistics"))
        for (const char* key : {"contiguity", "intercept_length", "mean_free_path"})
          for (const auto& [phase, value] : j["statistics"][key].items()) add(std::string(key) + "_" + phase, value);
      if (j.contains("stresses"))
        for (const auto& [load, phases] : j["stresses"].items()) {
          // The loaded component; both in-plane normal ones of the thermal residual.
          const std::vector<std::string> components =
              load == "thermal" ? std::vector<std::string>{"xx", "yy"}
                                : std::vector<std::string>{load == "yy" ? "yy" : load == "xy" ? "xy" : "xx"};
          for (const auto& [phase, s] : phases.items()) {
            for (const std::string& component : components)
              add(load + "_" + phase + "_mean_" + component, s["mean"][component]);
            add(load + "_" + phase + "_von_mises_p99", s["von_mises"]["p99"]);
          }
        }
      if (!j.contains("effective")) continue;
      const Json& e = j["effective"];
      if (e.contains("thermal_expansion"))
        for (const char* a : {"a11", "a22", "a12"}) add(std::string("thermal_expansion_") + a, e["thermal_expansion"][a]);
      if (e.contains("stiffness")) {
        any_tensor = true;
        for (std::size_t q = 0; q < kTensor.size(); ++q)
          tensor[q].push_back(e[kTensor[q].first][kTensor[q].second].get<double>());
        continue;
      }
      modulus.push_back(e["modulus"].get<double>());
      voigt = e.value("voigt", NAN);
      reuss = e.value("reuss", NAN);
      if (e.contains("hashin_shtrikman")) {
        hs_lo = e["hashin_shtrikman"]["lower"].get<double>();
        hs_hi = e["hashin_shtrikman"]["upper"].get<double>();
      }
    }
    if (found == 0) continue;
    const std::vector<double>& plotted = modulus.empty() ? tensor[0] : modulus;
    plotted_c11 = plotted_c11 || modulus.empty();
    if (!keys.empty() && !plotted.empty()) {
      std::string series;
      for (std::size_t k = 0; k < keys.size(); ++k)
        if (k != x_key) series += (series.empty() ? "" : ", ") + keys[k] + " " + points[p][keys[k]].get<std::string>();
      const double key_x = std::strtod(points[p][keys[x_key]].get<std::string>().c_str(), nullptr);
      const bool by_achieved = achieved.size() == plotted.size() && !achieved.empty();
      const double x = by_achieved ? stats(achieved)[0] : key_x;
      const std::string series_name = series.empty() ? "runs" : series;
      for (std::size_t k = 0; k < plotted.size(); ++k)
        by_series[series_name].push_back({by_achieved ? achieved[k] : key_x, plotted[k] / 1e9});
      const std::array<double, 3> ps = stats(plotted);
      means[series_name].first.push_back({x, ps[0] / 1e9});
      means[series_name].second.push_back(ps[2] / 1e9);
      if (!std::isnan(voigt)) {
        auto& b = bounds[x];
        b[0] += voigt / 1e9, b[1] += reuss / 1e9, b[2] += hs_lo / 1e9, b[3] += hs_hi / 1e9, b[4] += 1;
      }
    }
    const std::array<double, 3> s = stats(modulus);
    std::string line;
    for (const auto& k : keys) line += points[p][k].get<std::string>() + ",";
    line += std::to_string(found) + "," + num(s[0]) + "," + num(s[1]) + "," + num(s[2]) + "," + num(voigt) + "," +
            num(reuss) + "," + num(hs_lo) + "," + num(hs_hi) + "," + num(cells / found) + "," + num(q_min);
    std::string tensor_columns;
    for (const std::vector<double>& v : tensor) {
      const std::array<double, 3> ts = stats(v);
      for (const double v3 : ts) tensor_columns.append(",").append(num(v3));
    }
    lines.emplace_back(line, tensor_columns);
    extra_rows.emplace_back();
    for (const auto& [name, values] : extras) extra_rows.back()[name] = stats(values);
    ++rows;
  }
  std::string csv;
  for (const auto& k : keys) csv += k + ",";
  csv += "runs,modulus_mean,modulus_std,modulus_ci95,voigt,reuss,hs_lower,hs_upper,cells_mean,q_min";
  // Without periodic runs the tensor's columns are left out.
  if (any_tensor)
    for (const auto& [group, q] : kTensor) csv.append(",").append(q).append("_mean,").append(q).append("_std,").append(q).append("_ci95");
  for (const std::string& name : extra_names) csv += "," + name + "_mean," + name + "_std," + name + "_ci95";
  csv += "\n";
  for (std::size_t row = 0; row < lines.size(); ++row) {
    csv += lines[row].first + (any_tensor ? lines[row].second : std::string());
    for (const std::string& name : extra_names) {
      const auto found = extra_rows[row].find(name);
      const std::array<double, 3> v = found != extra_rows[row].end() ? found->second : std::array<double, 3>{NAN, NAN, NAN};
      for (const double x : v) csv.append(",").append(num(x));
    }
    csv += "\n";
  }
  // Said before the summary is written, so nobody mistakes a partial summary for a whole one.
  Warnings warnings;
  auto list = [](const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t k = 0; k < names.size() && k < 8; ++k) text += (k ? ", " : "") + names[k];
    return text + (names.size() > 8 ? ", ..." : "");
  };
  const std::size_t total = points.size() * static_cast<std::size_t>(realisations);
  if (!failed.empty())
    warnings.add("sweep --collect: " + std::to_string(failed.size()) + " of " + std::to_string(total) +
                 " runs failed and are left out: " + list(failed) + " (each kept as NAME.failed/, its log in " +
                 (dir / "logs").string() + ")");
  if (!stale.empty())
    warnings.add("sweep --collect: " + std::to_string(stale.size()) + " of " + std::to_string(total) +
                 " runs were made from another config than plan.json's and are left out: " + list(stale) +
                 " (run the sweep again)");
  if (!missing.empty())
    warnings.add("sweep --collect: " + std::to_string(missing.size()) + " of " + std::to_string(total) +
                 " runs are missing" + (solve ? " or unsolved" : "") + " and are left out: " + list(missing) +
                 " (not run yet or interrupted: run the sweep again)");
  write_text_file(dir / "summary.csv", csv);
  if (!by_series.empty()) {
    Plot plot{.x_label = x_phase.empty() ? keys[x_key] : "achieved fraction of " + x_phase,
              .y_label = std::string(plotted_c11 ? "effective C11" : "effective modulus") +
                         " (GPa): runs, their mean and 95 % CI",
              .series = {}};
    // Every realisation a small point; each point's mean with its 95 % CI as a bar.
    int colour = 0;
    for (auto& [name, pts] : by_series) {
      plot.series.push_back({"", pts, false, colour});
      const auto& [mean, ci] = means[name];
      plot.series.push_back({name, mean, false, colour, ci});
      ++colour;
    }
    PlotSeries voigt_line{"Voigt", {}, true, 4}, reuss_line{"Reuss", {}, true, 5},
        hs_upper{"Hashin-Shtrikman", {}, true, 2}, hs_lower{"", {}, true, 2};
    for (const auto& [x, b] : bounds) {
      voigt_line.points.push_back({x, b[0] / b[4]});
      reuss_line.points.push_back({x, b[1] / b[4]});
      hs_lower.points.push_back({x, b[2] / b[4]});
      hs_upper.points.push_back({x, b[3] / b[4]});
    }
    if (!bounds.empty()) plot.series.insert(plot.series.end(), {voigt_line, reuss_line});
    if (!bounds.empty() && std::isfinite(hs_upper.points.front().y))
      plot.series.insert(plot.series.end(), {hs_upper, hs_lower});
    write_plot_png(dir / "summary.png", plot);
  }
  std::printf("grainmesh sweep --collect: %zu points (%zu of %zu runs) in %s%s\n", rows,
              total - failed.size() - stale.size() - missing.size(), total, (dir / "summary.csv").string().c_str(),
              by_series.empty() ? "" : " and summary.png");
}

}  // namespace grainmesh
