// make bench: the OpenFOAM export of a million cells, ASCII and binary. A synthetic mesh
// (a square grid cut into triangles, two phases in stripes of grains) stands in for a
// mesh-stage output: the export's cost depends on the counts, not on where they came from.
// Each case runs in a child process, three times (median); "seconds" is write_foam_case()
// (polyMesh, zones, fields, dictionaries). Writes bench/results.json ("export").
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/child.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_case.hpp"

using namespace grainmesh;

namespace {

ExportMesh<2> grid_mesh(int n) {
  ExportMesh<2> e;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) e.mesh.points.push_back({static_cast<double>(i) / n, static_cast<double>(j) / n});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      const int grain = (j / 10) * (n / 10 + 1) + i / 10;  // 10 x 10 squares per grain
      for (const auto& t : {std::array<int, 3>{a, b, d}, std::array<int, 3>{a, d, c}}) {
        e.mesh.add_cell(t);
        e.grain.push_back(grain);
        e.phase.push_back(grain % 7 == 0 ? 1 : 0);
      }
    }
  e.phases = {{"WC", 700e9, 0.24}, {"Co", 211e9, 0.31}};
  e.cell = Box{{0.0, 0.0}, {1.0, 1.0}};
  e.periodic = true;
  return e;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path source = argc > 1 ? argv[1] : ".";
  const ExportMesh<2> mesh = grid_mesh(708);  // 1,002,528 cells
  Json results = Json::array();
  std::printf("%-30s %9s %10s %12s %9s\n", "export, 1M cells", "seconds", "cells", "cells / s", "peak MiB");
  for (bool binary : {false, true}) {
    const std::string name = binary ? "binary" : "ascii";
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("grainmesh-bench-export-" + name);
    Json row = median_in_children(3, [&] {
      std::filesystem::remove_all(dir);
      std::filesystem::create_directories(dir);
      const auto start = std::chrono::steady_clock::now();
      write_foam_case(dir, mesh, {.binary = binary});
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::uintmax_t bytes = 0;
      for (const auto& f : std::filesystem::recursive_directory_iterator(dir))
        if (f.is_regular_file()) bytes += f.file_size();
      return Json{{"seconds", seconds}, {"cells", mesh.mesh.cells()}, {"bytes", bytes}};
    });
    std::filesystem::remove_all(dir);
    if (row.contains("error")) {
      std::printf("%s: error: %s\n", name.c_str(), row["error"].get<std::string>().c_str());
      return 1;
    }
    const double cells_per_second = row["cells"].get<double>() / row["seconds"].get<double>();
    row["cells_per_second"] = cells_per_second;
    std::printf("%-30s %9.3f %10zu %12.0f %9.1f\n", name.c_str(), row["seconds"].get<double>(),
                row["cells"].get<std::size_t>(), cells_per_second, row["peak_memory_mib"].get<double>());
    Json labelled{{"case", "1M cells, " + name}};
    labelled.update(row);
    results.push_back(labelled);
  }
  write_results(source / "bench" / "results.json", "export",
                "median of 3 runs, each in a fresh process; write_foam_case() alone", results);
  return 0;
}
