#include "analysis/thermal.hpp"

#include <cmath>

#include "common/errors.hpp"

namespace grainmesh {

namespace {

std::vector<StressState> superposed(const std::vector<std::pair<double, const std::vector<StressState>*>>& terms) {
  std::vector<StressState> out(terms.front().second->size());
  for (const auto& [weight, states] : terms)
    for (std::size_t t = 0; t < out.size(); ++t) {
      const StressState& s = (*states)[t];
      out[t].xx += weight * s.xx, out[t].yy += weight * s.yy, out[t].zz += weight * s.zz, out[t].xy += weight * s.xy;
    }
  return out;
}

}  // namespace

ThermalResidual thermal_residual(const PeriodicHomogenised& h) {
  if (h.cases.size() != 4 || h.cases[3].load.delta_T == 0.0)
    throw GeometryError("thermal_residual: the load cases hold no thermal case");
  const LoadCaseResult& thermal = h.cases[3];
  ThermalResidual r;
  r.delta_T = thermal.load.delta_T;
  // The strain that takes the thermal case's mean stress off: C e = -sigma_T, e in Voigt
  // (engineering shear).
  const Stiffness<3> S = inverse(h.stiffness);
  const std::array<double, 3> sigma{thermal.stress.xx, thermal.stress.yy, thermal.stress.xy};
  std::array<double, 3> e{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) e[i] -= S[i][j] * sigma[j];
  const std::array<double, 3> mean_strain{e[0], e[1], 0.5 * e[2]};  // tensor components
  for (int k = 0; k < 3; ++k) r.expansion[k] = (thermal.load.strain[k] + mean_strain[k]) / r.delta_T;
  // Each mechanical case's weight: that strain over the case's own.
  std::vector<std::pair<double, const CaseFields*>> fields{{1.0, &thermal.fields}};
  std::vector<std::pair<double, const std::vector<StressState>*>> stress{{1.0, &thermal.cell_stress}},
      virial{{1.0, &thermal.virial_stress}};
  for (int k = 0; k < 3; ++k) {
    const LoadCaseResult& c = h.cases[k];
    const double weight = mean_strain[k] / c.load.strain[k];
    fields.push_back({weight, &c.fields});
    stress.push_back({weight, &c.cell_stress});
    virial.push_back({weight, &c.virial_stress});
  }
  r.fields = superposed(fields);
  r.cell_stress = superposed(stress);
  r.virial_stress = superposed(virial);
  fields[1].first += 1.0;
  stress[1].first += 1.0;
  virial[1].first += 1.0;
  r.loaded_fields = superposed(fields);
  r.loaded_stress = superposed(stress);
  r.loaded_virial_stress = superposed(virial);
  return r;
}

std::optional<std::array<double, 3>> levin_expansion(const std::vector<FoamPhase>& phases, const Stiffness<3>& c,
                                                     bool plane_stress) {
  if (phases.size() != 2) return std::nullopt;
  std::array<double, 2> k{}, b{};
  for (int i = 0; i < 2; ++i) {
    const Lame l = lame(phases[i], plane_stress);
    k[i] = l.lambda + l.mu;
    b[i] = free_expansion(phases[i], plane_stress);
  }
  const double dk = 1 / (2 * k[0]) - 1 / (2 * k[1]);
  if (std::abs(dk) <= 1e-12 * (1 / (2 * k[0]) + 1 / (2 * k[1]))) return std::nullopt;
  const double P = -(b[0] - b[1]) / dk;
  const double uniform = b[0] + P / (2 * k[0]);
  const Stiffness<3> S = inverse(c);
  std::array<double, 3> a{};
  for (int i = 0; i < 3; ++i) a[i] = (i < 2 ? uniform : 0.0) - P * (S[i][0] + S[i][1]);
  a[2] *= 0.5;  // engineering to tensor shear
  return a;
}

}  // namespace grainmesh
