// A periodic load case, the same in 2D and 3D: a macroscopic strain imposed as the jump of
// the displacement across the cyclic pairs (Voigt tensor components, N = 3: xx, yy, xy;
// N = 6: xx, yy, zz, yz, xz, xy) and a temperature change; its case directory and the
// options its case is written and solved with. The load cases of a cell are made by
// periodic_load_cases (homogenise.hpp for 2D cells, homogenise_3d.hpp for 3D ones).
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "export/foam_options.hpp"

namespace grainmesh {

template <std::size_t N>
struct LoadCase {
  std::string name;               // xx ... xy, thermal: also the case directory's suffix
  std::array<double, N> strain{};  // tensor components
  double delta_T = 0.0;           // K
};

// The case directory of a load case: case_NAME.
template <std::size_t N>
std::string load_case_dir(const LoadCase<N>& c) {
  return "case_" + c.name;
}

// The case directories of `cases` under `dir`, in their order.
template <std::size_t N>
std::vector<std::filesystem::path> load_case_dirs(const std::vector<LoadCase<N>>& cases,
                                                  const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  for (const LoadCase<N>& c : cases) out.push_back(dir / load_case_dir(c));
  return out;
}

// The options a load case's case is written and solved with: `o`'s, cyclic, the case's
// strain (in 2D xx, yy, xy of the 3D tensor) and temperature change.
template <std::size_t N>
FoamOptions load_case_options(const FoamOptions& o, const LoadCase<N>& c);

}  // namespace grainmesh
