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

#include "analysis/voigt.hpp"
#include "export/foam_options.hpp"

namespace grainmesh {

template <std::size_t N>
struct LoadCase {
  std::string name;               // xx ... xy, thermal: also the case directory's suffix
  std::array<double, N> strain{};  // tensor components
  double delta_T = 0.0;           // K
};

// The mechanical load cases of a periodic cell at the mean strain e: one per Voigt
// component, in its order and named by it, e in a normal component, an engineering shear
// e (the tensor component e / 2) in a shear one.
template <std::size_t N>
std::vector<LoadCase<N>> mechanical_load_cases(double e);

// The thermal load case, `thermal`: the temperature change delta_T at the strain `free` in
// every normal direction (the phases' mean free strain), no shear.
template <std::size_t N>
LoadCase<N> thermal_load_case(double free, double delta_T);

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
