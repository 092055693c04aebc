#include <catch2/catch.hpp>

#include <cmath>
#include <thread>

#include "common/errors.hpp"
#include "domain/size_function.hpp"

using namespace grainmesh;

TEST_CASE("constant size", "[size]") {
  const auto h = constant_size(0.3);
  CHECK(h({5, 7}) == 0.3);
  CHECK(h.is_constant());
  CHECK_THROWS_AS(constant_size(0), ConfigError);
  CHECK_THROWS_AS(constant_size(-1), ConfigError);
}

TEST_CASE("the thesis' graded size functions are expressible", "[size]") {
  // eq. 3.11: h = min(4 |p| - 1, 2)
  const auto h311 = expression_size("min(4*sqrt(x^2+y^2) - 1, 2)", "size.function");
  CHECK(h311({0.5, 0}) == Approx(1.0));
  CHECK(h311({0, 0.6}) == Approx(1.4));
  CHECK(h311({3, 4}) == Approx(2.0));
  CHECK_FALSE(h311.is_constant());
  // eq. 3.12: h = 1 - 1.5 |p|
  const auto h312 = expression_size("1 - 1.5*sqrt(x^2+y^2)", "size.function");
  CHECK(h312({0, 0}) == Approx(1.0));
  CHECK(h312({0.3, 0.4}) == Approx(0.25));
}

TEST_CASE("minimum of several sizes", "[size]") {
  const auto h = minimum_size({constant_size(0.5), expression_size("x", "k")});
  CHECK(h({0.2, 0}) == Approx(0.2));
  CHECK(h({2, 0}) == Approx(0.5));
  CHECK(h.describe() == "min(0.5, x)");
  const auto c = minimum_size({constant_size(0.5), constant_size(0.25)});
  CHECK(c.is_constant());
  CHECK(c({9, 9}) == 0.25);
}

TEST_CASE("bad size expressions are errors naming the key", "[size]") {
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(expression_size("1 + ", "cfg.ini: size.function"),
                    Contains("cfg.ini: size.function") && Contains("1 + "));
  CHECK_THROWS_AS(expression_size("z * 2", "k"), ConfigError);  // unknown variable
}

TEST_CASE("expressions evaluate the same from several threads", "[size]") {
  const auto h = expression_size("1 + x*x + sin(y)", "k");
  std::vector<Vec2> pts;
  for (int i = 0; i < 20000; ++i) pts.push_back({0.001 * i, -0.002 * i});
  std::vector<double> serial(pts.size()), a(pts.size()), b(pts.size());
  h.eval(pts, serial);
  std::thread t1([&] { h.eval(pts, a); });
  std::thread t2([&] { h.eval(pts, b); });
  t1.join();
  t2.join();
  CHECK(a == serial);
  CHECK(b == serial);
}
