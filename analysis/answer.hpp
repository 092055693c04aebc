// A solved cell's answer, typed, one contract for 2D and 3D (N the Voigt size: 3 in 2D,
// 6 in 3D): the effective properties of the mixed (thesis) load or of the periodic load
// cases, with the bounds that hold for them and the verdicts on them (verdicts.hpp), the
// thermal expansion beside Levin's exact relation, and the phases' stress statistics per
// solved state. Built here from the solved states; written into report.json by one
// serializer (pipelines/report_json.hpp) and printed from the type.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "analysis/bounds.hpp"
#include "analysis/engineering.hpp"
#include "analysis/fe_homogenise.hpp"
#include "analysis/load_case.hpp"
#include "analysis/phase_statistics.hpp"
#include "analysis/solve.hpp"
#include "analysis/solved_state.hpp"
#include "analysis/thermal.hpp"
#include "analysis/verdicts.hpp"
#include "export/foam_options.hpp"

namespace grainmesh {

// Where a warning on the answer sends the user (the docs section of the dimension): after
// a broken Voigt or Reuss bound (`see`: "see docs/run.md, Homogenisation"), after a broken
// Hashin-Shtrikman bound (`why` it may break), after an expansion off Levin's relation
// (`refine`: what to refine).
struct AnswerAdvice {
  std::string see, why, refine;
};

// The mixed load's answer: the modulus from the force (2D: in the plane state; 3D: under
// uniaxial strain), the mean stress and strain it is their ratio of, the volume (2D: area)
// average beside it, the solve; and, unless the load is uniaxial (the bounds are for the
// cell held sideways), the bounds that hold for it (mixed_bounds) and the verdict.
template <std::size_t N>
struct MixedAnswer {
  double modulus = 0.0, sigma_xx = 0.0, strain_xx = 0.0;  // Pa, Pa, 1
  std::array<double, N> volume_average{};                // Pa, Voigt order
  double volume_average_modulus = 0.0;                   // Pa
  SolveRun run;
  std::optional<ElasticBounds> bounds;
  std::optional<ModulusVerdict> verdict;
};

// A periodic load case as the answer keeps it: its load, its mean stress from the forces
// (Pa, Voigt order) and the solver's run.
template <std::size_t N>
struct SolvedLoadCase {
  LoadCase<N> load;
  std::array<double, N> stress{};
  SolveRun run;
};

// The free thermal expansion under delta_T (tensor components, 1/K) and Levin's exact
// relation beside it (two isotropic phases of different bulk moduli), with their
// difference (levin_difference); in 2D the plane state it is the in-plane expansion of
// (plane strain: the cell held out of plane).
template <std::size_t N>
struct ThermalAnswer {
  double delta_T = 0.0;
  std::array<double, N> expansion{};
  std::optional<std::array<double, N>> levin;
  double levin_difference = 0.0;  // when levin
  std::string plane_state;        // 2D: plane_strain or plane_stress; empty in 3D
};

// The finite-element reference beside a periodic answer (fe_homogenise.hpp) and how far
// the answer lies from it, relative: each stiffness entry's difference over the
// reference's entry, or over its largest entry where the entry is below a hundredth of it
// (couplings that vanish by symmetry); K's and G's over theirs; the expansion's by the
// same rule, over the largest of its normal components.
template <std::size_t N>
struct ReferenceAnswer {
  FeHomogenised<N> fe;
  Stiffness<N> stiffness{};  // fe's symmetric part
  double bulk_modulus = 0.0, shear_modulus = 0.0;
  Stiffness<N> stiffness_error{};
  double bulk_error = 0.0, shear_error = 0.0;
  std::optional<std::array<double, N>> expansion_error;
  // The farthest of K, G and the entries of their own scale: its name and |error|.
  std::string farthest;
  double farthest_error = 0.0;
};

// The periodic load cases' answer: the cases (mechanical ones, then the thermal one), the
// stiffness judged (verdict: the symmetric part, its symmetry error, K and G, inside the
// bounds), the bounds at the phases' `fractions`, the engineering constants, the stiffness
// from the cells' volume averages, and the thermal expansion under a temperature change.
template <std::size_t N>
struct PeriodicAnswer {
  std::vector<SolvedLoadCase<N>> cases;
  StiffnessVerdict<N> verdict;
  TensorBounds<N> bounds;
  std::vector<double> fractions;
  EngineeringConstants engineering;
  Stiffness<N> volume_average_stiffness{};  // symmetric part
  std::optional<ThermalAnswer<N>> thermal;
  std::optional<ReferenceAnswer<N>> reference;  // homogenise.reference = fe

  // The most corrections any case took.
  int corrections() const;
};

// The phases' stresses of one solved state, named as report.json's stresses: mixed, a
// load case's name, thermal (the residual stress), thermal_xx (cooled, then pulled).
struct StateStresses {
  std::string state;
  std::vector<PhaseStresses> phases;  // in the order of Answer::phase_names
};

template <std::size_t N>
struct Answer {
  std::variant<MixedAnswer<N>, PeriodicAnswer<N>> effective;
  std::vector<std::string> phase_names;
  std::vector<StateStresses> stresses;
};

// The mixed load's answer from its solve, the bounds at the phases' `fractions` (unless
// foam.uniaxial); a broken bound a warning in `warnings` ending in `advice`'s see (Voigt,
// Reuss) or why (Hashin-Shtrikman).
template <std::size_t N>
MixedAnswer<N> mixed_answer(const MixedHomogenised<N>& h, const std::vector<FoamPhase>& phases,
                            const std::vector<double>& fractions, const FoamOptions& foam, const AnswerAdvice& advice,
                            std::vector<std::string>& warnings);

// The periodic load cases' answer from their solve, with the thermal residual `thermal`
// when heated (thermal_residual(h)); the phases at `fractions` under foam's plane state
// (2D). A broken bound, and an expansion more than kLevinTolerance off Levin's relation,
// a warning in `warnings` ending in `advice`'s.
template <std::size_t N>
PeriodicAnswer<N> periodic_answer(const PeriodicHomogenised<N>& h, const ThermalResidual<N>* thermal,
                                  const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                                  const FoamOptions& foam, const AnswerAdvice& advice,
                                  std::vector<std::string>& warnings);

// The finite-element reference `fe` of the cell put beside the periodic answer `a`, with
// the answer's errors against it; an answer more than kReferenceTolerance off it (a
// stiffness entry of its own scale, K or G) a warning naming the farthest, ending in
// `advice`'s see.
template <std::size_t N>
ReferenceAnswer<N> reference_answer(const PeriodicAnswer<N>& a, const FeHomogenised<N>& fe, const AnswerAdvice& advice,
                                    std::vector<std::string>& warnings);
inline constexpr double kReferenceTolerance = 0.01;

// The phases' stresses of a solved state (phase_stresses): each cell weighted by `weight`
// (its area or volume) in its `phase` of `phases`; `loaded` the loaded component's index
// among the N Voigt components (a load case's), -1 none; with `balanced`, the means from
// the cells' virial stresses (a periodic case's).
template <std::size_t N>
std::vector<PhaseStresses> state_phase_stresses(const SolvedState<N>& s, const std::vector<double>& weight,
                                                const std::vector<int>& phase, int phases, int loaded, bool balanced);

}  // namespace grainmesh
