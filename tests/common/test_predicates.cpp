#include <catch2/catch.hpp>

#include <cmath>

#include "common/predicates.hpp"

using namespace grainmesh;

TEST_CASE("orient2d gives the sign of the turn", "[predicates]") {
  CHECK(orient2d({0, 0}, {1, 0}, {0, 1}) == 1);
  CHECK(orient2d({0, 0}, {0, 1}, {1, 0}) == -1);
  CHECK(orient2d({0, 0}, {1, 1}, {2, 2}) == 0);
}

TEST_CASE("orient2d is exact where floating point is not", "[predicates]") {
  // Exactly collinear points whose naive determinant rounds away from zero.
  const Vec2 a{0.5, 0.5}, b{12.0, 12.0}, c{24.0, 24.0};
  CHECK(orient2d(a, b, c) == 0);
  // One unit in the last place off the line, on either side.
  CHECK(orient2d(a, b, {24.0, std::nextafter(24.0, 25.0)}) == 1);
  CHECK(orient2d(a, b, {24.0, std::nextafter(24.0, 23.0)}) == -1);
  // Kettner et al.'s classic failure of the naive test: points a few ulps from (0.5, 0.5).
  const Vec2 r{12.0, 12.0}, s{24.0, 24.0};
  for (int i = 0; i < 64; ++i) {
    Vec2 p{0.5 + i * std::ldexp(1.0, -53), 0.5};
    const int exact = orient2d(p, r, s);
    // p lies on y = 0.5 with x >= 0.5: to the right of (below) the line y = x, or on it.
    CHECK(exact == (i == 0 ? 0 : -1));
  }
}
