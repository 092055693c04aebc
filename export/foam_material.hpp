// The phases' elastic and thermal constants as a solidDisplacementFoam case carries them,
// and what follows from them: Lame constants, the thermal stress per kelvin, the free
// expansion (plane strain or plane stress in 2D), the stiffness contrast.
#pragma once

#include <string>
#include <vector>

#include "export/foam_options.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

struct FoamPhase {
  std::string name;
  double youngs_modulus = 0.0;  // E, Pa
  double poisson_ratio = 0.0;   // nu, in (-1, 0.5)
  double alpha = 0.0;           // linear thermal expansion, 1/K
};

// A phase's in-plane Lame constants as solidDisplacementFoam has them (rho = 1): mu =
// E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)) in plane strain, E nu / ((1 +
// nu)(1 - nu)) in plane stress; gamma = 2 mu + lambda is the stiffness its implicit
// operator carries.
struct Lame {
  double lambda = 0.0, mu = 0.0;
  double gamma() const { return lambda + 2 * mu; }
};
Lame lame(const FoamPhase& phase, bool plane_stress);

// The stress a phase's free thermal strain would carry per kelvin of temperature change,
// as solidDisplacementFoam has it: threeK alpha, threeK = E / (1 - 2 nu) in plane strain
// (3 lambda + 2 mu), E / (1 - nu) in plane stress (the in-plane 2 (lambda + mu)). The
// stress is C : grad(D) - threeK alpha delta_T I (plane stress: its in-plane part).
double thermal_stress_per_kelvin(const FoamPhase& phase, bool plane_stress);
// The in-plane strain a phase takes when free to expand, per kelvin: (1 + nu) alpha under
// plane strain (held out of plane), alpha under plane stress. (In 3D: alpha itself.)
double free_expansion(const FoamPhase& phase, bool plane_stress);
// Per cell (cell_phase, an index into `phases`): threeK alpha delta_T of its phase (Pa),
// what the solver's sigmaD leaves out of the stress; all zero without a temperature change.
std::vector<double> thermal_stress(const std::vector<FoamPhase>& phases, const std::vector<int>& cell_phase,
                                   const FoamOptions& options);

// The ratio of the stiffest phase's 2 mu + lambda to the softest's (plane strain unless
// options.plane_stress).
double stiffness_contrast(const std::vector<FoamPhase>& phases, const FoamOptions& options);

// The phases' elastic constants as the case carries them.
std::vector<FoamPhase> foam_phases(const std::vector<Phase>& phases);

}  // namespace grainmesh
