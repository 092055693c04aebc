// make bench: time to a 3D answer. `grainmesh run --solve` end to end on the 3D WC-Co
// example (data/examples/grains_3d_wc_co.ini: 85 % WC, 15 % Co, 500 tetrahedra per grain
// solved on their dual's polyhedra) at 100 and 1,000 grains of the same size, periodic (six
// load cases, the 6 x 6 tensor), serial and with solve.processes = 2: seconds per stage,
// cells, the process tree's peak memory (the solver's included), the tensor's symmetry
// and its bulk and shear moduli against Hashin-Shtrikman. One run each (a fresh process).
// Writes bench/results.json ("answer_3d").
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "bench/child.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  const fs::path dir = fs::temp_directory_path() / "grainmesh-bench-answer-3d";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string config = (source / "data" / "examples" / "grains_3d_wc_co.ini").string();
  Json results = Json::array();
  std::printf("%7s %5s %9s %8s %8s %8s %8s %8s %8s %9s  %s\n", "grains", "procs", "tets", "cells", "tess s", "mesh s",
              "export s", "solve s", "total s", "peak MiB", "K, G vs HS upper; symmetry");
  for (const int grains : {100, 1000}) {
    const double side = 2.0 * std::cbrt(grains / 100.0);  // the example's grain size
    for (const int processes : {1, 2}) {
      const fs::path out = dir / "run";
      fs::remove_all(out);
      char args[512];
      std::snprintf(args, sizeof args,
                    "run %s -o %s --solve --quiet --set tessellation.grains=%d --set domain.width=%g --set "
                    "domain.height=%g --set domain.depth=%g --set homogenise.boundary=periodic --set "
                    "export.format=binary --set output.pictures=none --set solve.processes=%d",
                    config.c_str(), out.string().c_str(), grains, side, side, side, processes);
      const auto start = std::chrono::steady_clock::now();
      // The run in a child of ours, so its rusage is its process tree's (solvers included).
      const pid_t pid = fork();
      if (pid == 0) {
        const std::string command = std::string(GRAINMESH_BINARY) + " " + args + " > " + (dir / "run.log").string() + " 2>&1";
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
      }
      int status = 0;
      rusage usage{};
      wait4(pid, &status, 0, &usage);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::fprintf(stderr, "bench_answer_3d: grainmesh %s failed (see %s)\n", args, (dir / "run.log").c_str());
        return 1;
      }
      const Json report = read_json(out / "report.json");
      const Json& eff = report["effective"];
      const Json& hs = eff["hashin_shtrikman"];
      const double K = eff["bulk_modulus"].get<double>() / hs["bulk_upper"].get<double>() - 1.0;
      const double G = eff["shear_modulus"].get<double>() / hs["shear_upper"].get<double>() - 1.0;
      Json row{{"grains", grains},
               {"processes", processes},
               {"tetrahedra", report["mesh"]["cells"]},
               {"cells", report["case_cells"]["cells"]},
               {"seconds", seconds},
               {"stages", report["seconds"]},
               {"peak_memory_mib", static_cast<double>(usage.ru_maxrss) / 1024.0},
               {"corrections", eff["corrections"]},
               {"symmetry_error", eff["symmetry_error"]},
               {"bulk_vs_hs_upper", K},
               {"shear_vs_hs_upper", G}};
      const Json& s = report["seconds"];
      std::printf("%7d %5d %9d %8d %8.2f %8.2f %8.2f %8.2f %8.2f %9.0f  K %+.2f %%, G %+.2f %%; %.1e\n", grains, processes,
                  row["tetrahedra"].get<int>(), row["cells"].get<int>(), s["tessellate"].get<double>(),
                  s["mesh"].get<double>(), s["export"].get<double>(), s["solve"].get<double>(), seconds,
                  row["peak_memory_mib"].get<double>(), 100 * K, 100 * G, eff["symmetry_error"].get<double>());
      std::fflush(stdout);
      results.push_back(row);
    }
  }
  fs::remove_all(dir);
  write_results(source / "bench" / "results.json", "answer_3d",
                "one run of grainmesh run --solve (periodic, binary case, no pictures) per row, a fresh process, "
                "wall clock end to end; stages from its report; peak memory of the process tree (wait4)",
                results);
  return 0;
}
