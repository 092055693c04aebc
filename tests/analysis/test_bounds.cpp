// Elastic bounds for the export's default load.
#include <catch2/catch.hpp>

#include "analysis/bounds.hpp"

using namespace grainmesh;

TEST_CASE("elastic bounds: ordered, and equal for one material", "[homogenise]") {
  const std::vector<FoamPhase> one{{"a", 200e9, 0.3}, {"b", 200e9, 0.3}};
  const ElasticBounds same = elastic_bounds(one, {0.4, 0.6}, false);
  const double M = 200e9 * 0.7 / (1.3 * 0.4);
  CHECK(same.voigt == Approx(M));
  CHECK(same.reuss == Approx(M));
  CHECK(*same.hs_lower == Approx(M));
  CHECK(*same.hs_upper == Approx(M));

  const std::vector<FoamPhase> two{{"hard", 800e9, 0.1}, {"soft", 300e9, 0.1}};
  for (double f : {0.1, 0.5, 0.9}) {
    const ElasticBounds b = elastic_bounds(two, {1 - f, f}, false);
    CHECK(b.reuss < *b.hs_lower);
    CHECK(*b.hs_lower < *b.hs_upper);
    CHECK(*b.hs_upper < b.voigt);
  }
  // Voigt is the plain average of M; with equal nu, Reuss is the harmonic mean of M.
  const ElasticBounds half = elastic_bounds(two, {0.5, 0.5}, false);
  const double M1 = 800e9 * 0.9 / (1.1 * 0.8), M2 = 300e9 * 0.9 / (1.1 * 0.8);
  CHECK(half.voigt == Approx(0.5 * (M1 + M2)));
  CHECK(half.reuss == Approx(2.0 / (1 / M1 + 1 / M2)));
}
