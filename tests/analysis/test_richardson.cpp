// Richardson extrapolation against sequences with a known limit and order.
#include <catch2/catch.hpp>

#include <cmath>

#include "analysis/richardson.hpp"

using namespace grainmesh;

TEST_CASE("Richardson extrapolation recovers the limit and order of f = L + C h^p", "[analysis][richardson]") {
  for (const double p : {0.5, 1.0, 2.0}) {
    INFO("order " << p);
    std::vector<double> f, cells;
    for (int k = 0; k < 4; ++k) {
      const double n = 1000.0 * std::pow(2.0, k);  // cells double: h shrinks by sqrt(2)
      cells.push_back(n);
      f.push_back(5.0 + 3.0 * std::pow(1.0 / std::sqrt(n), p));
    }
    const RichardsonEstimate e = richardson(f, cells);
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
  const RichardsonEstimate wobble = richardson({1.0, 1.1, 1.05}, {100, 200, 400});
  CHECK_FALSE(wobble.order);
  CHECK_FALSE(wobble.asymptotic);
  CHECK(wobble.limit == 1.05);
  // Values within kSettled of each other have settled.
  const RichardsonEstimate flat = richardson({2.0, 2.0 + 1e-5, 2.0 - 1e-5}, {100, 200, 400});
  CHECK(flat.settled);
  CHECK(flat.limit == 2.0 - 1e-5);
  CHECK_FALSE(first_within({1.0, 1.5}, 2.0, 1e-3));
  CHECK_THROWS(richardson({1.0, 2.0}, {1.0, 2.0}));
}
