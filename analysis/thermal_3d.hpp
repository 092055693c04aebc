// Thermal residual stress of a periodic 3D cell under a uniform temperature change, and its
// effective thermal expansion tensor, by superposition of the solved load cases.
//
// The thermal case holds the cell at a mean strain e_T (the phases' mean free strain)
// while the temperature changes by delta_T: its mean stress sigma_T. Free on average, the
// cell takes e_T - C^-1 sigma_T (C the effective stiffness of the six mechanical cases),
// so alpha = (e_T - C^-1 sigma_T) / delta_T; the free state's fields are the thermal
// case's plus each mechanical case's scaled to the strain -C^-1 sigma_T.
#pragma once

#include <optional>
#include <vector>

#include "analysis/bounds.hpp"
#include "analysis/foam_fields.hpp"
#include "analysis/homogenise_3d.hpp"

namespace grainmesh {

struct ThermalResidual3 {
  double delta_T = 0.0;  // K
  Voigt6 expansion{};    // xx, yy, zz, yz, xz, xy tensor components, 1/K
  CaseFields fields;     // the free state: displacement and the whole stress (the residual stress)
  FieldValues virial_stress;  // and its cells' virial stresses (traction.hpp)
  // The free state with the xx case added once more: cooled, then pulled (load.displacement).
  CaseFields loaded_fields;
  FieldValues loaded_virial_stress;
};

// From solved periodic cases with a thermal case (periodic_load_cases with delta_T), and
// the stiffness to free it with (their symmetric part). Throws GeometryError when there
// is no thermal case.
ThermalResidual3 thermal_residual_3d(const PeriodicHomogenised3& h, const Stiffness<6>& stiffness);

// Levin's exact relation for two isotropic phases in any microstructure: a uniform
// pressure that strains both phases alike, s / (3 K_i) + alpha_i equal for both (per
// kelvin; K = lambda + 2 mu / 3), leaves the whole cell uniformly strained, so the
// effective expansion is that strain less what s does to the effective compliance:
//   s = (alpha_2 - alpha_1) / (1 / (3 K_1) - 1 / (3 K_2)),
//   alpha = (alpha_1 + s / (3 K_1)) I - s C^-1 I   (tensor components).
// None unless two phases with different K.
std::optional<Voigt6> levin_expansion_3d(const std::vector<FoamPhase>& phases, const Stiffness<6>& c);

}  // namespace grainmesh
