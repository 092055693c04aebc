// A solved cell's answer, typed, one contract for 2D and 3D (N the Voigt size: 3 in 2D,
// 6 in 3D): the effective properties of the mixed (thesis) load or of the periodic load
// cases, with the bounds that hold for them and the verdicts on them (verdicts.hpp), the
// thermal expansion beside Levin's exact relation, and the phases' stress statistics per
// solved state. Built here from the solved states; written into report.json by one
// serializer (pipelines/report_json.hpp) and printed from the type.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
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

// Where a periodic cell's answer comes from (homogenise.solver): OpenFOAM's load cases or
// the finite-element solve (fe_homogenise.hpp).
enum class Solver { openfoam, fe };

// How far each reported quantity may lie from the exact answer on the cell's geometry,
// relative and by the rule of ReferenceAnswer's errors (an entry below a hundredth of the
// largest on the largest's scale), with what it was measured by (`basis`).
template <std::size_t N>
struct ErrorEstimate {
  Stiffness<N> stiffness{};
  double bulk_modulus = 0.0, shear_modulus = 0.0;
  std::optional<std::array<double, N>> expansion;  // when heated
  std::string basis;
};

// The finite elements solved on two levels of refinement, `coarse` and `fine` (coarse
// split in nested refinement: half its element size), and the fine level's error
// estimate from their difference.
template <std::size_t N>
struct FeLevels {
  FeHomogenised<N> fine, coarse;
  ErrorEstimate<N> estimate;

  double seconds() const { return fine.seconds + coarse.seconds; }
};

// How much of the two levels' difference the fine level's error may be: 1 / (r - 1) for a
// stiffness converging by a factor r per halving of the element size, r >= 1.5 (measured
// at least 1.67 on contrast-20 cells whose corners make the solution singular, about 3.5
// at the default contrast: docs/benchmarks.md, fe_nested).
inline constexpr double kFeLevelFactor = 2.0;
// The same for an off-diagonal stiffness entry (a coupling, not an energy: it need not
// fall from level to level, and converges more slowly): r >= 4/3 (measured 1.38 and 1.44
// on C12 of the default cell at contrast 20, four nested levels: docs/benchmarks.md).
inline constexpr double kFeCouplingFactor = 3.0;

// The fine level's error estimate: each quantity's difference from the coarse level times
// kFeLevelFactor (an off-diagonal entry's times kFeCouplingFactor), relative to the fine
// one by ReferenceAnswer's rule; `how` the levels.
template <std::size_t N>
FeLevels<N> fe_levels(const FeHomogenised<N>& fine, const FeHomogenised<N>& coarse, const std::string& how);

// The finite-element reference beside a periodic answer (fe_homogenise.hpp) and how far
// the answer lies from it, relative: each stiffness entry's difference over the
// reference's entry, or over its largest entry where the entry is below a hundredth of it
// (couplings that vanish by symmetry); K's and G's over theirs; the expansion's by the
// same rule, over the largest of its normal components.
template <std::size_t N>
struct ReferenceAnswer {
  FeLevels<N> fe;
  Stiffness<N> stiffness{};  // fe's symmetric part
  double bulk_modulus = 0.0, shear_modulus = 0.0;
  Stiffness<N> stiffness_error{};
  double bulk_error = 0.0, shear_error = 0.0;
  std::optional<std::array<double, N>> expansion_error;
  // The farthest of K, G and the entries of their own scale: its name and |error|.
  std::string farthest;
  double farthest_error = 0.0;
};

// The periodic cell's answer (`solver`'s): the stiffness judged (verdict: the symmetric
// part, its symmetry error, K and G, inside the bounds), the bounds at the phases'
// `fractions`, the engineering constants, the thermal expansion under a temperature change
// and each quantity's error estimate. With OpenFOAM's load cases solved, the cases
// (mechanical ones, then the thermal one) and the stiffness from the cells' volume
// averages; under solver fe, the finite-element solve (`fe`) and, when OpenFOAM solved
// too, OpenFOAM's answer beside it (`openfoam`, its reference this answer).
template <std::size_t N>
struct PeriodicAnswer {
  Solver solver = Solver::openfoam;
  std::vector<SolvedLoadCase<N>> cases;
  StiffnessVerdict<N> verdict;
  TensorBounds<N> bounds;
  std::vector<double> fractions;
  EngineeringConstants engineering;
  Stiffness<N> volume_average_stiffness{};  // symmetric part, when cases
  std::optional<ThermalAnswer<N>> thermal;
  std::optional<ErrorEstimate<N>> error_estimate;  // none: not measured (solver openfoam, reference none)
  std::optional<FeLevels<N>> fe;                   // solver fe
  std::optional<ReferenceAnswer<N>> reference;     // solver openfoam, homogenise.reference = fe
  std::shared_ptr<const PeriodicAnswer<N>> openfoam;  // solver fe, solved by OpenFOAM too

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

// The finite-element reference `fe` (its fine level) of the cell put beside the periodic
// answer `a`, with the answer's errors against it; an answer more than kReferenceTolerance
// off it (a stiffness entry of its own scale, K or G) a warning naming the farthest,
// ending in `advice`'s see.
template <std::size_t N>
ReferenceAnswer<N> reference_answer(const PeriodicAnswer<N>& a, const FeLevels<N>& fe, const AnswerAdvice& advice,
                                    std::vector<std::string>& warnings);
inline constexpr double kReferenceTolerance = 0.01;

// The OpenFOAM answer `a` with the finite-element reference `fe` beside it
// (reference_answer) and its error estimate from it: each quantity's difference from the
// reference plus the reference's own estimate.
template <std::size_t N>
void add_reference(PeriodicAnswer<N>& a, const FeLevels<N>& fe, const AnswerAdvice& advice,
                   std::vector<std::string>& warnings);

// The finite-element answer (solver fe) from its solve `fe` (its fine level, with its
// error estimate): judged against the bounds at the phases' `fractions` (foam's plane
// state in 2D), its expansion under foam.delta_T beside Levin's relation. With `openfoam`
// (the load cases solved too), their cases and OpenFOAM's answer beside it, its reference
// this answer. Broken bounds are warnings, as in periodic_answer.
template <std::size_t N>
PeriodicAnswer<N> fe_answer(const FeLevels<N>& fe, const std::vector<FoamPhase>& phases,
                            const std::vector<double>& fractions, const FoamOptions& foam, const AnswerAdvice& advice,
                            std::vector<std::string>& warnings, std::optional<PeriodicAnswer<N>> openfoam = {});

// The phases' stresses of a solved state (phase_stresses): each cell weighted by `weight`
// (its area or volume) in its `phase` of `phases`; `loaded` the loaded component's index
// among the N Voigt components (a load case's), -1 none; with `balanced`, the means from
// the cells' virial stresses (a periodic case's).
template <std::size_t N>
std::vector<PhaseStresses> state_phase_stresses(const SolvedState<N>& s, const std::vector<double>& weight,
                                                const std::vector<int>& phase, int phases, int loaded, bool balanced);

}  // namespace grainmesh
