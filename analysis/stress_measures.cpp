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

double von_mises(const StressTensor& s) {
  const auto [xx, yy, zz, yz, xz, xy] = s;
  return std::sqrt(0.5 * ((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx)) +
                   3.0 * (xy * xy + yz * yz + xz * xz));
}

double largest_principal(const StressTensor& s) {
  const auto [xx, yy, zz, yz, xz, xy] = s;
  if (yz == 0.0 && xz == 0.0) return largest_principal(StressState{xx, yy, zz, xy});
  // Eigenvalues of a symmetric 3 x 3: m + 2 sqrt(p) cos(phi + 2 pi k / 3), the largest k = 0.
  const double m = (xx + yy + zz) / 3.0;
  const double a = xx - m, b = yy - m, c = zz - m;
  const double p = (a * a + b * b + c * c + 2.0 * (xy * xy + yz * yz + xz * xz)) / 6.0;
  if (p == 0.0) return m;
  const double det = a * (b * c - yz * yz) - xy * (xy * c - yz * xz) + xz * (xy * yz - b * xz);
  const double r = std::clamp(det / (2.0 * p * std::sqrt(p)), -1.0, 1.0);
  return m + 2.0 * std::sqrt(p) * std::cos(std::acos(r) / 3.0);
}

double hydrostatic(const StressTensor& s) { return (s[0] + s[1] + s[2]) / 3.0; }

StressTensor stress_tensor(const StressState& s) { return {s.xx, s.yy, s.zz, 0.0, 0.0, s.xy}; }

std::vector<StressTensor> stress_tensors(const std::vector<StressState>& own, const std::vector<StressState>* virial) {
  std::vector<StressTensor> out;
  out.reserve(own.size());
  for (std::size_t k = 0; k < own.size(); ++k) {
    const StressState& b = virial ? (*virial)[k] : own[k];
    out.push_back({b.xx, b.yy, own[k].zz, 0.0, 0.0, b.xy});
  }
  return out;
}

StressTensor openfoam_stress(const double* s) { return {s[0], s[3], s[5], s[4], s[2], s[1]}; }

}  // namespace grainmesh
