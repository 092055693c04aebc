// A solved state of a cell and the solved load cases of its periodic homogenisation, one
// type for 2D and 3D (N the Voigt size: 3 in 2D, 6 in 3D, as Stiffness<N>). A state holds
// OpenFOAM's cell fields and each cell's virial stress from its face forces
// (traction.hpp), and in 2D the cell stresses recovered phase by phase with the plane
// state's sigma_zz (stress_recovery.hpp); in 3D the cells' stress is OpenFOAM's own.
// States superpose: linear elasticity adds solutions (the thermal residual, thermal.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "analysis/foam_fields.hpp"
#include "analysis/load_case.hpp"
#include "analysis/solve.hpp"
#include "analysis/stress_measures.hpp"
#include "analysis/voigt.hpp"

namespace grainmesh {

template <std::size_t N>
struct SolvedState;

template <>
struct SolvedState<3> {
  CaseFields fields;                       // displacement and OpenFOAM's stress per cell
  std::vector<StressState> cell_stress;    // recovered phase by phase (stress_recovery.hpp)
  std::vector<StressState> virial_stress;  // from the face forces (DiscreteTraction::virial_stress)
};

template <>
struct SolvedState<6> {
  CaseFields fields;          // displacement and the cells' stress
  FieldValues virial_stress;  // from the face forces (DiscreteTraction::virial_stress_tensor)
};

// The sum of weight x state over `terms` (at least one), field by field.
template <std::size_t N>
SolvedState<N> superposed(const std::vector<std::pair<double, const SolvedState<N>*>>& terms);

// Each cell's stress tensor in `s` (2D: the recovered one, its sigma_zz the plane state's;
// 3D: OpenFOAM's); with `virial`, each cell's virial stress instead (2D: in plane, sigma_zz
// still the recovered one).
template <std::size_t N>
std::vector<StressTensor> cell_stress_tensors(const SolvedState<N>& s, bool virial = false);

// A solved periodic load case: its state, the mean stress from the forces through the
// sides (exact for the discrete solution), the volume (2D: area) average of the cell
// stresses beside it (biased: it mixes the phases in cells next to interfaces), and the
// solver's run.
template <std::size_t N>
struct LoadCaseResult : SolvedState<N> {
  LoadCase<N> load;
  std::array<double, N> stress{};          // Pa, Voigt order (tensor components)
  std::array<double, N> volume_average{};  // Pa
  SolveRun run;
};

// The thesis' mixed load solved (right pulled, symmetry planes elsewhere; its virial
// stresses not computed): the force through `right` over its area, the imposed mean
// strain (displacement / width), their ratio the modulus (2D: plane strain or stress; 3D:
// under uniaxial strain, C11 of an isotropic cell), and the same from the volume (2D:
// area) average of the cell stresses (biased, as a load case's).
template <std::size_t N>
struct MixedHomogenised : SolvedState<N> {
  double sigma_xx = 0.0;                   // Pa
  double strain_xx = 0.0;
  double modulus = 0.0;                    // sigma_xx / strain_xx, Pa
  std::array<double, N> volume_average{};  // Pa, Voigt order
  double volume_average_modulus = 0.0;     // volume_average[0] / strain_xx, Pa
  SolveRun run;
};

template <std::size_t N>
struct PeriodicHomogenised {
  std::vector<LoadCaseResult<N>> cases;    // as periodic_load_cases: the mechanical ones, then thermal
  Stiffness<N> stiffness{};                // column j from load case j (per engineering strain), as solved
  Stiffness<N> volume_average_stiffness{};  // the same from the volume averages
};

// Fills h.stiffness and h.volume_average_stiffness from h.cases: column k is case k's
// stress over its strain, the shears' per engineering strain (twice the tensor component).
template <std::size_t N>
void assemble_stiffness(PeriodicHomogenised<N>& h);

}  // namespace grainmesh
