// Synthetic solved periodic cases of a known stiffness (no solver), for the tests of the
// periodic bookkeeping and of the answer built from it, in 2D (N = 3) and 3D (N = 6).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "analysis/load_case.hpp"
#include "analysis/solved_state.hpp"
#include "analysis/voigt.hpp"

namespace grainmesh::test {

// A symmetric positive definite stiffness with every entry nonzero (Pa).
template <std::size_t N>
Stiffness<N> anisotropic_stiffness() {
  Stiffness<N> c{};
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) c[i][j] = i == j ? 500e9 + 40e9 * i : 30e9 + 7e9 * (i + j);
  return c;
}

// C applied to a strain in tensor components (the shears doubled to engineering ones).
template <std::size_t N>
std::array<double, N> stress_of(const Stiffness<N>& c, const std::array<double, N>& strain) {
  std::array<double, N> s{};
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) s[i] += c[i][j] * (j < voigt_dimensions<N>() ? 1.0 : 2.0) * strain[j];
  return s;
}

// The cases a cell of stiffness C gives under mechanical_load_cases(e), and, heated by
// delta_T with a free expansion alpha in every normal direction, the thermal case held at
// the strain `held`. Each case's state: one cell whose displacement is its load's strain.
template <std::size_t N>
PeriodicHomogenised<N> synthetic_cases(const Stiffness<N>& c, double e, double alpha, double delta_T, double held) {
  PeriodicHomogenised<N> h;
  std::vector<LoadCase<N>> loads = mechanical_load_cases<N>(e);
  loads.push_back(thermal_load_case<N>(held, delta_T));
  for (const LoadCase<N>& load : loads) {
    LoadCaseResult<N> r;
    r.load = load;
    std::array<double, N> elastic = load.strain;  // the strain less the free expansion
    for (std::size_t k = 0; k < voigt_dimensions<N>(); ++k) elastic[k] -= alpha * load.delta_T;
    r.stress = stress_of(c, elastic);
    r.volume_average = r.stress;
    r.fields.displacement = FieldValues{.width = static_cast<int>(N), .values = std::vector<double>(load.strain.begin(), load.strain.end())};
    r.fields.stress = FieldValues{.width = static_cast<int>(N), .values = std::vector<double>(r.stress.begin(), r.stress.end())};
    h.cases.push_back(r);
  }
  assemble_stiffness(h);
  return h;
}

}  // namespace grainmesh::test
