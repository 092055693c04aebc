#include "analysis/answer.hpp"

#include <algorithm>
#include <cmath>

#include "common/format.hpp"

namespace grainmesh {

namespace {

// The plane state of 2D cells; a 3D cell has none.
template <std::size_t N>
bool plane_stress(const FoamOptions& foam) {
  return N == 3 && foam.plane_stress;
}

}  // namespace

template <std::size_t N>
int PeriodicAnswer<N>::corrections() const {
  int most = 0;
  for (const SolvedLoadCase<N>& c : cases) most = std::max(most, c.run.corrections);
  return most;
}

template <std::size_t N>
MixedAnswer<N> mixed_answer(const MixedHomogenised<N>& h, const std::vector<FoamPhase>& phases,
                            const std::vector<double>& fractions, const FoamOptions& foam, const AnswerAdvice& advice,
                            std::vector<std::string>& warnings) {
  MixedAnswer<N> a{.modulus = h.modulus, .sigma_xx = h.sigma_xx, .strain_xx = h.strain_xx,
                   .volume_average = h.volume_average, .volume_average_modulus = h.volume_average_modulus,
                   .run = h.run, .bounds = {}, .verdict = {}};
  if (foam.uniaxial) return a;  // the bounds are for the cell held sideways
  const ElasticBounds& b = *(a.bounds = mixed_bounds<N>(phases, fractions, plane_stress<N>(foam)));
  const ModulusVerdict& v = *(a.verdict = judge_modulus(h.modulus, b.voigt, b.reuss, b.hs_lower, b.hs_upper));
  for (const std::string& w : v.broken_voigt_reuss) warnings.push_back(w + " (check the solve; " + advice.see + ")");
  for (const std::string& w : v.broken_hashin_shtrikman) warnings.push_back(w + " (" + advice.why + ")");
  return a;
}

namespace {

// The free expansion under delta_T beside Levin's relation with the stiffness it was
// freed with (`solved`).
template <std::size_t N>
ThermalAnswer<N> thermal_answer(double delta_T, const std::array<double, N>& expansion, const Stiffness<N>& solved,
                                const std::vector<FoamPhase>& phases, const FoamOptions& foam,
                                const AnswerAdvice& advice, std::vector<std::string>& warnings) {
  ThermalAnswer<N> a{.delta_T = delta_T, .expansion = expansion, .levin = {}, .levin_difference = 0.0,
                     .plane_state = N == 3 ? plane_state(foam) : ""};
  // Levin's relation with the stiffness the expansion was freed with (as solved).
  a.levin = levin_expansion(phases, solved, plane_stress<N>(foam));
  if (!a.levin) return a;
  a.levin_difference = levin_difference({a.expansion.begin(), a.expansion.end()}, {a.levin->begin(), a.levin->end()});
  if (a.levin_difference > kLevinTolerance)
    warnings.push_back("effective.thermal_expansion differs from Levin's exact relation by " +
                       to_text(100.0 * a.levin_difference, 2) + " % of its largest component: " + advice.refine);
  return a;
}

// A solved stiffness judged against the bounds at the phases' `fractions`, with its
// engineering constants; a broken bound a warning.
template <std::size_t N>
PeriodicAnswer<N> judged_answer(Solver solver, const Stiffness<N>& solved, const std::vector<FoamPhase>& phases,
                                const std::vector<double>& fractions, const FoamOptions& foam,
                                const AnswerAdvice& advice, std::vector<std::string>& warnings) {
  PeriodicAnswer<N> a;
  a.solver = solver;
  a.bounds = tensor_bounds<N>(phases, fractions, plane_stress<N>(foam));
  a.fractions = fractions;
  a.verdict = judge_stiffness(solved, a.bounds);
  a.engineering = engineering_constants(a.verdict.stiffness);
  if (!a.verdict.inside_voigt_reuss)
    warnings.push_back("effective.stiffness does not lie between the Reuss and Voigt tensors (positive semidefinite "
                       "order): check the solve (" + advice.see + ")");
  for (const std::string& w : a.verdict.broken_hashin_shtrikman) warnings.push_back(w + " (" + advice.why + ")");
  return a;
}

}  // namespace

template <std::size_t N>
PeriodicAnswer<N> periodic_answer(const PeriodicHomogenised<N>& h, const ThermalResidual<N>* thermal,
                                  const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                                  const FoamOptions& foam, const AnswerAdvice& advice,
                                  std::vector<std::string>& warnings) {
  PeriodicAnswer<N> a = judged_answer(Solver::openfoam, h.stiffness, phases, fractions, foam, advice, warnings);
  for (const LoadCaseResult<N>& c : h.cases) a.cases.push_back({c.load, c.stress, c.run});
  a.volume_average_stiffness = symmetric_part(h.volume_average_stiffness);
  if (thermal != nullptr)
    a.thermal = thermal_answer(thermal->delta_T, thermal->expansion, h.stiffness, phases, foam, advice, warnings);
  return a;
}

namespace {

// The share of the largest entry below which an entry is measured on the largest: the
// couplings that vanish by symmetry.
constexpr double kOwnScale = 0.01;

// Whether `reference` is measured on its own scale: not below kOwnScale of `largest`.
bool own_scale(double reference, double largest) { return std::abs(reference) >= kOwnScale * largest; }

// `value`'s difference from `reference`, relative to it or, below kOwnScale of `largest`,
// to `largest`.
double relative_error(double value, double reference, double largest) {
  return (value - reference) / (own_scale(reference, largest) ? std::abs(reference) : largest);
}

// Each stiffness entry's change from the coarse level to the fine, absolute; an
// off-diagonal entry's taken no smaller, relative to the entry (to kOwnScale of the
// largest when it is smaller), than its two diagonals' (their geometric mean). A
// coupling's error is the difference of two nearly equal energies' errors (strains
// e_i + e_j and e_i - e_j), and its change between two levels may pass through zero while
// the error does not (measured on a 3D cell: C12 and C13, and couplings that vanish by
// symmetry, changed less from the coarse level to the fine than from the fine to the next;
// tests/export/test_nested_split.cpp); the diagonals' changes, energies' and so of one
// sign, do not.
template <std::size_t N>
Stiffness<N> level_differences(const Stiffness<N>& coarse, const Stiffness<N>& fine) {
  const double largest = largest_entry(fine);
  Stiffness<N> d{};
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) {
      d[i][j] = std::abs(coarse[i][j] - fine[i][j]);
      if (i == j) continue;
      const double diagonals =
          std::sqrt(std::abs(coarse[i][i] / fine[i][i] - 1.0) * std::abs(coarse[j][j] / fine[j][j] - 1.0));
      d[i][j] = std::max(d[i][j], std::max(std::abs(fine[i][j]), kOwnScale * largest) * diagonals);
    }
  return d;
}

// The largest normal component of an expansion: the scale of its components' errors.
template <std::size_t N>
double expansion_scale(const std::array<double, N>& x) {
  return std::max({std::abs(x[0]), std::abs(x[1]), std::abs(x[voigt_dimensions<N>() - 1])});
}

}  // namespace

