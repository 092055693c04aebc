// make bench: fixed-seed tessellation benchmarks, each run in a fresh child process
// (median of 3 for time, largest peak memory). The time is tessellate() alone: seeds,
// power diagrams, Lloyd, regularisation, window, phases and cut; no file output.
// Prints a table and writes bench/results.json ("tessellate").
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/child.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellate.hpp"

using namespace grainmesh;

namespace {

struct Case {
  std::string name;
  int grains;
  int lloyd;
  PhaseMode mode;
  double limit_seconds;  // the bound, 0 = none
  double limit_mib;
};

Json measure(const Case& c) {
  TessellationOptions o;
  o.width = 2.0;
  o.height = 1.0;
  o.grains = c.grains;
  o.lloyd_iterations = c.lloyd;
  o.phase_mode = c.mode;
  o.phases = {Phase{"WC", 0.0, true, 700e9, 0.24, {}}, Phase{"Co", 0.15, false, 211e9, 0.31, {}}};
  o.matrix_phase = 1;
  Rng rng(1);
  const auto start = std::chrono::steady_clock::now();
  const Tessellation t = tessellate(o, rng);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {{"seconds", seconds},
          {"grains", t.stats.grains},
          {"regions", t.regions.size()},
          {"vertices", t.vertices.size()},
          {"sharpest_corner_deg", t.stats.sharpest_corner_deg},
          {"shortest_edge_over_threshold", t.stats.shortest_edge / t.stats.edge_threshold},
          {"side_jogs", t.stats.side_jogs},
          {"co_fraction", t.stats.phases[1].achieved_fraction}};
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path source = argc > 1 ? argv[1] : ".";
  const int runs = 3;
  const std::vector<Case> cases{
      {"200 grains, 3 Lloyd", 200, 3, PhaseMode::grain, 0, 0},
      {"2000 grains, 3 Lloyd", 2000, 3, PhaseMode::grain, 0, 0},
      {"10k grains, 10 Lloyd", 10'000, 10, PhaseMode::grain, 2.0, 0},
      {"10k grains, 10 Lloyd, binder", 10'000, 10, PhaseMode::binder, 0, 0},
      {"100k grains, Poisson", 100'000, 0, PhaseMode::grain, 30.0, 2048},
      {"100k grains, 3 Lloyd", 100'000, 3, PhaseMode::grain, 30.0, 2048},
  };
  Json results = Json::array();
  std::printf("%-32s %9s %8s %9s %8s %9s %9s %7s\n", "case", "seconds", "limit s", "regions", "sharpest", "short/thr",
              "peak MiB", "ok");
  bool all_ok = true;
  for (const Case& c : cases) {
    Json row = median_in_children(runs, [&] { return measure(c); });
    if (row.contains("error")) {
      std::printf("%-32s error: %s\n", c.name.c_str(), row["error"].get<std::string>().c_str());
      return 1;
    }
    const double s = row["seconds"].get<double>(), mib = row["peak_memory_mib"].get<double>();
    const bool ok = (c.limit_seconds == 0 || s < c.limit_seconds) && (c.limit_mib == 0 || mib < c.limit_mib);
    all_ok = all_ok && ok;
    Json labelled{{"case", c.name}, {"lloyd_iterations", c.lloyd}};
    labelled.update(row);
    if (c.limit_seconds > 0) labelled["limit_seconds"] = c.limit_seconds;
    if (c.limit_mib > 0) labelled["limit_mib"] = c.limit_mib;
    std::printf("%-32s %9.3f %8s %9zu %8.1f %9.2f %9.1f %7s\n", c.name.c_str(), s,
                c.limit_seconds > 0 ? std::to_string(c.limit_seconds).substr(0, 4).c_str() : "-",
                row["regions"].get<std::size_t>(), row["sharpest_corner_deg"].get<double>(),
                row["shortest_edge_over_threshold"].get<double>(), mib, ok ? "yes" : "NO");
    std::fflush(stdout);
    results.push_back(labelled);
  }
  write_results(source / "bench" / "results.json", "tessellate",
                "median of 3 runs of tessellate() alone, in a fresh process each", results);
  return all_ok ? 0 : 1;
}
