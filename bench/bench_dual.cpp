// make bench: triangles against polygonal cells (export.cells) on the same meshes — the
// periodic ten-strip laminate of the homogenisation tests (stiffness ratio 3, layers
// across and along the load, at three densities) against its exact layered modulus, and
// the default cell: cells, checkMesh's max non-orthogonality and skewness, the mixed
// load's modulus and its error, and the solve's seconds. Each case in a child process,
// three times (median). Writes bench/results.json ("dual").
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/homogenise.hpp"
#include "bench/child.hpp"
#include "common/errors.hpp"
#include "export/foam.hpp"
#include "pipelines/config.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/laminate.hpp"
#include "pipelines/mesh_command.hpp"
#include "pipelines/run_command.hpp"
#include "pipelines/tessellate_command.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

struct Case {
  std::string name;
  std::string config;            // ini text; empty: the default cell
  std::vector<std::string> set;  // on top of it
  double exact = 0.0;            // the exact modulus, Pa; 0: none
};

// checkMesh's number after `label` in its log (NaN when absent).
double logged(const std::string& log, const std::string& label) {
  const auto at = log.find(label);
  return at == std::string::npos ? std::nan("") : std::stod(log.substr(at + label.size()));
}

Json measure(const Case& c, FoamOptions::Cells cells, const fs::path& dir) {
  const Config config = c.config.empty() ? Config::from_text(default_run_config(), "default config", c.set)
                                         : Config::from_text(c.config, c.name, c.set);
  const Config tess_config = config.subset(tessellate_config_keys());
  const Tessellation t = run_tessellate_job(read_tessellate_job(tess_config), tess_config);
  const GrainMesh m = mesh_tessellation(t, read_mesh_job(config.subset(mesh_config_keys()), t).options);
  FoamOptions o = read_foam_options(config.subset(export_config_keys()));
  o.cells = cells;
  const ExportMesh e = export_mesh(t, m, cells);
  fs::remove_all(dir);
  fs::create_directories(dir);
  const PolyMesh pm = write_foam_case(dir, e, o);
  const std::string log_file = (dir / "checkMesh.log").string();
  const std::string command = "cd '" + dir.string() + "' && WM_PROJECT_DIR=" + kFoamProjectDir + " checkMesh > '" +
                              log_file + "' 2>&1";
  if (std::system(command.c_str()) != 0) throw IoError("checkMesh failed in " + dir.string());
  std::stringstream log;
  log << std::ifstream(log_file).rdbuf();
  Json row{{"triangles", m.mesh.triangles.size()},
           {"cells", e.mesh.cells()},
           {"non_orthogonality_max_deg", logged(log.str(), "Mesh non-orthogonality Max: ")},
           {"non_orthogonality_mean_deg", logged(log.str(), "average: ")},
           {"skewness_max", logged(log.str(), "Max skewness = ")},
           {"mesh_ok", log.str().find("Mesh OK.") != std::string::npos}};
  const auto start = std::chrono::steady_clock::now();
  const Homogenised h = solve_and_homogenise(dir, e, pm, o);
  row["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  row["modulus"] = h.modulus;
  if (c.exact > 0.0) row["modulus_error"] = h.modulus / c.exact - 1.0;
  fs::remove_all(dir);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  const test::Material hard{600e9, 0.2}, soft{200e9, 0.3};
  const std::array<double, 4> exact = test::laminate(hard, soft, 0.3);  // layers normal to x
  std::vector<Case> cases;
  for (const bool across : {true, false})
    for (const int per_grain : {50, 200, 800})
      cases.push_back({std::string("laminate ") + (across ? "across" : "along") + ", " + std::to_string(per_grain) +
                           " triangles per strip",
                       test::laminate_config(hard, soft, across, 0.0),
                       {"mesh.triangles_per_grain=" + std::to_string(per_grain)},
                       across ? exact[0] : exact[1]});
  for (const int per_grain : {100, 400})
    cases.push_back({"default cell, " + std::to_string(per_grain) + " triangles per grain", "",
                     {"mesh.triangles_per_grain=" + std::to_string(per_grain)}, 0.0});

  Json results = Json::array();
  std::printf("%-44s %-9s %7s %10s %9s %9s %11s %8s\n", "dual", "cells", "count", "error", "nonorth", "skewness",
              "modulus", "seconds");
  const fs::path dir = fs::temp_directory_path() / "grainmesh-bench-dual";
  for (const Case& c : cases)
    for (const auto cells : {FoamOptions::Cells::triangles, FoamOptions::Cells::polygons}) {
      const char* shape = cells == FoamOptions::Cells::polygons ? "polygons" : "triangles";
      std::fflush(stdout);
      Json row = median_in_children(3, [&] { return measure(c, cells, dir); });
      if (row.contains("error")) {
        std::printf("%s: error: %s\n", c.name.c_str(), row["error"].get<std::string>().c_str());
        return 1;
      }
      std::printf("%-44s %-9s %7zu %10.2e %9.1f %9.2f %11.4e %8.2f\n", c.name.c_str(), shape,
                  row["cells"].get<std::size_t>(), row.value("modulus_error", 0.0), row["non_orthogonality_max_deg"].get<double>(),
                  row["skewness_max"].get<double>(), row["modulus"].get<double>(), row["seconds"].get<double>());
      Json labelled{{"case", c.name}, {"shape", shape}};
      labelled.update(row);
      results.push_back(labelled);
    }
  write_results(source / "bench" / "results.json", "dual",
                "median of 3 runs, each in a fresh process; seconds = solve_and_homogenise() (mixed load); modulus_error = "
                "modulus / exact layered modulus - 1",
                results);
  return 0;
}
