#include "analysis/thermal_3d.hpp"

#include <cmath>

#include "common/errors.hpp"

namespace grainmesh {

ThermalResidual3 thermal_residual_3d(const PeriodicHomogenised3& h, const Stiffness<6>& stiffness) {
  if (h.cases.size() != 7 || h.cases[6].load.delta_T == 0.0)
    throw GeometryError("thermal_residual_3d: the load cases hold no thermal case");
  const LoadCaseResult3& thermal = h.cases[6];
  ThermalResidual3 r;
  r.delta_T = thermal.load.delta_T;
  // The (engineering) strain that takes the thermal case's mean stress off: C e = -sigma_T.
  const Stiffness<6> S = inverse(stiffness);
  Voigt6 e{};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) e[i] -= S[i][j] * thermal.stress[j];
  std::vector<std::pair<double, const CaseFields*>> terms{{1.0, &thermal.fields}};
  std::vector<std::pair<double, const FieldValues*>> virial{{1.0, &thermal.virial_stress}};
  for (int k = 0; k < 6; ++k) {
    const double tensor = k < 3 ? e[k] : 0.5 * e[k];
    r.expansion[k] = (thermal.load.strain[k] + tensor) / r.delta_T;
    // Each mechanical case's weight: that strain over the case's own (both tensor components).
    terms.push_back({tensor / h.cases[k].load.strain[k], &h.cases[k].fields});
    virial.push_back({terms.back().first, &h.cases[k].virial_stress});
  }
  r.fields = superposed(terms);
  r.virial_stress = superposed(virial);
  terms[1].first += 1.0;
  virial[1].first += 1.0;
  r.loaded_fields = superposed(terms);
  r.loaded_virial_stress = superposed(virial);
  return r;
}

std::optional<Voigt6> levin_expansion_3d(const std::vector<FoamPhase>& phases, const Stiffness<6>& c) {
  if (phases.size() != 2) return std::nullopt;
  std::array<double, 2> compliance{};  // 1 / (3 K)
  for (int i = 0; i < 2; ++i) {
    const Lame l = lame(phases[i], /*plane_stress=*/false);
    compliance[i] = 1.0 / (3.0 * l.lambda + 2.0 * l.mu);
  }
  const double dk = compliance[0] - compliance[1];
  if (std::abs(dk) <= 1e-12 * (compliance[0] + compliance[1])) return std::nullopt;
  const double s = (phases[1].alpha - phases[0].alpha) / dk;
  const double uniform = phases[0].alpha + s * compliance[0];
  const Stiffness<6> S = inverse(c);
  Voigt6 a{};
  for (int i = 0; i < 6; ++i) a[i] = (i < 3 ? uniform : 0.0) - s * (S[i][0] + S[i][1] + S[i][2]) * (i < 3 ? 1.0 : 0.5);
  return a;
}

}  // namespace grainmesh
