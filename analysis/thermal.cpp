#include "analysis/thermal.hpp"

#include <cmath>

#include "common/errors.hpp"

namespace grainmesh {

template <std::size_t N>
ThermalResidual<N> thermal_residual(const PeriodicHomogenised<N>& h) {
  if (h.cases.size() != N + 1 || h.cases[N].load.delta_T == 0.0)
    throw GeometryError("thermal_residual: the load cases hold no thermal case");
  constexpr std::size_t normals = voigt_dimensions<N>();
  const LoadCaseResult<N>& thermal = h.cases[N];
  ThermalResidual<N> r;
  r.delta_T = thermal.load.delta_T;
  // The (engineering) strain that takes the thermal case's mean stress off: C e = -sigma_T.
  const Stiffness<N> S = inverse(h.stiffness);
  std::array<double, N> e{};
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) e[i] -= S[i][j] * thermal.stress[j];
  std::vector<std::pair<double, const SolvedState<N>*>> terms{{1.0, &thermal}};
  for (std::size_t k = 0; k < N; ++k) {
    const double tensor = k < normals ? e[k] : 0.5 * e[k];
    r.expansion[k] = (thermal.load.strain[k] + tensor) / r.delta_T;
    // Each mechanical case's weight: that strain over the case's own (both tensor components).
    terms.push_back({tensor / h.cases[k].load.strain[k], &h.cases[k]});
  }
  r.free = superposed(terms);
  terms[1].first += 1.0;
  r.loaded = superposed(terms);
  return r;
}

template <std::size_t N>
std::optional<std::array<double, N>> levin_expansion(const std::vector<FoamPhase>& phases, const Stiffness<N>& c,
                                                     bool plane_stress) {
  if (phases.size() != 2) return std::nullopt;
  constexpr std::size_t normals = voigt_dimensions<N>();
  std::array<double, 2> compliance{}, b{};  // 1 / (d K) = 1 / (d lambda + 2 mu), the free expansion
  for (int i = 0; i < 2; ++i) {
    const Lame l = lame(phases[i], plane_stress);
    compliance[i] = 1.0 / (static_cast<double>(normals) * l.lambda + 2.0 * l.mu);
    // In 2D the in-plane free expansion under the plane state; in 3D alpha itself.
    b[i] = N == 3 ? free_expansion(phases[i], plane_stress) : phases[i].alpha;
  }
  const double dk = compliance[0] - compliance[1];
  if (std::abs(dk) <= 1e-12 * (compliance[0] + compliance[1])) return std::nullopt;
  const double P = (b[1] - b[0]) / dk;
  const double uniform = b[0] + P * compliance[0];
  const Stiffness<N> S = inverse(c);
  std::array<double, N> a{};
  for (std::size_t i = 0; i < N; ++i) {
    double row = 0.0;
    for (std::size_t j = 0; j < normals; ++j) row += S[i][j];
    a[i] = (i < normals ? uniform : 0.0) - P * row * (i < normals ? 1.0 : 0.5);
  }
  return a;
}

template ThermalResidual<3> thermal_residual(const PeriodicHomogenised<3>&);
template ThermalResidual<6> thermal_residual(const PeriodicHomogenised<6>&);
template std::optional<std::array<double, 3>> levin_expansion(const std::vector<FoamPhase>&, const Stiffness<3>&, bool);
template std::optional<std::array<double, 6>> levin_expansion(const std::vector<FoamPhase>&, const Stiffness<6>&, bool);

}  // namespace grainmesh
