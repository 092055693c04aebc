// make bench: fixed-seed DistMesh benchmarks. Each case runs in a child process, three
// times, so that its peak memory is its own; the time is the mesher's alone (seeding,
// iterations, final optimisation), without reading the config or writing files.
// Prints a table and updates bench/results.json ("distmesh").
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "bench/child.hpp"
#include "mesh/quality.hpp"
#include "pipelines/domain_command.hpp"

using namespace grainmesh;

namespace {

struct Case {
  std::string name;
  std::string config;                   // relative to the source directory
  std::optional<double> thesis_seconds;  // the thesis' Tables 3.1-3.3
};

// Runs one case in this process and returns its measures.
Json measure(const std::filesystem::path& config) {
  const DistMeshResult r = mesh_domain(read_domain_job(Config::from_file(config)));
  Json row{{"seconds", r.stats.seconds}};
  row.update(mesh_measures(r.mesh));
  row.update(Json{{"iterations", r.stats.iterations},
                  {"retriangulations", r.stats.retriangulations},
                  {"triangulations_built_anew", r.stats.rebuilds},
                  {"converged", r.stats.converged}});
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path source = argc > 1 ? argv[1] : ".";
  const int runs = 3;
  const std::vector<Case> cases{
      {"circle_h02 (Table 3.1)", "data/examples/circle_h02.ini", 0.8},
      {"circle_h01 (Table 3.1)", "data/examples/circle_h01.ini", 8.62},
      {"ellipse (Table 3.2)", "data/examples/ellipse.ini", 1.85},
      {"union_polygon_circle (Table 3.3)", "data/examples/union_polygon_circle.ini", 10.28},
      {"ellipse_minus_circle (Table 3.3)", "data/examples/ellipse_minus_circle.ini", 19.97},
      {"intersection_two_circles (Table 3.3)", "data/examples/intersection_two_circles.ini", 1.16},
      {"fibres_20", "data/examples/fibres_20.ini", {}},
  };

  Json results = Json::array();
  std::printf("%-38s %9s %9s %8s %9s %7s %7s %8s %8s %9s\n", "case", "seconds", "thesis s", "ratio", "triangles",
              "q_min", "q_mean", "q<0.5", "min ang", "peak MiB");
  for (const Case& c : cases) {
    Json row = median_in_children(runs, [&] { return measure(source / c.config); });
    if (row.contains("error")) {
      std::printf("%-38s error: %s\n", c.name.c_str(), row["error"].get<std::string>().c_str());
      return 1;
    }
    const double peak = row["peak_memory_mib"].get<double>();
    Json labelled{{"case", c.name}, {"config", c.config}};
    labelled.update(row);
    row = std::move(labelled);
    std::string thesis = "-", ratio = "-";
    if (c.thesis_seconds) {
      row["thesis_seconds"] = *c.thesis_seconds;
      row["share_of_thesis_time"] = row["seconds"].get<double>() / *c.thesis_seconds;
      thesis = std::to_string(*c.thesis_seconds).substr(0, 5);
      char b[32];
      std::snprintf(b, sizeof b, "%.3f%%", 100.0 * row["share_of_thesis_time"].get<double>());
      ratio = b;
    }
    std::printf("%-38s %9.4f %9s %8s %9zu %7.3f %7.4f %8.4f %8.1f %9.1f\n", c.name.c_str(), row["seconds"].get<double>(),
                thesis.c_str(), ratio.c_str(), row["triangles"].get<std::size_t>(), row["q_min"].get<double>(),
                row["q_mean"].get<double>(), row["q_below_0_5"].get<double>(), row["min_angle_deg"].get<double>(), peak);
    std::fflush(stdout);
    results.push_back(row);
  }

  write_results(source / "bench" / "results.json", "distmesh",
                "median of 3 runs of the mesher alone, in a fresh process each", results);
  return 0;
}
