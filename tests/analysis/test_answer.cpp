// The typed answer of a solved cell, the same in 2D and 3D, built from synthetic solved
// cases of a known stiffness (no solver): the verdicts it carries and the warnings it
// gives — inside the bounds none; above Voigt a warning with the caller's advice; a thermal
// expansion on Levin's exact relation none, 5 % off one — and the mixed load's bounds.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "analysis/answer.hpp"
#include "analysis/synthetic_cases.hpp"

using namespace grainmesh;
using namespace grainmesh::test;

namespace {

// WC and Co, 80 % WC.
const std::vector<FoamPhase> kPhases{{"WC", 700e9, 0.24, 5.2e-6}, {"Co", 210e9, 0.31, 13.8e-6}};
const std::vector<double> kFractions{0.8, 0.2};
const AnswerAdvice kAdvice{.see = "SEE", .why = "WHY", .refine = "REFINE"};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The isotropic stiffness of bulk modulus K (in d dimensions: 2D lambda + mu, 3D
// lambda + 2 mu / 3) and shear modulus mu.
template <std::size_t N>
Stiffness<N> isotropic(double K, double mu) {
  constexpr std::size_t d = voigt_dimensions<N>();
  const double lambda = K - 2.0 * mu / static_cast<double>(d);
  Stiffness<N> c{};
  for (std::size_t i = 0; i < d; ++i)
    for (std::size_t j = 0; j < d; ++j) c[i][j] = lambda + (i == j ? 2.0 * mu : 0.0);
  for (std::size_t k = d; k < N; ++k) c[k][k] = mu;
  return c;
}

// The cell's stiffness in the middle of the Hashin-Shtrikman bounds (so inside Voigt and
// Reuss too).
template <std::size_t N>
Stiffness<N> inside_stiffness() {
  const TensorBounds<N> b = tensor_bounds<N>(kPhases, kFractions);
  return isotropic<N>(0.5 * (*b.bulk_lower + *b.bulk_upper), 0.5 * (*b.shear_lower + *b.shear_upper));
}

// Solved cases of stiffness c whose phases expand freely by alpha (the cell's expansion),
// each case's solve taking 10 + k corrections.
template <std::size_t N>
PeriodicHomogenised<N> cases_of(const Stiffness<N>& c, double alpha) {
  const double delta_T = -800.0;
  PeriodicHomogenised<N> h = synthetic_cases<N>(c, 1e-3, alpha, delta_T, 0.7 * alpha * delta_T);
  for (std::size_t k = 0; k < h.cases.size(); ++k) h.cases[k].run.corrections = 10 + static_cast<int>(k);
  return h;
}

template <std::size_t N>
void check_periodic() {
  const Stiffness<N> c = inside_stiffness<N>();
  const double levin = levin_expansion<N>(kPhases, c)->at(0);  // isotropic: the same in every normal direction
  {
    const PeriodicHomogenised<N> h = cases_of<N>(c, levin);
    const ThermalResidual<N> r = thermal_residual(h);
    std::vector<std::string> warnings;
    const PeriodicAnswer<N> a = periodic_answer(h, &r, kPhases, kFractions, FoamOptions{}, kAdvice, warnings);
    CHECK(warnings.empty());
    CHECK(a.verdict.inside_voigt_reuss);
    CHECK(a.verdict.inside_hashin_shtrikman == std::optional<bool>(true));
    CHECK(a.cases.size() == N + 1);
    CHECK(a.corrections() == 10 + static_cast<int>(N));
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j) CHECK(a.verdict.stiffness[i][j] == Approx(c[i][j]).epsilon(1e-12));
    // Isotropic: E_x from the compliance, the universal anisotropy index zero.
    CHECK(a.engineering.universal_anisotropy == Approx(0.0).margin(1e-9));
    REQUIRE(a.thermal);
    CHECK(a.thermal->expansion[0] == Approx(levin).epsilon(1e-9));
    CHECK(a.thermal->levin_difference < 1e-9);
    CHECK(a.thermal->plane_state == (N == 3 ? "plane_strain" : ""));
  }
  {
    // 5 % off Levin's relation: refine, says the warning.
    const PeriodicHomogenised<N> h = cases_of<N>(c, 1.05 * levin);
    const ThermalResidual<N> r = thermal_residual(h);
    std::vector<std::string> warnings;
    const PeriodicAnswer<N> a = periodic_answer(h, &r, kPhases, kFractions, FoamOptions{}, kAdvice, warnings);
    CHECK(a.thermal->levin_difference == Approx(0.05).epsilon(1e-6));
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].find("Levin's exact relation by 5 %") != std::string::npos);
    CHECK(ends_with(warnings[0], ": REFINE"));
  }
  {
    // Stiffer than the Voigt tensor: outside every bound, each break a warning with its advice.
    Stiffness<N> above = tensor_bounds<N>(kPhases, kFractions).voigt;
    for (auto& row : above)
      for (double& v : row) v *= 1.1;
    std::vector<std::string> warnings;
    const PeriodicAnswer<N> a = periodic_answer<N>(cases_of<N>(above, levin), nullptr, kPhases, kFractions,
                                                FoamOptions{}, kAdvice, warnings);
    CHECK_FALSE(a.verdict.inside_voigt_reuss);
    CHECK(a.verdict.inside_hashin_shtrikman == std::optional<bool>(false));
    CHECK_FALSE(a.thermal);
    REQUIRE(warnings.size() == 3);  // Voigt-Reuss; K and G above Hashin-Shtrikman's upper bounds
    CHECK(ends_with(warnings[0], "(SEE)"));
    CHECK(ends_with(warnings[1], "(WHY)"));
    CHECK(ends_with(warnings[2], "(WHY)"));
  }
}