template <std::size_t N>
FeLevels<N> fe_levels(const FeHomogenised<N>& fine, const FeHomogenised<N>& coarse, const std::string& how) {
  FeLevels<N> l{.fine = fine, .coarse = coarse, .estimate = {}};
  ErrorEstimate<N>& e = l.estimate;
  const Stiffness<N> f = symmetric_part(fine.stiffness), c = symmetric_part(coarse.stiffness);
  const double largest = largest_entry(f);
  const Stiffness<N> d = level_differences(c, f);
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j)
      e.stiffness[i][j] =
          (i == j ? kFeLevelFactor : kFeCouplingFactor) * relative_error(f[i][j] + d[i][j], f[i][j], largest);
  e.bulk_modulus = kFeLevelFactor * std::abs(bulk_modulus(c) / bulk_modulus(f) - 1.0);
  e.shear_modulus = kFeLevelFactor * std::abs(shear_modulus(c) / shear_modulus(f) - 1.0);
  if (fine.expansion && coarse.expansion) {
    std::array<double, N> x{};
    const double scale = expansion_scale<N>(*fine.expansion);
    for (std::size_t k = 0; k < N; ++k)
      x[k] = kFeLevelFactor * std::abs(relative_error((*coarse.expansion)[k], (*fine.expansion)[k], scale));
    e.expansion = x;
  }
  e.basis = "the finite elements on two levels (" + how + "): " + to_text(kFeLevelFactor) +
            " x their difference, an off-diagonal stiffness entry's " + to_text(kFeCouplingFactor) +
            " x (its relative difference no smaller than its diagonals'), the fine level's error when each halving "
            "of the element size gains a factor of " + to_text(1.0 + 1.0 / kFeLevelFactor) + " (" +
            to_text(1.0 + 1.0 / kFeCouplingFactor, 3) + ") or more (docs/run.md, Error estimates)";
  return l;
}

