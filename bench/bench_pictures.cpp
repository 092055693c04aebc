// make bench: what the pictures cost. `grainmesh run --solve` end to end on the default
// cell (100 grains) and on a cell of 1,000 grains of its grain size, with output.pictures
// = none, basic and all (mixed load, ASCII case as a user runs it); median of three fresh
// processes each. Writes bench/results.json ("pictures").
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/child.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  const fs::path dir = fs::temp_directory_path() / "grainmesh-bench-pictures";
  fs::remove_all(dir);
  fs::create_directories(dir);
  struct Cell {
    int grains;
    const char* size;
  };
  const std::vector<Cell> cells{{100, ""}, {1000, " --set domain.width=10 --set domain.height=5.667"}};
  Json results = Json::array();
  std::printf("%7s %9s %9s %9s\n", "grains", "pictures", "total s", "solve s");
  for (const Cell& cell : cells)
    for (const std::string pictures : {"none", "basic", "all"}) {
      std::vector<Json> samples;
      for (int run = 0; run < 3; ++run) {
        const fs::path out = dir / "run";
        fs::remove_all(out);
        const auto start = std::chrono::steady_clock::now();
        run_command(GRAINMESH_BINARY,
                    "run -o " + out.string() + " --solve --quiet --set tessellation.grains=" +
                        std::to_string(cell.grains) + cell.size + " --set output.pictures=" + pictures,
                    dir / "run.log");
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const Json report = read_json(out / "report.json");
        samples.push_back({{"grains", cell.grains},
                           {"pictures", pictures},
                           {"seconds", seconds},
                           {"stages", report["seconds"]}});
      }
      std::sort(samples.begin(), samples.end(),
                [](const Json& a, const Json& b) { return a["seconds"].get<double>() < b["seconds"].get<double>(); });
      const Json& row = samples[1];
      std::printf("%7d %9s %9.2f %9.2f\n", cell.grains, pictures.c_str(), row["seconds"].get<double>(),
                  row["stages"]["solve"].get<double>());
      std::fflush(stdout);
      results.push_back(row);
    }
  fs::remove_all(dir);
  write_results(source / "bench" / "results.json", "pictures",
                "median of 3 runs of grainmesh run --solve (mixed load), each a fresh process, wall clock end to end",
                results);
  return 0;
}
