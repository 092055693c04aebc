// Every example of the thesis' Chapter 3 (data/examples/) against the acceptance bounds:
// q_min >= 0.5, mean q >= 0.97, a valid mesh, boundary nodes within 1e-3 h0 of the
// zero level set, the exact area within 0.5 % where it is known, and the fibre
// fractions within 0.5 % absolute.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <optional>

#include "helpers.hpp"
#include "mesh/quality.hpp"
#include "pipelines/domain_command.hpp"

using namespace grainmesh;
using std::numbers::pi;

namespace {

struct Expected {
  std::optional<double> area;            // exact area of the domain
  std::optional<double> inner_fraction;  // exact area fraction inside the interface
};

const std::map<std::string, Expected>& expected() {
  static const std::map<std::string, Expected> table{
      {"circle_h02", {pi, {}}},
      {"circle_h01", {pi, {}}},
      {"ellipse", {2 * pi, {}}},
      {"union_polygon_circle", {2.25 + pi / 8, {}}},
      {"ellipse_minus_circle", {7 * pi, {}}},
      {"intersection_two_circles", {4.5 * std::acos(5.0 / 6.0) - 1.25 * std::sqrt(2.75), {}}},
      {"polygon_hexagon", {1.5 * std::sqrt(3.0), {}}},
      {"polygon_nonconvex_hole", {2.92, {}}},
      {"plate_with_hole", {4 - pi / 4, {}}},
      {"graded_hole", {4 - pi / 4, {}}},
      {"graded_disk", {pi / 4, {}}},
      {"interface_basic", {4.0, pi / 16}},
      {"fibres_6", {1.0, 0.19}},
      {"fibres_20", {1.0, 0.15}},
  };
  return table;
}

void check_example(const std::string& name) {
  const Config config = Config::from_file(test::example(name));
  const DomainJob job = read_domain_job(config);
  const DistMeshResult r = mesh_domain(job);
  const TriMesh& mesh = r.mesh;
  const Expected& want = expected().at(name);

  REQUIRE_NOTHROW(validate(mesh));  // no inverted or zero-area triangle, every point used
  CHECK(r.stats.converged);
  const MeshQuality q = measure_quality(mesh);
  CHECK(q.q_min >= 0.5);
  CHECK(q.q_mean >= 0.97);

  double worst = 0.0;
  for (int v : boundary_points(mesh, mesh_edges(mesh)))
    worst = std::max(worst, std::abs(job.problem.domain(mesh.points[v])));
  CHECK(worst <= 1e-3 * job.problem.h0);

  const double area = mesh_area(mesh);
  if (want.area) CHECK(std::abs(area - *want.area) <= 0.005 * *want.area);

  if (want.inner_fraction) {
    CHECK(r.stats.interface_straddling == 0);
    double inner = 0.0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (r.phase[t] == 1) inner += triangle_area(mesh, static_cast<int>(t));
    CHECK(std::abs(inner / area - *want.inner_fraction) <= 0.005);
  }
}

}  // namespace

TEST_CASE("every example file is checked here", "[examples]") {
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_dir() / "data" / "examples")) {
    // grains_*.ini are tessellation configs, checked in test_tessellate_cli.cpp.
    if (entry.path().extension() != ".ini" || entry.path().stem().string().rfind("grains_", 0) == 0) continue;
    ++files;
    CHECK(expected().count(entry.path().stem().string()) == 1);
  }
  CHECK(files == expected().size());
}

#define EXAMPLE_TEST(name) \
  TEST_CASE("example " #name " meets the acceptance bounds", "[examples]") { check_example(#name); }

EXAMPLE_TEST(circle_h02)
EXAMPLE_TEST(circle_h01)
EXAMPLE_TEST(ellipse)
EXAMPLE_TEST(union_polygon_circle)
EXAMPLE_TEST(ellipse_minus_circle)
EXAMPLE_TEST(intersection_two_circles)
EXAMPLE_TEST(polygon_hexagon)
EXAMPLE_TEST(polygon_nonconvex_hole)
EXAMPLE_TEST(plate_with_hole)
EXAMPLE_TEST(graded_hole)
EXAMPLE_TEST(graded_disk)
EXAMPLE_TEST(interface_basic)
EXAMPLE_TEST(fibres_6)
EXAMPLE_TEST(fibres_20)
