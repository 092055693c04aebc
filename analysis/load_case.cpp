#include "analysis/load_case.hpp"

namespace grainmesh {

template <std::size_t N>
std::vector<LoadCase<N>> mechanical_load_cases(double e) {
  std::vector<LoadCase<N>> cases;
  for (std::size_t k = 0; k < N; ++k) {
    LoadCase<N> c{voigt_names<N>()[k], {}};
    c.strain[k] = k < voigt_dimensions<N>() ? e : 0.5 * e;
    cases.push_back(c);
  }
  return cases;
}

template <std::size_t N>
LoadCase<N> thermal_load_case(double free, double delta_T) {
  LoadCase<N> c{"thermal", {}, delta_T};
  for (std::size_t k = 0; k < voigt_dimensions<N>(); ++k) c.strain[k] = free;
  return c;
}

template <std::size_t N>
FoamOptions load_case_options(const FoamOptions& o, const LoadCase<N>& c) {
  FoamOptions out = o;
  out.cyclic = true;
  if constexpr (N == 3)
    out.strain = {c.strain[0], c.strain[1], 0.0, 0.0, 0.0, c.strain[2]};
  else
    out.strain = c.strain;
  out.delta_T = c.delta_T;
  return out;
}

template std::vector<LoadCase<3>> mechanical_load_cases(double);
template std::vector<LoadCase<6>> mechanical_load_cases(double);
template LoadCase<3> thermal_load_case(double, double);
template LoadCase<6> thermal_load_case(double, double);
template FoamOptions load_case_options(const FoamOptions&, const LoadCase<3>&);
template FoamOptions load_case_options(const FoamOptions&, const LoadCase<6>&);

}  // namespace grainmesh
