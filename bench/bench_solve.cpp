// make bench: the solve of `grainmesh run --solve` on the default cell and its variants:
// corrections and seconds to convergence as the stiffness contrast grows, one material
// (the case's own stop on x alone), two phases a hair apart (a component near zero),
// cyclic patches, a 1,000-grain cell, and how soon a diverging solve is stopped. Each case in a child process, three times (median); "seconds" is
// solve_mixed() (the solver with its start-up, reading the stress). Writes
// bench/results.json ("solve").
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/homogenise.hpp"
#include "bench/child.hpp"
#include "common/errors.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_case.hpp"
#include "export/foam_material.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh.hpp"
#include "pipelines/config.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/mesh_job.hpp"
#include "pipelines/run_command.hpp"
#include "pipelines/tessellate_job.hpp"

using namespace grainmesh;

namespace {

struct Case {
  std::string name;
  std::vector<std::string> set;  // on top of the default config
};

// The default cell with `set`, exported into `dir` and solved; what it took.
Json solve_case(const Case& c, const std::filesystem::path& dir) {
  const Config config = Config::from_text(default_run_config(), "default config", c.set);
  const Config tess_config = config.subset(tessellate_config_keys());
  const Tessellation t = run_tessellate_job(read_tessellate_job<2>(tess_config));
  const GrainMesh m = mesh_tessellation(t, read_mesh_job(config.subset(mesh_config_keys()), t).options);
  const ExportMesh<2> e = grain_export_mesh(t, m);
  const FoamOptions o = read_foam_options(config.subset(export_config_keys()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const PolyMesh pm = write_foam_case(dir, e, o);
  const auto start = std::chrono::steady_clock::now();
  Json row{{"cells", m.mesh.triangles.size()}, {"stiffness_contrast", stiffness_contrast(e.phases, o)}};
  try {
    const MixedHomogenised<3> h = solve_mixed(dir, e, pm, o);
    row["corrections"] = h.run.corrections;
    row["final_residual"] = h.run.final_residual;
    row["modulus"] = h.modulus;
    row["outcome"] = "converged";
  } catch (const SolveError& err) {
    const std::string what = err.what();
    row["outcome"] = what.substr(0, what.find(':', what.find(':') + 1));  // "D: solidDisplacementFoam diverges"
    row["message"] = what;
    if (const auto at = what.find(" after "); at != std::string::npos)
      row["corrections"] = std::stoi(what.substr(at + 7));  // "... after 19 corrections"
  }
  row["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::filesystem::remove_all(dir);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path source = argc > 1 ? argv[1] : ".";
  const std::vector<Case> cases{
      {"default cell (contrast 2.7, harmonic)", {}},
      {"matrix E 80 GPa (contrast 10, linear)", {"phase.matrix.E=80e9"}},
      {"matrix E 8 GPa (contrast 100)", {"phase.matrix.E=8e9"}},
      {"matrix E 0.8 GPa (contrast 1,000)", {"phase.matrix.E=800e6"}},
      {"matrix E 0.08 GPa (contrast 10,000)", {"phase.matrix.E=80e6"}},
      {"one material", {"phase.matrix.E=800e9"}},
      {"two phases 1e-8 apart", {"phase.matrix.E=799.99999e9"}},
      {"cyclic patches", {"export.cyclic=true"}},
      {"1,000 grains", {"tessellation.grains=1000"}},
      {"diverging: harmonic at contrast 16", {"phase.matrix.E=50e9", "export.stiffness_interpolation=harmonic"}},
  };
  Json results = Json::array();
  std::printf("%-42s %8s %9s %12s %10s %9s  %s\n", "solve", "cells", "contrast", "corrections", "seconds", "peak MiB",
              "outcome");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "grainmesh-bench-solve";
  for (const Case& c : cases) {
    std::fflush(stdout);  // or a child's fflush before it starts the solver prints our lines again
    Json row = median_in_children(3, [&] { return solve_case(c, dir); });
    if (row.contains("error")) {
      std::printf("%s: error: %s\n", c.name.c_str(), row["error"].get<std::string>().c_str());
      return 1;
    }
    std::printf("%-42s %8zu %9.1f %12d %10.2f %9.1f  %s\n", c.name.c_str(), row["cells"].get<std::size_t>(),
                row["stiffness_contrast"].get<double>(), row.value("corrections", 0), row["seconds"].get<double>(),
                row["peak_memory_mib"].get<double>(), row["outcome"].get<std::string>().c_str());
    Json labelled{{"case", c.name}};
    labelled.update(row);
    results.push_back(labelled);
  }
  write_results(source / "bench" / "results.json", "solve",
                "median of 3 runs, each in a fresh process; solve_mixed() alone (the solver's run, "
                "start-up included, and reading its stress)",
                results);
  return 0;
}
