#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "common/errors.hpp"
#include "common/random.hpp"
#include "domain/distance.hpp"

using namespace grainmesh;
using std::numbers::pi;

namespace {

// Distance to the ellipse by minimising over its parameter t: dense sampling, then
// golden-section search around the best sample. Independent of the library's method.
double ellipse_brute_force(double a, double b, Vec2 p) {
  auto dist = [&](double t) { return std::hypot(a * std::cos(t) - p.x, b * std::sin(t) - p.y); };
  const int n = 4000;
  int best = 0;
  for (int i = 1; i < n; ++i)
    if (dist(2 * pi * i / n) < dist(2 * pi * best / n)) best = i;
  double lo = 2 * pi * (best - 1) / n, hi = 2 * pi * (best + 1) / n;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int k = 0; k < 200; ++k) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    (dist(m1) < dist(m2) ? hi : lo) = (dist(m1) < dist(m2) ? m2 : m1);
  }
  const double d = dist(0.5 * (lo + hi));
  return (p.x / a) * (p.x / a) + (p.y / b) * (p.y / b) < 1 ? -d : d;
}

}  // namespace

TEST_CASE("circle and rectangle give exact signed distances", "[distance]") {
  const auto c = circle({1, 2}, 0.5);
  CHECK(c({1, 2}) == Approx(-0.5));
  CHECK(c({4, 6}) == Approx(4.5));
  CHECK(c({1.5, 2}) == Approx(0.0).margin(1e-15));

  const auto r = rectangle({0, 0}, {4, 2});
  CHECK(r({1, 1}) == Approx(-1.0));
  CHECK(r({3.5, 1}) == Approx(-0.5));
  CHECK(r({6, 1}) == Approx(2.0));
  CHECK(r({7, 6}) == Approx(5.0));  // corner zone
  CHECK(r({4, 2}) == 0.0);
  CHECK(r.vertices().size() == 4);
}

TEST_CASE("ellipse distance is the exact Euclidean distance", "[distance]") {
  Rng rng(7);
  for (auto [a, b] : {std::pair{2.0, 1.0}, std::pair{1.0, 3.0}, std::pair{4.0, 2.0}, std::pair{1.0, 1.0}}) {
    const auto e = ellipse({0, 0}, a, b);
    for (int i = 0; i < 300; ++i) {
      const Vec2 p{(2 * uniform01(rng) - 1) * 1.6 * a, (2 * uniform01(rng) - 1) * 1.6 * b};
      INFO("a = " << a << " b = " << b << " p = (" << p.x << ", " << p.y << ")");
      REQUIRE(e(p) == Approx(ellipse_brute_force(a, b, p)).margin(1e-9));
    }
    // On the axes and at the centre, where the general formula divides by zero.
    CHECK(e({0, 0}) == Approx(-std::min(a, b)));
    CHECK(e({3 * a, 0}) == Approx(2 * a));
    CHECK(e({0, -3 * b}) == Approx(2 * b));
    CHECK(e({0.1 * a, 0}) == Approx(ellipse_brute_force(a, b, {0.1 * a, 0})).margin(1e-9));
  }
  // Same zero level set as the thesis' eq. 3.2, (x/2)^2 + y^2 = 1.
  const auto e = translate(ellipse({0, 0}, 2, 1), {0.5, -0.25});
  for (double t = 0; t < 2 * pi; t += 0.1)
    CHECK(e({0.5 + 2 * std::cos(t), -0.25 + std::sin(t)}) == Approx(0.0).margin(1e-12));
}

TEST_CASE("Boolean operations follow the thesis' equations", "[distance]") {
  const auto a = circle({0, 0}, 1), b = circle({1, 0}, 1);
  Rng rng(11);
  for (int i = 0; i < 200; ++i) {
    const Vec2 p{4 * uniform01(rng) - 2, 4 * uniform01(rng) - 2};
    CHECK(unite({a, b})(p) == std::min(a(p), b(p)));            // eq. 3.3
    CHECK(subtract(a, b)(p) == std::max(a(p), -b(p)));          // eq. 3.5
    CHECK(intersect({a, b})(p) == std::max(a(p), b(p)));        // eq. 3.8
    CHECK(translate(a, {1, 0})(p) == Approx(b(p)).margin(1e-15));
  }
  const Box lens = intersect({a, b}).bounds();
  CHECK(lens.lo.x == 0.0);
  CHECK(lens.hi.x == 1.0);
  const Box both = unite({a, b}).bounds();
  CHECK(both.lo.x == -1.0);
  CHECK(both.hi.x == 2.0);
  const auto plate = subtract(polygon({{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}}), circle({0, 0}, 0.5));
  CHECK(plate.vertices().size() == 4);
  CHECK(translate(rectangle({0, 0}, {1, 1}), {2, 3}).vertices().front() == Vec2{2, 3});
}

TEST_CASE("primitives reject bad parameters", "[distance]") {
  CHECK_THROWS_AS(circle({0, 0}, 0), GeometryError);
  CHECK_THROWS_AS(circle({0, 0}, -1), GeometryError);
  CHECK_THROWS_AS(ellipse({0, 0}, 1, 0), GeometryError);
  CHECK_THROWS_AS(rectangle({1, 0}, {0, 1}), GeometryError);
  CHECK_THROWS_AS(unite({}), GeometryError);
}

TEST_CASE("curvature sizes come from the radius of curvature", "[distance]") {
  const double angle = 2 * pi / 48, g = 0.1;
  const auto c = circle({0, 0}, 2);
  CHECK(c.curvature_size({2, 0}, angle, g) == Approx(2 * angle));
  CHECK(c.curvature_size({3, 0}, angle, g) == Approx(2 * angle + g));
  // Ellipse a = 2, b = 1: radius b^2/a = 0.5 at the ends of the major axis, a^2/b = 4 at
  // the ends of the minor axis.
  const auto e = ellipse({0, 0}, 2, 1);
  CHECK(e.curvature_size({2, 0}, angle, 0) == Approx(0.5 * angle));
  CHECK(e.curvature_size({0, 1}, angle, 0) == Approx(4 * angle));
  // Straight primitives ask for nothing; compositions take the least.
  CHECK(std::isinf(rectangle({0, 0}, {1, 1}).curvature_size({0.5, 0.5}, angle, g)));
  CHECK(subtract(rectangle({-3, -3}, {3, 3}), c).curvature_size({2, 0}, angle, g) == Approx(2 * angle));
}

TEST_CASE("projection lands on the zero level set", "[distance]") {
  const auto d = subtract(ellipse({0, 0}, 4, 2), circle({-0.5, 0}, 1));
  Rng rng(5);
  for (int i = 0; i < 100; ++i) {
    const Vec2 p{10 * uniform01(rng) - 5, 6 * uniform01(rng) - 3};
    const Vec2 q = project_to_zero(d, p, 1.5e-8, 1e-12);
    CHECK(std::abs(d(q)) < 1e-9);
  }
}
