// Thermal residual stress of a periodic cell under a uniform temperature change, and its
// effective thermal expansion, from the solved load cases by superposition.
//
// The thermal load case holds the cell at a mean strain e_T (near the free one) while the
// temperature changes by delta_T: its mean stress sigma_T. Free on average (zero mean
// stress), the cell takes e_T - C^-1 sigma_T (C the effective stiffness of the three
// mechanical cases), so a = (e_T - C^-1 sigma_T) / delta_T. The free state's fields are
// the thermal case's plus each mechanical case's scaled to the strain -C^-1 sigma_T:
// linear elasticity adds solutions. Under a mechanical load as well (load.displacement,
// the xx case's strain), the xx case is added once more: cooled, then pulled.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "analysis/bounds.hpp"
#include "analysis/foam_fields.hpp"
#include "analysis/homogenise.hpp"
#include "analysis/stress_measures.hpp"
#include "export/foam_material.hpp"

namespace grainmesh {

struct ThermalResidual {
  double delta_T = 0.0;                  // K
  std::array<double, 3> expansion{};     // a11, a22, a12 (tensor components), 1/K
  CaseFields fields;                     // the free state: displacement and stress
  std::vector<StressState> cell_stress;  // its recovered stress: the residual stress
  std::vector<StressState> virial_stress;  // and its virial stress (traction.hpp)
  CaseFields loaded_fields;              // the free state plus the xx load case
  std::vector<StressState> loaded_stress, loaded_virial_stress;
};

// From solved periodic cases with a thermal case (periodic_load_cases with delta_T).
// Throws GeometryError when there is none.
ThermalResidual thermal_residual(const PeriodicHomogenised& h);

// Levin's exact relation for two isotropic phases (any microstructure): a uniform
// in-plane pressure p that strains both phases alike, p / (2 k_i) + b_i delta_T equal for
// both (k = lambda + mu the in-plane bulk modulus, b the free in-plane expansion,
// free_expansion), leaves the whole cell uniformly strained; so the effective expansion
// is that uniform strain less what p does to the effective compliance S = C^-1:
//   P = -(b1 - b2) / (1 / (2 k1) - 1 / (2 k2)),
//   a = (b1 + P / (2 k1)) (1, 1, 0) - P S (1, 1, 0)   (Voigt: a11, a22, 2 a12),
// here with a12 the tensor component. None unless two phases with different k.
std::optional<std::array<double, 3>> levin_expansion(const std::vector<FoamPhase>& phases, const Stiffness<3>& c,
                                                     bool plane_stress);

}  // namespace grainmesh
