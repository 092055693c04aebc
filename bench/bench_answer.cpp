// make bench: time to an answer. For cells of 100, 1,000 and 10,000 grains (the default
// cell's grain size and phases), `grainmesh run --solve` end to end, as a user runs it
// (a fresh process; binary case, no pictures), under the mixed load (the modulus) and
// periodic (the tensor), at 25 and at 100 (the default) triangles per grain: seconds
// per stage, cells, and the error against the cell's own Richardson limit from
// `grainmesh converge` (25 to 400 triangles per grain; at 10,000 grains the mixed
// modulus alone, to 100, and the periodic tensor at 25 only). Median of three runs (one
// at 10,000 grains). Writes bench/results.json ("answer").
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/child.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

struct Cell {
  int grains;
  double width, height;
};

std::string cell_args(const Cell& c, const std::string& boundary) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "--set tessellation.grains=%d --set domain.width=%g --set domain.height=%g --set homogenise.boundary=%s",
                c.grains, c.width, c.height, boundary.c_str());
  return buf;
}

// The quantities compared with the limit: the modulus, or C11 and C12 (the slowest).
std::vector<std::string> quantities(const std::string& boundary) {
  return boundary == "mixed" ? std::vector<std::string>{"modulus"} : std::vector<std::string>{"C11", "C12", "C66"};
}
double quantity(const Json& effective, const std::string& q) {
  return q == "modulus" ? effective["modulus"].get<double>() : effective["stiffness"][q].get<double>();
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  const fs::path dir = fs::temp_directory_path() / "grainmesh-bench-answer";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // The default cell's grain size: 100 grains in 3 x 1.7 um.
  const std::vector<Cell> cells{{100, 3.0, 1.7}, {1000, 10.0, 5.667}, {10000, 30.0, 17.0}};
  Json results = Json::array();
  std::printf("%7s %9s %5s %8s %8s %8s %8s %8s %8s  %s\n", "grains", "boundary", "tpg", "cells", "tess s", "mesh s",
              "export s", "solve s", "total s", "error vs limit");
  for (const Cell& cell : cells) {
    for (const std::string boundary : {"mixed", "periodic"}) {
      // The limit: the study's Richardson estimate of each quantity; at 10,000 grains the
      // mixed one alone, from 25 to 100 triangles per grain, and one run of each.
      const bool big = cell.grains >= 10000;
      Json limits;
      if (!big || boundary == "mixed") {
        const fs::path study = dir / ("converge-" + std::to_string(cell.grains) + "-" + boundary);
        run_command(GRAINMESH_BINARY, "converge -o " + study.string() + " --levels " + std::to_string(big ? 3 : 5) + " --start 25 " +
                          cell_args(cell, boundary) + " --set export.format=binary --set output.pictures=false",
                      dir / "converge.log");
        limits = read_json(study / "report.json")["study"];
      }
      for (const int tpg : {25, 100}) {
        if (big && boundary == "periodic" && tpg == 100) continue;
        std::vector<Json> samples;
        for (int run = 0; run < (big ? 1 : 3); ++run) {
          const fs::path out = dir / "run";
          fs::remove_all(out);
          const auto start = std::chrono::steady_clock::now();
          run_command(GRAINMESH_BINARY, "run -o " + out.string() + " --solve --quiet " + cell_args(cell, boundary) +
                        " --set export.format=binary --set output.pictures=false --set mesh.triangles_per_grain=" +
                        std::to_string(tpg),
                    dir / "run.log");
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const Json report = read_json(out / "report.json");
          Json row{{"grains", cell.grains},
                   {"boundary", boundary},
                   {"triangles_per_grain", tpg},
                   {"cells", report["mesh"]["cells"]},
                   {"seconds", seconds},
                   {"stages", report["seconds"]},
                   {"peak_memory_mib", report["peak_memory_mib"]}};
          Json errors = Json::object();
          if (!limits.is_null())
            for (const std::string& q : quantities(boundary)) {
              const double limit = limits[q]["limit"].get<double>();
              errors[q] = quantity(report["effective"], q) / limit - 1.0;
            }
          row["error_vs_limit"] = errors;
          samples.push_back(row);
        }
        std::sort(samples.begin(), samples.end(),
                  [](const Json& a, const Json& b) { return a["seconds"].get<double>() < b["seconds"].get<double>(); });
        const Json& row = samples[samples.size() / 2];
        std::string errors;
        for (const auto& [q, e] : row["error_vs_limit"].items()) {
          char buf[64];
          std::snprintf(buf, sizeof buf, "%s%s %+.3f %%", errors.empty() ? "" : ", ", q.c_str(), 100 * e.get<double>());
          errors += buf;
        }
        const Json& s = row["stages"];
        std::printf("%7d %9s %5d %8d %8.2f %8.2f %8.2f %8.2f %8.2f  %s\n", cell.grains, boundary.c_str(), tpg,
                    row["cells"].get<int>(), s["tessellate"].get<double>(), s["mesh"].get<double>(),
                    s["export"].get<double>(), s["solve"].get<double>(), row["seconds"].get<double>(), errors.c_str());
        std::fflush(stdout);
        results.push_back(row);
      }
    }
  }
  fs::remove_all(dir);
  write_results(source / "bench" / "results.json", "answer",
                "median of 3 runs of grainmesh run --solve (binary case, output.pictures = false), each a fresh "
                "process, wall clock end to end; stages from its report; limits from grainmesh converge",
                results);
  return 0;
}
