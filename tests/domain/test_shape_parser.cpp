#include <catch2/catch.hpp>

#include "common/errors.hpp"
#include "domain/shape_parser.hpp"

using namespace grainmesh;
using Catch::Matchers::Contains;

TEST_CASE("shapes parse into the distance functions they name", "[parser]") {
  const auto d = parse_shape("difference(rectangle(-1, -1, 1, 1), circle(0,0,0.5))", "k");
  CHECK(d({0, 0}) == Approx(0.5));
  CHECK(d({0.75, 0}) == Approx(-0.25));
  CHECK(parse_shape("ellipse(0, 0, 2, 1)", "k")({3, 0}) == Approx(1.0));
  CHECK(parse_shape("translate(1, 2, circle(0, 0, 1))", "k")({1, 2}) == Approx(-1.0));
  CHECK(parse_shape("union(circle(0,0,1), circle(3,0,1))", "k")({3, 0}) == Approx(-1.0));
  CHECK(parse_shape("intersection(circle(0,0,1), circle(1,0,1))", "k")({0.5, 0}) == Approx(-0.5));
  const auto holed = parse_shape("polygon(0 0, 4 0, 4 4, 0 4; 1 1, 3 1, 3 3, 1 3)", "k");
  CHECK(holed({2, 2}) == Approx(1.0));
  CHECK(holed({0.5, 2}) == Approx(-0.5));
  CHECK(holed.vertices().size() == 8);
  CHECK(parse_shape("  circle( +1.5e0 ,-2,  2.5E-1 ) ", "k")({1.5, -2}) == Approx(-0.25));
}

TEST_CASE("shape syntax errors name the key and the column", "[parser]") {
  CHECK_THROWS_WITH(parse_shape("circle(0, 0 1)", "cfg.ini: domain.shape"),
                    Contains("cfg.ini: domain.shape") && Contains("expected ','") && Contains("column 13"));
  CHECK_THROWS_WITH(parse_shape("square(1)", "k"), Contains("unknown shape 'square'"));
  CHECK_THROWS_WITH(parse_shape("circle(0, 0, x)", "k"), Contains("expected a number"));
  CHECK_THROWS_WITH(parse_shape("circle(0, 0, 1) extra", "k"), Contains("unexpected text"));
  CHECK_THROWS_WITH(parse_shape("", "k"), Contains("empty shape"));
  CHECK_THROWS_AS(parse_shape("circle(0, 0, 1", "k"), ConfigError);
}

TEST_CASE("invalid geometry in a shape is a geometry error naming the key", "[parser]") {
  CHECK_THROWS_AS(parse_shape("polygon(0 0, 2 2, 2 0, 0 2)", "k"), GeometryError);
  CHECK_THROWS_WITH(parse_shape("circle(0, 0, -1)", "domain.shape"), Contains("domain.shape") && Contains("radius"));
}

TEST_CASE("point lists and number lists", "[parser]") {
  const auto pts = parse_point_list("1 2, 3.5 -4", "k");
  REQUIRE(pts.size() == 2);
  CHECK(pts[1] == Vec2{3.5, -4});
  CHECK(parse_point_list("  ", "k").empty());
  CHECK_THROWS_WITH(parse_point_list("1 2 3", "fixed.points"), Contains("fixed.points"));
  CHECK(parse_numbers("-1 -2 3 4", 4, "k") == std::vector<double>{-1, -2, 3, 4});
  CHECK_THROWS_WITH(parse_numbers("1 2 3", 4, "domain.bbox"), Contains("domain.bbox") && Contains("expected 4 numbers"));
}
