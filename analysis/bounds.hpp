// Bounds on effective elastic properties from the phases and their area fractions:
// Voigt (uniform strain) and Reuss (uniform stress) for every microstructure, and the
// two-dimensional Hashin-Shtrikman bounds on the bulk and shear moduli of two isotropic
// phases (for a statistically isotropic microstructure).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "export/foam.hpp"

namespace grainmesh {

// An in-plane stiffness in Voigt notation: rows and columns xx, yy, xy, the shear as
// engineering strain (sigma_xy = C66 gamma_xy), in Pa; plane strain or plane stress.
using Stiffness = std::array<std::array<double, 3>, 3>;

// The stiffness of an isotropic phase.
Stiffness isotropic_stiffness(const FoamPhase& phase, bool plane_stress);

// The inverse of a stiffness (a compliance, and back). Throws GeometryError when singular.
Stiffness inverse(const Stiffness& c);

// Whether upper - lower is positive semidefinite (its symmetric part), to `rounding`
// relative to the largest entry.
bool semidefinite_order(const Stiffness& lower, const Stiffness& upper, double rounding = 1e-6);

struct TensorBounds {
  Stiffness voigt{}, reuss{};
  std::optional<double> bulk_lower, bulk_upper, shear_lower, shear_upper;  // Hashin-Shtrikman, two phases
};
TensorBounds tensor_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                           bool plane_stress);

// The in-plane bulk and shear moduli of a stiffness, isotropic in the mean: K the mean
// stress over the area strain, (C11 + C22 + C12 + C21) / 4; mu the mean of the shear
// stiffness in the axes and at 45 degrees, C66 / 2 + (C11 + C22 - C12 - C21) / 8.
double bulk_modulus(const Stiffness& c);
double shear_modulus(const Stiffness& c);

// Bounds on sigma_xx / eps_xx for the thesis' load (the `mixed` boundary): eps_xx
// imposed, the mean eps_yy zero (symmetry top and bottom), plane strain (or stress).
struct ElasticBounds {
  double voigt = 0.0;     // uniform strain: <M>
  double reuss = 0.0;     // uniform stress with zero mean eps_yy
  std::optional<double> hs_lower, hs_upper;  // two isotropic phases: Hashin-Shtrikman (2D)
};
ElasticBounds elastic_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                             bool plane_stress);

}  // namespace grainmesh
