#include "analysis/stress_measures.hpp"

#include <algorithm>
#include <cmath>

namespace grainmesh {

double von_mises(const StressState& s) {
  const double a = s.xx - s.yy, b = s.yy - s.zz, c = s.zz - s.xx;
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * s.xy * s.xy);
}

double largest_principal(const StressState& s) {
  const double in_plane = 0.5 * (s.xx + s.yy) + std::hypot(0.5 * (s.xx - s.yy), s.xy);
  return std::max(in_plane, s.zz);
}

double hydrostatic(const StressState& s) { return (s.xx + s.yy + s.zz) / 3.0; }

std::array<double, 6> vtk_components(const StressState& s) { return {s.xx, s.yy, s.zz, s.xy, 0.0, 0.0}; }

}  // namespace grainmesh
