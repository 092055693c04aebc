// Richardson extrapolation against sequences with a known limit and order.
#include <catch2/catch.hpp>

#include <cmath>

#include "analysis/richardson.hpp"

using namespace grainmesh;

TEST_CASE("Richardson extrapolation recovers the limit and order of f = L + C h^p", "[analysis][richardson]") {
  for (const double p : {0.5, 1.0, 2.0}) {
    INFO("order " << p);
    std::vector<double> f;
    for (int k = 0; k < 4; ++k) f.push_back(5.0 + 3.0 * std::pow(0.1 / std::pow(1.5, k), p));  // h shrinks by 1.5
    const RichardsonEstimate e = richardson(f, 1.5);
    REQUIRE(e.order);
    CHECK(*e.order == Approx(p).epsilon(1e-9));
    CHECK(e.limit == Approx(5.0).epsilon(1e-12));
    CHECK(e.asymptotic);
    // Coarse levels lie further from the limit: the first within a tolerance.
    const auto first = first_within(f, e.limit, std::abs(f[2] - 5.0) / 5.0 * 1.0001);
    REQUIRE(first);
    CHECK(*first == 2);
  }
  // Values that oscillate have no order: the finest is the limit, not asymptotic.
  const RichardsonEstimate wobble = richardson({1.0, 1.1, 1.05}, 2.0);
  CHECK_FALSE(wobble.order);
  CHECK_FALSE(wobble.asymptotic);
  CHECK(wobble.limit == 1.05);
  // Values within kSettled of each other have settled.
  const RichardsonEstimate flat = richardson({2.0, 2.0 + 1e-5, 2.0 - 1e-5}, 2.0);
  CHECK(flat.settled);
  CHECK(flat.limit == 2.0 - 1e-5);
  CHECK_FALSE(first_within({1.0, 1.5}, 2.0, 1e-3));
  CHECK_THROWS(richardson({1.0, 2.0}, 2.0));
  CHECK_THROWS(richardson({1.0, 2.0, 2.5}, 1.0));
}
