// Bounds on effective elastic properties from the phases and their area (2D) or volume
// (3D) fractions: Voigt (uniform strain) and Reuss (uniform stress) tensors for every
// microstructure, and the Hashin-Shtrikman bounds on the bulk and shear moduli of two
// isotropic phases (for a statistically isotropic microstructure), in the dimension of the
// stiffness: N = 3 in 2D (plane strain or plane stress), N = 6 in 3D. Defined for N = 3, 6.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "analysis/voigt.hpp"
#include "export/foam_material.hpp"

namespace grainmesh {

// The stiffness of an isotropic phase: lambda + 2 mu on the normal diagonal, lambda off
// it, mu for each shear; in 2D lambda is plane strain's or plane stress's (lame), in 3D
// plane_stress is not used.
template <std::size_t N>
Stiffness<N> isotropic_stiffness(const FoamPhase& phase, bool plane_stress = false);

template <std::size_t N>
struct TensorBounds {
  Stiffness<N> voigt{}, reuss{};
  std::optional<double> bulk_lower, bulk_upper, shear_lower, shear_upper;  // Hashin-Shtrikman, two phases
};
// The bounds of `phases` at `fractions` (one per phase, summing to 1). Hashin-Shtrikman
// when there are two phases, the one stiffer in shear stiffer in bulk too (well-ordered);
// in d dimensions, with the reference phase r and the other o:
//   K = K_r + f_o / (1 / (K_o - K_r) + f_r / (K_r + 2 (d - 1) mu_r / d)),
//   mu = mu_r + f_o / (1 / (mu_o - mu_r) + f_r / (mu_r + H_r)),
//   H_r = mu_r (d K_r / 2 + (d + 1)(d - 2) mu_r / d) / (K_r + 2 mu_r),
// the upper bound with the stiffer phase as reference, the lower with the softer (K the
// 2D bulk modulus lambda + mu in 2D, lambda + 2 mu / 3 in 3D).
template <std::size_t N>
TensorBounds<N> tensor_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                              bool plane_stress = false);

// Bounds on sigma_xx / eps_xx for the thesis' 2D load (the `mixed` boundary): eps_xx
// imposed, the mean eps_yy zero (symmetry top and bottom), plane strain (or stress).
struct ElasticBounds {
  double voigt = 0.0;     // uniform strain: <M>
  double reuss = 0.0;     // uniform stress with zero mean eps_yy
  std::optional<double> hs_lower, hs_upper;  // two isotropic phases: Hashin-Shtrikman (2D)
};
ElasticBounds elastic_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                             bool plane_stress);

// The bounds on the mixed load's modulus in the dimension of N: in 2D (N = 3)
// elastic_bounds; in 3D (N = 6), under uniaxial strain, the Voigt and Reuss tensors' C11
// (no Hashin-Shtrikman: the load is no isotropic modulus).
template <std::size_t N>
ElasticBounds mixed_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                           bool plane_stress = false);

}  // namespace grainmesh
