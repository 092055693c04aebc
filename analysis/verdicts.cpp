#include "analysis/verdicts.hpp"

#include <algorithm>
#include <cmath>

#include "common/format.hpp"

namespace grainmesh {

double bounds_tolerance(double measured_error) {
  constexpr double kRounding = 1e-6;  // relative: bounds that coincide (one material) are met to rounding
  return std::max(kRounding, measured_error);
}

std::optional<std::string> outside(const std::string& what, double value, double bound, const std::string& name,
                                   bool above, double tolerance) {
  if (above ? value <= bound * (1 + tolerance) : value >= bound * (1 - tolerance)) return std::nullopt;
  return what + " " + to_text(value, 4) + " Pa lies " + (above ? "above" : "below") + " " + name + " " +
         to_text(bound, 4) + " Pa by " + to_text(100.0 * std::abs(value / bound - 1.0), 2) + " %";
}

template <std::size_t N>
StiffnessVerdict<N> judge_stiffness(const Stiffness<N>& solved, const TensorBounds<N>& b, const std::string& what) {
  StiffnessVerdict<N> v;
  v.stiffness = symmetric_part(solved);
  v.symmetry_error = symmetry_error(solved);
  v.bulk_modulus = bulk_modulus(v.stiffness);
  v.shear_modulus = shear_modulus(v.stiffness);
  v.tolerance = bounds_tolerance(v.symmetry_error);
  v.inside_voigt_reuss =
      semidefinite_order(b.reuss, v.stiffness, v.tolerance) && semidefinite_order(v.stiffness, b.voigt, v.tolerance);
  if (!b.bulk_upper) return v;
  const double K = v.bulk_modulus, G = v.shear_modulus, t = v.tolerance;
  const char* upper = "the Hashin-Shtrikman upper bound";
  const char* lower = "the Hashin-Shtrikman lower bound";
  const std::string bulk = what + ".bulk_modulus", shear = what + ".shear_modulus";
  for (const auto& w :
       {outside(bulk, K, *b.bulk_upper, upper, true, t), outside(bulk, K, *b.bulk_lower, lower, false, t),
        outside(shear, G, *b.shear_upper, upper, true, t), outside(shear, G, *b.shear_lower, lower, false, t)})
    if (w) v.broken_hashin_shtrikman.push_back(*w);
  v.inside_hashin_shtrikman = v.broken_hashin_shtrikman.empty();
  return v;
}

ModulusVerdict judge_modulus(double modulus, double voigt, double reuss, std::optional<double> hs_lower,
                             std::optional<double> hs_upper, const std::string& what) {
  ModulusVerdict v;
  for (const auto& w : {outside(what, modulus, voigt, "the Voigt bound", true),
                        outside(what, modulus, reuss, "the Reuss bound", false)})
    if (w) {
      v.inside_voigt_reuss = false;
      v.broken_voigt_reuss.push_back(*w);
    }
  if (!hs_upper || !hs_lower) return v;
  v.inside_hashin_shtrikman = true;
  for (const auto& w : {outside(what, modulus, *hs_upper, "the Hashin-Shtrikman upper bound", true),
                        outside(what, modulus, *hs_lower, "the Hashin-Shtrikman lower bound", false)})
    if (w) {
      v.inside_hashin_shtrikman = false;
      v.broken_hashin_shtrikman.push_back(*w);
    }
  return v;
}

double levin_difference(const std::vector<double>& expansion, const std::vector<double>& levin) {
  double scale = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < levin.size(); ++k) {
    scale = std::max(scale, std::abs(levin[k]));
    difference = std::max(difference, std::abs(expansion[k] - levin[k]));
  }
  return difference / scale;
}

template StiffnessVerdict<3> judge_stiffness(const Stiffness<3>&, const TensorBounds<3>&, const std::string&);
template StiffnessVerdict<6> judge_stiffness(const Stiffness<6>&, const TensorBounds<6>&, const std::string&);

}  // namespace grainmesh