template <std::size_t N>
void check_mixed() {
  const ElasticBounds b = mixed_bounds<N>(kPhases, kFractions);
  REQUIRE(b.reuss < b.voigt);
  CHECK(bool(b.hs_lower) == (N == 3));  // Hashin-Shtrikman for the plane cell's isotropic modulus
  MixedHomogenised<N> h;
  h.strain_xx = 1e-3;
  // Between the bounds: Hashin-Shtrikman's (2D), which lie inside Voigt and Reuss.
  h.modulus = b.hs_lower ? 0.5 * (*b.hs_lower + *b.hs_upper) : 0.5 * (b.voigt + b.reuss);
  FoamOptions foam;
  std::vector<std::string> warnings;
  const MixedAnswer<N> inside = mixed_answer(h, kPhases, kFractions, foam, kAdvice, warnings);
  REQUIRE(inside.bounds);
  CHECK(inside.verdict->inside_voigt_reuss);
  CHECK(inside.verdict->inside_hashin_shtrikman == (N == 3 ? std::optional<bool>(true) : std::nullopt));
  CHECK(warnings.empty());
  warnings.clear();
  h.modulus = 1.2 * b.voigt;
  const MixedAnswer<N> above = mixed_answer(h, kPhases, kFractions, foam, kAdvice, warnings);
  CHECK_FALSE(above.verdict->inside_voigt_reuss);
  REQUIRE_FALSE(warnings.empty());
  CHECK(warnings[0].find("the Voigt bound") != std::string::npos);
  CHECK(ends_with(warnings[0], "(check the solve; SEE)"));
  // Pulled alone (uniaxial), the cell is not held sideways: no bounds, no verdict.
  warnings.clear();
  foam.uniaxial = true;
  const MixedAnswer<N> uniaxial = mixed_answer(h, kPhases, kFractions, foam, kAdvice, warnings);
  CHECK_FALSE(uniaxial.bounds);
  CHECK_FALSE(uniaxial.verdict);
  CHECK(warnings.empty());
}

// Two finite-element levels whose fine one is `c`, the coarse one `c` with its diagonal
// entry k times `factor`.
template <std::size_t N>
FeLevels<N> two_levels(const Stiffness<N>& c, std::size_t k, double factor) {
  FeHomogenised<N> fine, coarse;
  fine.stiffness = coarse.stiffness = c;
  coarse.stiffness[k][k] *= factor;
  return fe_levels(fine, coarse, "test");
}

