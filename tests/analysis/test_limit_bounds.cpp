// A convergence study's limits judged against the bounds of its cell (analysis/
// limit_bounds.hpp): limits inside pass; a shear limit below Hashin-Shtrikman's lower bound
// or a modulus limit outside Voigt and Reuss is named, as the limit of the answer's
// quantity; a quantity without a bound (the volume-average modulus) is not judged.
#include <algorithm>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "analysis/bounds.hpp"
#include "analysis/limit_bounds.hpp"

using namespace grainmesh;

namespace {

bool any_says(const std::vector<std::string>& sentences, const std::string& a, const std::string& b) {
  return std::any_of(sentences.begin(), sentences.end(), [&](const std::string& s) {
    return s.find(a) != std::string::npos && s.find(b) != std::string::npos;
  });
}

}  // namespace

TEST_CASE("a convergence study's limits outside the bounds are named", "[analysis][converge]") {
  SECTION("periodic: the tensor of the limits") {
    const std::vector<FoamPhase> phases{FoamPhase{"WC", 700e9, 0.24, 0.0}, FoamPhase{"Co", 211e9, 0.31, 0.0}};
    PeriodicAnswer<3> p;
    p.bounds = tensor_bounds<3>(phases, {0.85, 0.15});
    REQUIRE(p.bounds.shear_lower);
    // An isotropic tensor midway between the bounds (2D: C11 = K + G, C12 = K - G, C66 = G).
    const double K = 0.5 * (*p.bounds.bulk_lower + *p.bounds.bulk_upper);
    const double G = 0.5 * (*p.bounds.shear_lower + *p.bounds.shear_upper);
    p.verdict.stiffness = {{{K + G, K - G, 0.0}, {K - G, K + G, 0.0}, {0.0, 0.0, G}}};
    const Answer<3> a{.effective = p, .phase_names = {}, .stresses = {}};
    CHECK(limits_outside_bounds(a, {{"C11", K + G}, {"C12", K - G}, {"C66", G}}).empty());
    // C66's limit at half the lower bound takes the tensor's G a quarter below it.
    const auto broken = limits_outside_bounds(a, {{"C11", K + G}, {"C66", 0.5 * *p.bounds.shear_lower}});
    CHECK(any_says(broken, "the limit of effective.shear_modulus", "Hashin-Shtrikman lower bound"));
    CHECK_FALSE(any_says(broken, "bulk_modulus", ""));
    // A bulk limit above the upper bound, through C11 and C22.
    CHECK(any_says(limits_outside_bounds(a, {{"C11", 1.2 * (K + G)}, {"C22", 1.2 * (K + G)}}),
                   "the limit of effective.bulk_modulus", "Hashin-Shtrikman upper bound"));
  }
  SECTION("mixed: the modulus's limit") {
    MixedAnswer<3> m;
    m.bounds = ElasticBounds{.voigt = 10e9, .reuss = 5e9, .hs_lower = 6e9, .hs_upper = 9e9};
    const Answer<3> a{.effective = m, .phase_names = {}, .stresses = {}};
    CHECK(limits_outside_bounds(a, {{"modulus", 7e9}, {"volume_average_modulus", 20e9}}).empty());
    const auto broken = limits_outside_bounds(a, {{"modulus", 4e9}});
    CHECK(broken.size() == 2);
    CHECK(any_says(broken, "the limit of effective.modulus", "Reuss bound"));
    CHECK(any_says(broken, "the limit of effective.modulus", "Hashin-Shtrikman lower bound"));
  }
}
