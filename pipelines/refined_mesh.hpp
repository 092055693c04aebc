// A run's exported mesh refined as mesh.refine asks (nested_split.hpp), with the check
// that the refinement is not a slip.
#pragma once

#include <cmath>
#include <string>

#include "common/format.hpp"
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

}  // namespace grainmesh