// The answer beside a finite-element reference: on it, errors zero and no warning; its
// C11 2 % above, that error stated and one warning naming it; the answer's error estimate
// that error plus the reference's own (twice its two levels' difference: 0.5 % in C11).
template <std::size_t N>
void check_reference() {
  const Stiffness<N> c = inside_stiffness<N>();
  const FeLevels<N> fe = two_levels(c, 0, 1.005);
  CHECK(fe.estimate.stiffness[0][0] == Approx(0.01).epsilon(1e-9));
  CHECK(fe.estimate.stiffness[1][1] == 0.0);
  CHECK(fe.estimate.bulk_modulus > 0.0);
  std::vector<std::string> warnings;
  const PeriodicAnswer<N> same = periodic_answer<N>(cases_of<N>(c, 0.0), nullptr, kPhases, kFractions, FoamOptions{},
                                                    kAdvice, warnings);
  const ReferenceAnswer<N> r = reference_answer(same, fe, kAdvice, warnings);
  CHECK(warnings.empty());
  CHECK(std::abs(r.bulk_error) < 1e-12);
  CHECK(std::abs(r.stiffness_error[0][0]) < 1e-12);
  Stiffness<N> off = c;
  off[0][0] *= 1.02;
  PeriodicAnswer<N> a = periodic_answer<N>(cases_of<N>(off, 0.0), nullptr, kPhases, kFractions, FoamOptions{},
                                           kAdvice, warnings);
  REQUIRE(warnings.empty());  // still inside the bounds
  CHECK_FALSE(a.error_estimate);  // not measured without the reference
  add_reference(a, fe, kAdvice, warnings);
  const ReferenceAnswer<N>& e = *a.reference;
  CHECK(e.stiffness_error[0][0] == Approx(0.02).epsilon(1e-9));
  CHECK(std::abs(e.stiffness_error[0][1]) < 1e-12);
  REQUIRE(a.error_estimate);
  CHECK(a.error_estimate->stiffness[0][0] == Approx(0.03).epsilon(1e-9));
  CHECK(a.error_estimate->stiffness[0][1] == Approx(0.0).margin(1e-12));
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].find("up to 2 % (C11)") != std::string::npos);
  CHECK(ends_with(warnings[0], "(SEE)"));
}

// The finite elements' answer (solver fe): their fine level judged, its error estimate
// their levels'; with OpenFOAM's answer beside it, OpenFOAM's errors against it and its
// load cases, no warning of OpenFOAM's.
template <std::size_t N>
void check_fe_answer() {
  const Stiffness<N> c = inside_stiffness<N>();
  const FeLevels<N> fe = two_levels(c, 1, 1.004);
  std::vector<std::string> warnings;
  const PeriodicAnswer<N> alone = fe_answer(fe, kPhases, kFractions, FoamOptions{}, kAdvice, warnings);
  CHECK(alone.solver == Solver::fe);
  CHECK(alone.verdict.stiffness[1][1] == c[1][1]);
  CHECK(alone.cases.empty());
  REQUIRE(alone.error_estimate);
  CHECK(alone.error_estimate->stiffness[1][1] == Approx(0.008).epsilon(1e-9));
  Stiffness<N> off = c;
  off[0][0] *= 1.03;  // OpenFOAM's, 3 % off: no warning, as it is not the answer
  std::vector<std::string> theirs;
  const PeriodicAnswer<N> openfoam = periodic_answer<N>(cases_of<N>(off, 0.0), nullptr, kPhases, kFractions,
                                                        FoamOptions{}, kAdvice, theirs);
  const PeriodicAnswer<N> both = fe_answer(fe, kPhases, kFractions, FoamOptions{}, kAdvice, warnings,
                                                 std::optional<PeriodicAnswer<N>>(openfoam));
  CHECK(warnings.empty());
  REQUIRE(both.openfoam);
  REQUIRE(both.openfoam->reference);
  CHECK(both.openfoam->reference->stiffness_error[0][0] == Approx(0.03).epsilon(1e-9));
  CHECK(both.cases.size() == openfoam.cases.size());
  CHECK(both.verdict.stiffness[0][0] == c[0][0]);
}

}  // namespace

TEST_CASE("the answer beside its finite-element reference: the errors, more than 1 % a warning", "[analysis][answer]") {
  check_reference<3>();
  check_reference<6>();
}

TEST_CASE("the finite elements' answer: its estimate from two levels, OpenFOAM's beside it", "[analysis][answer]") {
  check_fe_answer<3>();
  check_fe_answer<6>();
}

TEST_CASE("the periodic answer in 2D: verdicts, Levin's relation, warnings with their advice", "[analysis][answer]") {
  check_periodic<3>();
}

TEST_CASE("the periodic answer in 3D: verdicts, Levin's relation, warnings with their advice", "[analysis][answer]") {
  check_periodic<6>();
}

TEST_CASE("the mixed load's answer in 2D and 3D: its bounds, a broken one a warning, none when uniaxial",
          "[analysis][answer]") {
  check_mixed<3>();
  check_mixed<6>();
}
