#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "common/errors.hpp"
#include "mesh/distmesh.hpp"
#include "mesh/quality.hpp"

using namespace grainmesh;
using Catch::Matchers::Contains;

namespace {
DistMeshResult mesh_of(const DistMeshProblem& pb, const DistMeshOptions& opt = {}, std::uint64_t seed = 1) {
  Rng rng(seed);
  return distmesh(pb, opt, rng);
}
DistMeshProblem unit_circle(double h0) {
  return {.domain = circle({0, 0}, 1), .h0 = h0, .bbox = {{-1, -1}, {1, 1}}};
}
}  // namespace

TEST_CASE("the unit circle meshes to a valid and converged high-quality mesh", "[distmesh]") {
  const auto r = mesh_of(unit_circle(0.1));
  CHECK(r.stats.converged);
  CHECK_NOTHROW(validate(r.mesh));
  const MeshQuality q = measure_quality(r.mesh);
  CHECK(q.q_min > 0.7);
  CHECK(q.q_mean > 0.98);
  CHECK(mesh_area(r.mesh) == Approx(std::numbers::pi).epsilon(0.005));
  for (int v : boundary_points(r.mesh, mesh_edges(r.mesh)))
    CHECK(std::abs(norm(r.mesh.points[v]) - 1.0) < 1e-3 * 0.1);
}

TEST_CASE("the thesis' plain Algorithm 1 is still available", "[distmesh]") {
  DistMeshProblem pb = unit_circle(0.1);
  const DistMeshOptions plain{.boundary_seeding = false, .split_long_edges = false, .optimize_sweeps = 0};
  const auto r = mesh_of(pb, plain);
  CHECK(r.stats.converged);
  CHECK(r.stats.density_added == 0);
  CHECK_NOTHROW(validate(r.mesh));
  CHECK(measure_quality(r.mesh).q_min > 0.5);
}

TEST_CASE("the iteration limit stops the loop and still gives a valid mesh", "[distmesh]") {
  DistMeshOptions opt;
  opt.max_iterations = 3;
  const auto r = mesh_of(unit_circle(0.1), opt);
  CHECK_FALSE(r.stats.converged);
  CHECK(r.stats.iterations == 3);
  CHECK_THAT(r.stats.stop_reason, Contains("iteration limit 3"));
  CHECK_NOTHROW(validate(r.mesh));
}

TEST_CASE("meshes are reproducible from the seed", "[distmesh]") {
  // A graded size makes the rejection step random.
  DistMeshProblem pb = unit_circle(0.05);
  pb.size = expression_size("1 + sqrt(x^2+y^2)", "k");
  const auto a = mesh_of(pb, {}, 42), b = mesh_of(pb, {}, 42), c = mesh_of(pb, {}, 43);
  CHECK(a.mesh.points == b.mesh.points);
  CHECK(a.mesh.triangles == b.mesh.triangles);
  CHECK(a.mesh.points != c.mesh.points);
}

TEST_CASE("fixed points are exact mesh nodes", "[distmesh]") {
  DistMeshProblem pb{.domain = rectangle({0, 0}, {2, 1}), .h0 = 0.1, .bbox = {{0, 0}, {2, 1}}};
  pb.fixed = {{0, 0}, {2, 0}, {2, 1}, {0, 1}, {1, 0.5}};
  const auto r = mesh_of(pb);
  for (const Vec2 f : pb.fixed)
    CHECK(std::find(r.mesh.points.begin(), r.mesh.points.end(), f) != r.mesh.points.end());
  CHECK(mesh_area(r.mesh) == Approx(2.0).epsilon(1e-9));  // straight sides: exact up to rounding
}

TEST_CASE("curvature refinement puts more nodes on curved boundaries", "[distmesh]") {
  DistMeshProblem coarse = unit_circle(0.2);
  DistMeshProblem refined = coarse;
  refined.curvature_angle = 2 * std::numbers::pi / 48;
  const auto a = mesh_of(coarse), b = mesh_of(refined);
  const auto na = boundary_points(a.mesh, mesh_edges(a.mesh)).size();
  const auto nb = boundary_points(b.mesh, mesh_edges(b.mesh)).size();
  CHECK(nb >= 44);
  CHECK(nb > na);
  CHECK(b.stats.lattice_spacing < 0.2);
  // The chord error of the area falls below 0.5 % only with the refinement.
  CHECK(std::abs(mesh_area(b.mesh) - std::numbers::pi) / std::numbers::pi < 0.005);
}

TEST_CASE("internal boundaries: no triangle straddles dI = 0", "[distmesh]") {
  DistMeshProblem pb{.domain = rectangle({-1, -1}, {1, 1}), .h0 = 0.1, .bbox = {{-1, -1}, {1, 1}}};
  pb.interface = circle({0, 0}, 0.5);
  pb.fixed = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const auto r = mesh_of(pb);
  CHECK(r.stats.interface_straddling == 0);
  int inside = 0;
  for (std::size_t t = 0; t < r.mesh.triangles.size(); ++t) {
    int lo = 1, hi = -1;
    for (int v : r.mesh.triangles[t]) {
      const double d = (*pb.interface)(r.mesh.points[v]);
      const int side = d > 1e-9 ? 1 : (d < -1e-9 ? -1 : 0);
      lo = std::min(lo, side);
      hi = std::max(hi, side);
    }
    REQUIRE_FALSE((lo < 0 && hi > 0));
    // The label agrees with the side the triangle's corners are on.
    if (hi > 0) CHECK(r.phase[t] == 0);
    if (lo < 0) CHECK(r.phase[t] == 1);
    inside += r.phase[t];
  }
  CHECK(inside > 0);
}

TEST_CASE("bad problems are reported and not meshed", "[distmesh]") {
  CHECK_THROWS_AS(mesh_of({.domain = circle({0, 0}, 1), .h0 = 0, .bbox = {{-1, -1}, {1, 1}}}), ConfigError);
  CHECK_THROWS_AS(mesh_of({.domain = circle({0, 0}, 1), .h0 = 0.1, .bbox = {}}), ConfigError);
  // The bounding box misses the domain.
  CHECK_THROWS_WITH(mesh_of({.domain = circle({0, 0}, 1), .h0 = 0.1, .bbox = {{5, 5}, {6, 6}}}),
                    Contains("empty inside its bounding box"));
  // The size function is negative in part of the domain (eq. 3.12 on too large a disk).
  CHECK_THROWS_WITH(mesh_of({.domain = circle({0, 0}, 1),
                             .size = expression_size("1 - 1.5*sqrt(x^2+y^2)", "k"),
                             .h0 = 0.1,
                             .bbox = {{-1, -1}, {1, 1}}}),
                    Contains("must be finite and positive"));
  CHECK_THROWS_WITH(mesh_of({.domain = circle({0, 0}, 1),
                             .size = expression_size("sqrt(-1)", "k"),
                             .h0 = 0.1,
                             .bbox = {{-1, -1}, {1, 1}}}),
                    Contains("is NaN"));
  DistMeshProblem outside = unit_circle(0.1);
  outside.fixed = {{3, 3}};
  CHECK_THROWS_WITH(mesh_of(outside), Contains("fixed point (3, 3) lies outside"));
}