template <std::size_t N>
ReferenceAnswer<N> reference_answer(const PeriodicAnswer<N>& a, const FeLevels<N>& levels, const AnswerAdvice& advice,
                                    std::vector<std::string>& warnings) {
  const FeHomogenised<N>& fe = levels.fine;
  ReferenceAnswer<N> r;
  r.fe = levels;
  r.stiffness = symmetric_part(fe.stiffness);
  r.bulk_modulus = bulk_modulus(r.stiffness);
  r.shear_modulus = shear_modulus(r.stiffness);
  const double largest = largest_entry(r.stiffness);
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j)
      r.stiffness_error[i][j] = relative_error(a.verdict.stiffness[i][j], r.stiffness[i][j], largest);
  r.bulk_error = a.verdict.bulk_modulus / r.bulk_modulus - 1.0;
  r.shear_error = a.verdict.shear_modulus / r.shear_modulus - 1.0;
  if (a.thermal && fe.expansion) {
    const double scale = expansion_scale<N>(*fe.expansion);
    std::array<double, N> e{};
    for (std::size_t k = 0; k < N; ++k) e[k] = relative_error(a.thermal->expansion[k], (*fe.expansion)[k], scale);
    r.expansion_error = e;
  }
  // The farthest of the quantities measured on their own scale: K, G and the entries not
  // below a hundredth of the largest.
  std::string worst = "the bulk modulus";
  double most = std::abs(r.bulk_error);
  if (std::abs(r.shear_error) > most) worst = "the shear modulus", most = std::abs(r.shear_error);
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i; j < N; ++j)
      if (own_scale(r.stiffness[i][j], largest) && std::abs(r.stiffness_error[i][j]) > most)
        worst = stiffness_name<N>(i, j), most = std::abs(r.stiffness_error[i][j]);
  r.farthest = worst;
  r.farthest_error = most;
  if (most > kReferenceTolerance)
    warnings.push_back("effective.stiffness lies up to " + to_text(100.0 * most, 2) + " % (" + worst +
                       ") from the finite-element reference (effective.reference): refine the mesh (" + advice.see + ")");
  return r;
}

template <std::size_t N>
void add_reference(PeriodicAnswer<N>& a, const FeLevels<N>& fe, const AnswerAdvice& advice,
                   std::vector<std::string>& warnings) {
  const ReferenceAnswer<N>& r = *(a.reference = reference_answer(a, fe, advice, warnings));
  const ErrorEstimate<N>& own = fe.estimate;
  ErrorEstimate<N> e;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) e.stiffness[i][j] = std::abs(r.stiffness_error[i][j]) + own.stiffness[i][j];
  e.bulk_modulus = std::abs(r.bulk_error) + own.bulk_modulus;
  e.shear_modulus = std::abs(r.shear_error) + own.shear_modulus;
  if (r.expansion_error && own.expansion) {
    std::array<double, N> x{};
    for (std::size_t k = 0; k < N; ++k) x[k] = std::abs((*r.expansion_error)[k]) + (*own.expansion)[k];
    e.expansion = x;
  }
  e.basis = "the difference from the finite-element reference (effective.reference) plus the reference's own "
            "estimate (effective.reference.error_estimate)";
  a.error_estimate = e;
}

