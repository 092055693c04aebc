// Bounds on the effective stiffness of a 3D cell from its phases and their volume
// fractions: Voigt (uniform strain) and Reuss (uniform stress) tensors for every
// microstructure, and the Hashin-Shtrikman bounds on the bulk and shear moduli of two
// isotropic phases (for a statistically isotropic microstructure).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "export/foam.hpp"

namespace grainmesh {

// A stiffness in Voigt notation: rows and columns xx, yy, zz, yz, xz, xy, the shears as
// engineering strains (sigma_yz = C44 gamma_yz), in Pa.
using Stiffness6 = std::array<std::array<double, 6>, 6>;

// The stiffness of an isotropic phase: lambda = E nu / ((1 + nu)(1 - 2 nu)), mu =
// E / (2 (1 + nu)).
Stiffness6 isotropic_stiffness_3d(const FoamPhase& phase);

// The inverse (a compliance, and back), by Gauss-Jordan elimination with partial
// pivoting. Throws GeometryError when singular.
Stiffness6 inverse(const Stiffness6& c);

// Whether upper - lower (its symmetric part) is positive semidefinite, to `rounding`
// relative to the largest entry: its symmetric LDL^T factorisation meets no pivot below
// -rounding x scale.
bool semidefinite_order(const Stiffness6& lower, const Stiffness6& upper, double rounding = 1e-6);

struct TensorBounds3 {
  Stiffness6 voigt{}, reuss{};
  std::optional<double> bulk_lower, bulk_upper, shear_lower, shear_upper;  // Hashin-Shtrikman, two phases
};
TensorBounds3 tensor_bounds_3d(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions);

// The bulk and shear moduli of a stiffness isotropic in the mean (Voigt's averages over
// orientations): K = (C11 + C22 + C33 + 2 (C12 + C13 + C23)) / 9, mu = (C11 + C22 + C33 -
// (C12 + C13 + C23) + 3 (C44 + C55 + C66)) / 15. Exact for an isotropic stiffness.
double bulk_modulus_3d(const Stiffness6& c);
double shear_modulus_3d(const Stiffness6& c);

}  // namespace grainmesh
