#include <catch2/catch.hpp>

#include <cmath>

#include "common/errors.hpp"
#include "mesh/quality.hpp"

using namespace grainmesh;

TEST_CASE("radius ratio of known triangles", "[quality]") {
  CHECK(radius_ratio({0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}) == Approx(1.0));
  // Right isosceles: 2 r / R = (2 - sqrt 2) sqrt 2 = 2 sqrt 2 - 2.
  CHECK(radius_ratio({0, 0}, {1, 0}, {0, 1}) == Approx(2 * std::sqrt(2.0) - 2));
  CHECK(radius_ratio({0, 0}, {1, 0}, {2, 0}) == Approx(0.0).margin(1e-15));
  CHECK(radius_ratio({0, 0}, {0, 0}, {1, 1}) == 0.0);
}

TEST_CASE("a square split on its diagonal", "[quality]") {
  // Internal face along the diagonal: the centre line is parallel to its normal and
  // passes through its middle, so non-orthogonality and skewness vanish there. Each
  // boundary face has skewness |(-1/6, 0)| / 0.5 = 1/3 (checkMesh's normalisation).
  const TriMesh m{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}}};
  const MeshQuality q = measure_quality(m);
  CHECK(q.triangles == 2);
  CHECK(q.q_min == Approx(2 * std::sqrt(2.0) - 2));
  CHECK(q.min_angle_deg == Approx(45.0));
  CHECK(q.max_angle_deg == Approx(90.0));
  CHECK(q.max_non_orthogonality_deg == Approx(0.0).margin(1e-6));
  CHECK(q.max_skewness == Approx(1.0 / 3.0));
  CHECK(q.q_below_half == 0.0);
}

TEST_CASE("non-orthogonality of a sheared pair", "[quality]") {
  // Shared edge on the y axis, apexes (-1, 0) and (1, 2): centroids (-1/3, 0) and
  // (1/3, 2/3), so the centre line makes atan((2/3)/(2/3)) = 45 degrees with the x-axis
  // normal of the face.
  const TriMesh m{{{0, -1}, {0, 1}, {-1, 0}, {1, 2}}, {{0, 1, 2}, {1, 0, 3}}};
  const MeshQuality q = measure_quality(m);
  CHECK(q.max_non_orthogonality_deg == Approx(45.0));
  CHECK(q.mean_non_orthogonality_deg == Approx(45.0));
  CHECK(q.max_skewness >= Approx(1.0 / 3.0));  // the internal face alone gives 1/3
}

TEST_CASE("mesh edges and areas and validation", "[trimesh]") {
  const TriMesh m{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}}};
  const auto edges = mesh_edges(m);
  CHECK(edges.size() == 5);
  int boundary = 0;
  for (const auto& e : edges) boundary += e.right < 0;
  CHECK(boundary == 4);
  CHECK(boundary_points(m, edges).size() == 4);
  CHECK(mesh_area(m) == Approx(1.0));
  CHECK(triangle_centroid(m, 0) == Vec2{2.0 / 3, 1.0 / 3});
  CHECK_NOTHROW(validate(m));

  TriMesh inverted = m;
  inverted.triangles[1] = {0, 3, 2};
  CHECK_THROWS_AS(validate(inverted), GeometryError);
  TriMesh unused = m;
  unused.points.push_back({5, 5});
  CHECK_THROWS_WITH(validate(unused), Catch::Matchers::Contains("belongs to no triangle"));
  TriMesh flat = m;
  flat.points[2] = {2, 0};  // triangle 0 becomes (0,0) (1,0) (2,0): collinear
  CHECK_THROWS_WITH(validate(flat), Catch::Matchers::Contains("zero area"));
}