template <std::size_t N>
PeriodicAnswer<N> fe_answer(const FeLevels<N>& fe, const std::vector<FoamPhase>& phases,
                            const std::vector<double>& fractions, const FoamOptions& foam, const AnswerAdvice& advice,
                            std::vector<std::string>& warnings, std::optional<PeriodicAnswer<N>> openfoam) {
  const FeHomogenised<N>& fine = fe.fine;
  PeriodicAnswer<N> a = judged_answer(Solver::fe, fine.stiffness, phases, fractions, foam, advice, warnings);
  a.fe = fe;
  if (fine.expansion)
    a.thermal = thermal_answer(foam.delta_T, *fine.expansion, fine.stiffness, phases, foam, advice, warnings);
  a.error_estimate = fe.estimate;
  if (openfoam) {
    a.cases = openfoam->cases;
    a.volume_average_stiffness = openfoam->volume_average_stiffness;
    std::vector<std::string> theirs;  // OpenFOAM's answer is not the answer: its doubts are not the run's
    openfoam->reference = reference_answer(*openfoam, fe, advice, theirs);
    a.openfoam = std::make_shared<const PeriodicAnswer<N>>(std::move(*openfoam));
  }
  return a;
}

template <std::size_t N>
std::vector<PhaseStresses> state_phase_stresses(const SolvedState<N>& s, const std::vector<double>& weight,
                                                const std::vector<int>& phase, int phases, int loaded, bool balanced) {
  const std::vector<StressTensor> own = cell_stress_tensors(s);
  const std::vector<StressTensor> virial = balanced ? cell_stress_tensors(s, true) : std::vector<StressTensor>{};
  const int component = loaded < 0 ? -1 : static_cast<int>(tensor_index<N>(static_cast<std::size_t>(loaded)));
  return phase_stresses(own, weight, phase, phases, component, balanced ? &virial : nullptr);
}

template struct PeriodicAnswer<3>;
template struct PeriodicAnswer<6>;
template FeLevels<3> fe_levels(const FeHomogenised<3>&, const FeHomogenised<3>&, const std::string&);
template FeLevels<6> fe_levels(const FeHomogenised<6>&, const FeHomogenised<6>&, const std::string&);
template ReferenceAnswer<3> reference_answer(const PeriodicAnswer<3>&, const FeLevels<3>&, const AnswerAdvice&,
                                             std::vector<std::string>&);
template ReferenceAnswer<6> reference_answer(const PeriodicAnswer<6>&, const FeLevels<6>&, const AnswerAdvice&,
                                             std::vector<std::string>&);
template void add_reference(PeriodicAnswer<3>&, const FeLevels<3>&, const AnswerAdvice&, std::vector<std::string>&);
template void add_reference(PeriodicAnswer<6>&, const FeLevels<6>&, const AnswerAdvice&, std::vector<std::string>&);
template PeriodicAnswer<3> fe_answer(const FeLevels<3>&, const std::vector<FoamPhase>&, const std::vector<double>&,
                                     const FoamOptions&, const AnswerAdvice&, std::vector<std::string>&,
                                     std::optional<PeriodicAnswer<3>>);
template PeriodicAnswer<6> fe_answer(const FeLevels<6>&, const std::vector<FoamPhase>&, const std::vector<double>&,
                                     const FoamOptions&, const AnswerAdvice&, std::vector<std::string>&,
                                     std::optional<PeriodicAnswer<6>>);
template MixedAnswer<3> mixed_answer(const MixedHomogenised<3>&, const std::vector<FoamPhase>&,
                                     const std::vector<double>&, const FoamOptions&, const AnswerAdvice&,
                                     std::vector<std::string>&);
template MixedAnswer<6> mixed_answer(const MixedHomogenised<6>&, const std::vector<FoamPhase>&,
                                     const std::vector<double>&, const FoamOptions&, const AnswerAdvice&,
                                     std::vector<std::string>&);
template PeriodicAnswer<3> periodic_answer(const PeriodicHomogenised<3>&, const ThermalResidual<3>*,
                                           const std::vector<FoamPhase>&, const std::vector<double>&,
                                           const FoamOptions&, const AnswerAdvice&, std::vector<std::string>&);
template PeriodicAnswer<6> periodic_answer(const PeriodicHomogenised<6>&, const ThermalResidual<6>*,
                                           const std::vector<FoamPhase>&, const std::vector<double>&,
                                           const FoamOptions&, const AnswerAdvice&, std::vector<std::string>&);
template std::vector<PhaseStresses> state_phase_stresses(const SolvedState<3>&, const std::vector<double>&,
                                                         const std::vector<int>&, int, int, bool);
template std::vector<PhaseStresses> state_phase_stresses(const SolvedState<6>&, const std::vector<double>&,
                                                         const std::vector<int>&, int, int, bool);

}  // namespace grainmesh
