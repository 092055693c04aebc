#include "export/foam_material.hpp"

#include <algorithm>

namespace grainmesh {

Lame lame(const FoamPhase& p, bool plane_stress) {
  const double E = p.youngs_modulus, nu = p.poisson_ratio;
  return {plane_stress ? E * nu / ((1 + nu) * (1 - nu)) : E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
}

double thermal_stress_per_kelvin(const FoamPhase& p, bool plane_stress) {
  const double E = p.youngs_modulus, nu = p.poisson_ratio;
  return (plane_stress ? E / (1 - nu) : E / (1 - 2 * nu)) * p.alpha;
}

double free_expansion(const FoamPhase& p, bool plane_stress) {
  return plane_stress ? p.alpha : (1 + p.poisson_ratio) * p.alpha;
}

std::vector<double> thermal_stress(const std::vector<FoamPhase>& phases, const std::vector<int>& cell_phase,
                                   const FoamOptions& o) {
  std::vector<double> per_phase;
  for (const FoamPhase& p : phases) per_phase.push_back(thermal_stress_per_kelvin(p, o.plane_stress) * o.delta_T);
  std::vector<double> out(cell_phase.size());
  for (std::size_t t = 0; t < out.size(); ++t) out[t] = per_phase[static_cast<std::size_t>(cell_phase[t])];
  return out;
}

double stiffness_contrast(const std::vector<FoamPhase>& phases, const FoamOptions& o) {
  double stiff_min = 1e300, stiff_max = 0.0;
  for (const FoamPhase& p : phases) {
    const double stiffness = lame(p, o.plane_stress).gamma();
    stiff_min = std::min(stiff_min, stiffness);
    stiff_max = std::max(stiff_max, stiffness);
  }
  return stiff_max / stiff_min;
}

std::vector<FoamPhase> foam_phases(const std::vector<Phase>& phases) {
  std::vector<FoamPhase> out;
  for (const Phase& p : phases) out.push_back({p.name, p.youngs_modulus, p.poisson_ratio, p.alpha.value_or(0.0)});
  return out;
}

}  // namespace grainmesh
