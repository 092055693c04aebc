// Thermal residual stress of a periodic cell under a uniform temperature change, and its
// effective thermal expansion, from the solved load cases by superposition; one contract
// for 2D and 3D (N the Voigt size: 3 in 2D, 6 in 3D).
//
// The thermal load case holds the cell at a mean strain e_T (the phases' mean free strain)
// while the temperature changes by delta_T: its mean stress sigma_T. Free on average (zero
// mean stress), the cell takes e_T - C^-1 sigma_T (C the effective stiffness of the
// mechanical cases), so alpha = (e_T - C^-1 sigma_T) / delta_T. The free state is the
// thermal case's plus each mechanical case's scaled to the strain -C^-1 sigma_T: linear
// elasticity adds solutions. Under a mechanical load as well (load.displacement, the xx
// case's strain), the xx case is added once more: cooled, then pulled.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "analysis/solved_state.hpp"
#include "analysis/voigt.hpp"
#include "export/foam_material.hpp"

namespace grainmesh {

template <std::size_t N>
struct ThermalResidual {
  double delta_T = 0.0;              // K
  std::array<double, N> expansion{};  // tensor components (2D: a11, a22, a12), 1/K
  SolvedState<N> free;               // the free state: its stress is the residual stress
  SolvedState<N> loaded;             // the free state plus the xx load case
};

// From solved periodic cases with a thermal case last (periodic_load_cases with delta_T),
// freed with the stiffness as solved (h.stiffness, not its symmetric part): its columns
// are the mechanical cases' own mean stresses, so the free state's mean stress is zero to
// rounding (the symmetric part would leave the symmetry error's share of sigma_T). Throws
// GeometryError when there is no thermal case.
template <std::size_t N>
ThermalResidual<N> thermal_residual(const PeriodicHomogenised<N>& h);

// Levin's exact relation for two isotropic phases (any microstructure): a uniform pressure
// p that strains both phases alike, p / (d K_i) + b_i delta_T equal for both (d the
// dimensions, K the bulk modulus in them: 2D lambda + mu, 3D lambda + 2 mu / 3; b the free
// expansion, free_expansion in 2D, alpha in 3D), leaves the whole cell uniformly strained,
// so the effective expansion is that uniform strain less what p does to the effective
// compliance S = C^-1:
//   P = -(b1 - b2) / (1 / (d K1) - 1 / (d K2)),
//   a = (b1 + P / (d K1)) I - P S I   (I the unit tensor in Voigt order),
// the shears as tensor components. None unless two phases with different K. `plane_stress`
// for 2D only.
template <std::size_t N>
std::optional<std::array<double, N>> levin_expansion(const std::vector<FoamPhase>& phases, const Stiffness<N>& c,
                                                     bool plane_stress = false);

}  // namespace grainmesh
