#include "analysis/limit_bounds.hpp"

#include <variant>

#include "analysis/verdicts.hpp"
#include "analysis/voigt.hpp"

namespace grainmesh {

namespace {

// How the sentences name the limits.
constexpr const char* kLimitOf = "the limit of effective";

template <std::size_t N>
std::vector<std::string> periodic_limits(const PeriodicAnswer<N>& a, const StudyLimits& limits) {
  Stiffness<N> c = a.verdict.stiffness;
  for (const auto& [name, limit] : limits)
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = i; j < N; ++j)
        if (stiffness_name<N>(i, j) == name) c[i][j] = c[j][i] = limit;
  const StiffnessVerdict<N> v = judge_stiffness(c, a.bounds, kLimitOf);
  std::vector<std::string> broken;
  if (!v.inside_voigt_reuss)
    broken.push_back(std::string(kLimitOf) + ".stiffness lies outside the Voigt and Reuss bounds");
  broken.insert(broken.end(), v.broken_hashin_shtrikman.begin(), v.broken_hashin_shtrikman.end());
  return broken;
}

template <std::size_t N>
std::vector<std::string> mixed_limits(const MixedAnswer<N>& a, const StudyLimits& limits) {
  std::vector<std::string> broken;
  if (!a.bounds) return broken;
  const ElasticBounds& b = *a.bounds;
  for (const auto& [name, limit] : limits)
    if (name == "modulus") {
      const ModulusVerdict v =
          judge_modulus(limit, b.voigt, b.reuss, b.hs_lower, b.hs_upper, std::string(kLimitOf) + ".modulus");
      broken.insert(broken.end(), v.broken_voigt_reuss.begin(), v.broken_voigt_reuss.end());
      broken.insert(broken.end(), v.broken_hashin_shtrikman.begin(), v.broken_hashin_shtrikman.end());
    }
  return broken;
}

}  // namespace

template <std::size_t N>
std::vector<std::string> limits_outside_bounds(const Answer<N>& finest, const StudyLimits& limits) {
  if (const auto* m = std::get_if<MixedAnswer<N>>(&finest.effective)) return mixed_limits(*m, limits);
  return periodic_limits(std::get<PeriodicAnswer<N>>(finest.effective), limits);
}

template std::vector<std::string> limits_outside_bounds(const Answer<3>&, const StudyLimits&);
template std::vector<std::string> limits_outside_bounds(const Answer<6>&, const StudyLimits&);

}  // namespace grainmesh
