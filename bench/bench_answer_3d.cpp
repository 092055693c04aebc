// make bench: time to a 3D answer on the 3D WC-Co example
// (data/examples/grains_3d_wc_co.ini: 85 % WC, 15 % Co, 500 tetrahedra per grain) at 100
// and 1,000 grains of the same size, periodic, one run each (a fresh process, no pictures):
// - the answer (`grainmesh run`, the finite elements on two nested levels) with the
//   thermal load: the 6 x 6 tensor and the expansion with their error estimates; seconds
//   per stage, the finite elements' unknowns, their levels' seconds and cycles, the
//   process's peak memory, the largest estimate. Writes "answer_3d_fe".
// - OpenFOAM's answer (`grainmesh run --solve`, homogenise.solver = openfoam: the
//   tetrahedra's dual polyhedra, six load cases), serial and with solve.processes = 2: seconds per stage, cells, the process
//   tree's peak memory (the solvers' included), the tensor's symmetry and its bulk and shear
//   moduli against Hashin-Shtrikman. Writes "answer_3d".
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/child.hpp"
#include "bench/peers.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

struct Run {
  Json report;
  double seconds = 0.0;
  double peak_mib = 0.0;
};

// grainmesh with `args` in a child of ours (run_process), so that its rusage is its
// process tree's (solvers included); its report read back. Exits on failure.
Run run_grainmesh(const std::vector<std::string>& args, const fs::path& dir, const fs::path& out) {
  std::vector<std::string> argv{GRAINMESH_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  const ProcessRun p = run_process(argv, dir / "run.log");
  if (p.exit_code != 0) {
    std::fprintf(stderr, "bench_answer_3d: grainmesh failed with %d (see %s)\n", p.exit_code, (dir / "run.log").c_str());
    std::exit(1);
  }
  return {read_json(out / "report.json"), p.seconds, p.peak_mib};
}

// The example at `grains` grains of its own size, periodic, without pictures, and `more`.
std::vector<std::string> cell_args(const std::string& config, const fs::path& out, int grains,
                                   const std::vector<std::string>& more) {
  char side[32];
  std::snprintf(side, sizeof side, "%g", 2.0 * std::cbrt(grains / 100.0));
  std::vector<std::string> args{"run", config, "-o", out.string(), "--quiet"};
  for (const std::string& set :
       {"tessellation.grains=" + std::to_string(grains), "domain.width=" + std::string(side),
        "domain.height=" + std::string(side), "domain.depth=" + std::string(side), std::string("homogenise.boundary=periodic"), std::string("output.pictures=none")}) {
    args.push_back("--set");
    args.push_back(set);
  }
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// The finite elements' answer with the thermal load (WC 5.2e-6, Co 13.8e-6 per K).
Json fe_rows(const std::string& config, const fs::path& dir) {
  Json results = Json::array();
  std::printf("%7s %9s %10s %7s %7s %8s %6s %13s %6s %8s %8s  %s\n", "grains", "tets", "unknowns", "tess s",
              "mesh s", "export s", "fe s", "coarse s (it)", "fine it", "total s", "peak MiB", "largest estimate");
  for (const int grains : {100, 1000}) {
    const fs::path out = dir / "run";
    fs::remove_all(out);
    const Run r = run_grainmesh(cell_args(config, out, grains,
                                          {"--set", "load.delta_T=-1000", "--set", "phase.WC.alpha=5.2e-6", "--set",
                                           "phase.Co.alpha=13.8e-6"}),
                                dir, out);
    const Json& fe = r.report["effective"]["finite_elements"];
    double largest = 0.0;
    for (const auto& [key, value] : r.report["effective"]["error_estimate"]["stiffness"].items())
      if (key[1] == key[2] || key == "C12") largest = std::max(largest, value.get<double>());
    const Json& s = r.report["seconds"];
    Json row{{"grains", grains},
             {"tetrahedra", r.report["mesh"]["cells"]},
             {"seconds", r.seconds},
             {"stages", s},
             {"finite_elements", fe},
             {"peak_memory_mib", r.peak_mib},
             {"largest_estimate", largest}};
    std::printf("%7d %9d %10d %7.2f %7.2f %8.2f %6.1f %8.1f (%2d) %6d %8.1f %8.0f  %.2f %%\n", grains,
                row["tetrahedra"].get<int>(), fe["unknowns"].get<int>(), s["tessellate"].get<double>(),
                s["mesh"].get<double>(), s["export"].get<double>(), fe["seconds"].get<double>(),
                fe["coarse"]["seconds"].get<double>(), fe["coarse"]["iterations"].get<int>(), fe["iterations"].get<int>(),
                r.seconds, r.peak_mib, 100 * largest);
    std::fflush(stdout);
    results.push_back(row);
  }
  return results;
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  const fs::path dir = fs::temp_directory_path() / "grainmesh-bench-answer-3d";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string config = (source / "data" / "examples" / "grains_3d_wc_co.ini").string();
  const Json fe = fe_rows(config, dir);
  write_results(source / "bench" / "results.json", "answer_3d_fe",
                "one run of grainmesh run (periodic, thermal load, the finite elements answering, no pictures) per row, "
                "a fresh process, wall clock end to end; stages and the finite elements' levels from its report; peak "
                "memory (wait4); the largest error estimate over the diagonal entries and C12",
                fe);
  Json results = Json::array();
  std::printf("%7s %5s %9s %8s %8s %8s %8s %8s %8s %9s  %s\n", "grains", "procs", "tets", "cells", "tess s", "mesh s",
              "export s", "solve s", "total s", "peak MiB", "K, G vs HS upper; symmetry");
  for (const int grains : {100, 1000}) {
    for (const int processes : {1, 2}) {
      const fs::path out = dir / "run";
      fs::remove_all(out);
      const Run r = run_grainmesh(cell_args(config, out, grains,
                                            {"--solve", "--set", "homogenise.solver=openfoam", "--set",
                                             "export.format=binary", "--set", "solve.processes=" + std::to_string(processes)}),
                                  dir, out);
      const double seconds = r.seconds;
      const Json& report = r.report;
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
               {"peak_memory_mib", r.peak_mib},
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
