// The cases of a run, plane or solid cell alike: the mixed load's case/, or each periodic
// load case in its own case_NAME/ on one mesh, its polyMesh files written once and copied
// (the load cases' options differ in the strain and temperature alone).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/homogenise.hpp"
#include "analysis/load_case.hpp"
#include "export/foam_options.hpp"

namespace grainmesh {

// Writes the cases of exported mesh `e` into `dir`; returns their directory names, and in
// `mesh` the mesh they were written on. `ExportedMesh` is ExportMesh<2> or ExportMesh<3>
// (write_foam_case and periodic_load_cases of its dimension).
template <class ExportedMesh, class CaseMesh>
std::vector<std::string> write_run_cases(const std::filesystem::path& dir, const ExportedMesh& e,
                                         const FoamOptions& foam, Boundary boundary, CaseMesh& mesh) {
  if (boundary == Boundary::mixed) {
    std::filesystem::create_directories(dir / "case");
    mesh = write_foam_case(dir / "case", e, foam);
    return {"case"};
  }
  std::vector<std::string> names;
  for (const auto& lc : periodic_load_cases(e, foam)) {
    const bool first = names.empty();
    names.push_back(load_case_dir(lc));
    std::filesystem::create_directories(dir / names.back());
    if (first)
      mesh = write_foam_case(dir / names.back(), e, load_case_options(foam, lc));
    else
      write_foam_case(dir / names.back(), e, mesh, load_case_options(foam, lc),
                      dir / names.front() / "constant" / "polyMesh");
  }
  return names;
}

}  // namespace grainmesh
