// make bench: scale. `grainmesh run --solve` end to end (tessellate, mesh, export, solve,
// homogenise; the mixed load) on cells of 10,000 and 100,000 grains at the default cell's
// grain size and density (100 triangles per grain: 1.06M and 10.5M cells, so the case is
// binary), the solve on one process and on two (decomposePar, mpirun -np 2
// solidDisplacementFoam -parallel, reconstructPar). Per stage: seconds and peak resident
// memory from the run's report (grainmesh's own; the solve's with the solver's
// processes summed); the solve split into OpenFOAM's steps (decomposePar, the solver,
// reconstructPar) as the report times them.
// One run each, a fresh process. Writes bench/results.json ("scale").
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/child.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

struct Cell {
  int grains;
  double width, height;  // the default cell's grain size: 100 grains in 3 x 1.7 um
};

}  // namespace

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  const fs::path dir = fs::temp_directory_path() / "grainmesh-bench-scale";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<Cell> cells{{10000, 30.0, 17.0}, {100000, 94.868, 53.759}};
  Json results = Json::array();
  std::printf("%7s %5s %9s %7s %7s %7s %7s %7s %7s | %7s %7s %7s %7s %7s | %9s %11s\n", "grains", "procs", "cells",
              "tess s", "mesh s", "exp s", "solve s", "total s", "decomp", "tess M", "mesh M", "exp M", "solve M",
              "peak M", "solver s", "modulus");
  for (const Cell& cell : cells)
    for (const int processes : {1, 2}) {
      const fs::path out = dir / "run";
      fs::remove_all(out);
      char args[512];
      std::snprintf(args, sizeof args,
                    "run -o %s --solve --quiet --set tessellation.grains=%d --set domain.width=%g --set "
                    "domain.height=%g --set output.pictures=none --set solve.processes=%d",
                    out.c_str(), cell.grains, cell.width, cell.height, processes);
      const auto start = std::chrono::steady_clock::now();
      run_command(GRAINMESH_BINARY, args, dir / "run.log");
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const Json report = read_json(out / "report.json");
      const Json& steps = report["effective"]["seconds"];
      const Json row{{"grains", cell.grains},
                     {"processes", processes},
                     {"cells", report["mesh"]["cells"]},
                     {"case_format", report["case_format"]},
                     {"seconds", seconds},
                     {"stages", report["seconds"]},
                     {"solve_steps", steps},
                     {"memory_mib", report["memory_mib"]},
                     {"peak_memory_mib", report["peak_memory_mib"]},
                     {"corrections", report["effective"]["corrections"]},
                     {"modulus", report["effective"]["modulus"]}};
      const Json& s = report["seconds"];
      const Json& m = report["memory_mib"];
      std::printf("%7d %5d %9d %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f | %7.0f %7.0f %7.0f %7.0f %7.0f | %9.2f %11.6g\n",
                  cell.grains, processes, report["mesh"]["cells"].get<int>(), s["tessellate"].get<double>(),
                  s["mesh"].get<double>(), s["export"].get<double>(), s["solve"].get<double>(), seconds,
                  steps["decomposePar"].get<double>() + steps["reconstructPar"].get<double>(),
                  m["tessellate"].get<double>(), m["mesh"].get<double>(), m["export"].get<double>(),
                  m["solve"].get<double>(), report["peak_memory_mib"].get<double>(),
                  steps["solidDisplacementFoam"].get<double>(),
                  report["effective"]["modulus"].get<double>());
      std::fflush(stdout);
      results.push_back(row);
      fs::remove_all(out);
    }
  fs::remove_all(dir);
  write_results(source / "bench" / "results.json", "scale",
                "one run of grainmesh run --solve (mixed load, output.pictures = none, binary case above 1M cells) per "
                "row, a fresh process, wall clock end to end; stages, OpenFOAM's steps, memory and the modulus from "
                "its report",
                results);
  return 0;
}
