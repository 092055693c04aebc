#include "analysis/load_case.hpp"

namespace grainmesh {

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

template FoamOptions load_case_options(const FoamOptions&, const LoadCase<3>&);
template FoamOptions load_case_options(const FoamOptions&, const LoadCase<6>&);

}  // namespace grainmesh
