// The cases of a run, plane or solid cell alike: the mixed load's case/, or each periodic
// load case in its own case_NAME/ on one mesh, its polyMesh files written once and copied
// (the load cases' options differ in the strain and temperature alone).
#pragma once

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/homogenise.hpp"
#include "analysis/load_case.hpp"
#include "common/format.hpp"
#include "export/foam_options.hpp"
#include "export/nested_split.hpp"
#include "pipelines/config_origin.hpp"

namespace grainmesh {

// The most cells mesh.refine may make: far more is a slip (a digit), refused before the split.
inline constexpr double kMaxRefinedCells = 2e7;

// The exported mesh `e` split `refine` times in nested refinement (mesh.refine; 0: as it
// is). Throws ConfigError naming mesh.refine (through `origin`) when that would make more
// than kMaxRefinedCells cells.
template <int D>
ExportMesh<D> refined(ExportMesh<D> e, int refine, const ConfigOrigin& origin) {
  if (refine == 0) return e;
  double cells = 0.0;
  if constexpr (D == 2) cells = static_cast<double>(e.mesh.cells());
  else cells = static_cast<double>(e.mesh.tets.size());
  cells *= std::pow(D == 2 ? 4.0 : 8.0, refine);
  if (cells > kMaxRefinedCells)
    origin.fail("mesh.refine", std::to_string(refine) + " would make about " + to_text(cells) + " cells, more than " +
                                   to_text(kMaxRefinedCells) + ": refine less, or coarsen the mesh");
  for (int k = 0; k < refine; ++k) e = split_nested(e);
  return e;
}

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
