// Verdicts on an effective answer, the same in 2D and 3D (Voigt size N = 3 or 6): whether
// a stiffness keeps the bounds that hold for every microstructure (Voigt and Reuss) and
// for isotropic ones (Hashin-Shtrikman), judged to a tolerance no finer than the answer's
// own measured error, and how far a thermal expansion lies from Levin's exact relation.
// A broken verdict comes with the sentence a warning says; the advice that follows it is
// the caller's (it names the docs page of the dimension).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "analysis/bounds.hpp"
#include "analysis/voigt.hpp"

namespace grainmesh {

// What a bound is judged to: relative rounding (1e-6), or the answer's own measured error
// when larger (a periodic tensor's symmetry error: a cell of two phases a hundredth apart
// lies between bounds closer together than its discretisation error).
double bounds_tolerance(double measured_error = 0.0);

// The sentence of a bound broken by `value` (above it when `above`) by more than
// `tolerance` (relative), "WHAT 1.234e+11 Pa lies above NAME 1.2e+11 Pa by 2.8 %"; nothing
// when it holds.
std::optional<std::string> outside(const std::string& what, double value, double bound, const std::string& name,
                                   bool above, double tolerance = bounds_tolerance());

// A periodic cell's stiffness judged: the tensor reported (the symmetric part of the one
// solved, column by column), its symmetry error, its bulk and shear moduli, and whether it
// keeps the bounds to `tolerance` = bounds_tolerance(symmetry_error).
template <std::size_t N>
struct StiffnessVerdict {
  Stiffness<N> stiffness{};  // Pa
  double symmetry_error = 0.0;
  double bulk_modulus = 0.0, shear_modulus = 0.0;  // Pa, voigt.hpp's
  double tolerance = 0.0;
  bool inside_voigt_reuss = true;  // Reuss <= C <= Voigt in the positive semidefinite order
  std::optional<bool> inside_hashin_shtrikman;  // when the bounds have them (two phases)
  std::vector<std::string> broken_hashin_shtrikman;  // the broken ones' sentences (outside)
};
// `what` names the tensor in the sentences ("effective": effective.bulk_modulus, ...).
template <std::size_t N>
StiffnessVerdict<N> judge_stiffness(const Stiffness<N>& solved, const TensorBounds<N>& bounds,
                                    const std::string& what = "effective");

// The modulus of the thesis' mixed load judged against its Voigt and Reuss values (and
// Hashin-Shtrikman's when given): the broken bounds' sentences (outside).
struct ModulusVerdict {
  bool inside_voigt_reuss = true;
  std::optional<bool> inside_hashin_shtrikman;
  std::vector<std::string> broken_voigt_reuss, broken_hashin_shtrikman;
};
ModulusVerdict judge_modulus(double modulus, double voigt, double reuss, std::optional<double> hs_lower = {},
                             std::optional<double> hs_upper = {}, const std::string& what = "effective.modulus");

// How far an effective expansion lies from Levin's exact relation: the largest difference
// of a component over Levin's largest component (components in the same order). Above
// kLevinTolerance the answer is to be refined.
double levin_difference(const std::vector<double>& expansion, const std::vector<double>& levin);
inline constexpr double kLevinTolerance = 0.01;

}  // namespace grainmesh
