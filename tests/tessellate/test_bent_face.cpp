// How a bent face of a 3D tessellation is split into planar triangles: by diagonals
// (face_shape) or about a new centre point (centre_fan), and which the regularisation
// keeps on drawn cells.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "tessellate/bent_face.hpp"
#include "tessellate/tessellation_3d.hpp"
#include "tessellate/tessellate_3d.hpp"
#include "tessellate/validate_3d.hpp"

using namespace grainmesh;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A regular hexagon of unit radius about (0.5, 0.5, 0.5) in the plane z = 0.5, its first
// corner lifted by `lift`.
std::vector<Vec3> hexagon(double lift) {
  std::vector<Vec3> p;
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3.0;
    p.push_back({0.5 + 0.3 * std::cos(a), 0.5 + 0.3 * std::sin(a), 0.5 + (k == 0 ? lift : 0.0)});
  }
  return p;
}

}  // namespace

TEST_CASE("a bent hexagon: diagonals make 30 degree slices, a centre fan about 60 degree triangles", "[tessellate3d]") {
  const std::vector<int> ring{0, 1, 2, 3, 4, 5};
  const Vec3 box{1.0, 1.0, 1.0};
  REQUIRE(face_shape(hexagon(0.0), ring, 1e-12, box).planar);
  const std::vector<Vec3> p = hexagon(0.01);
  const FaceShape diagonals = face_shape(p, ring, 1e-12, box);
  REQUIRE_FALSE(diagonals.planar);
  REQUIRE(diagonals.valid);
  REQUIRE(diagonals.triangles.size() == 4);
  REQUIRE(smallest_angle(p, diagonals.triangles) == Approx(30.0 * kDeg).margin(1.0 * kDeg));
  const CentreFan fan = centre_fan(p, ring);
  REQUIRE(fan.valid);
  REQUIRE(fan.smallest_angle == Approx(60.0 * kDeg).margin(1.0 * kDeg));
  REQUIRE(fan.centre.z == Approx(0.5 + 0.01 / 6.0));  // the corners' mean
}

TEST_CASE("a centre fan that would fold is not valid", "[tessellate3d]") {
  // An arrow head: its corners' mean lies outside, beyond the notch, so a triangle of the
  // fan turns against the ring.
  const std::vector<Vec3> p{{0.0, 0.0, 0.0}, {1.0, 0.5, 0.0}, {0.0, 1.0, 0.0}, {0.9, 0.5, 0.001}};
  REQUIRE_FALSE(centre_fan(p, {0, 1, 2, 3}).valid);
}

TEST_CASE("regularised cells: every face planar, bent faces split about centres where that is wider", "[tessellate3d]") {
  for (bool periodic : {true, false}) {
    CAPTURE(periodic);
    Tessellation3Options o;
    o.grains = 100;
    o.periodic = periodic;
    o.lloyd_iterations = 3;
    o.phases = {Phase{"WC", 0.8, false, 1.0, 0.3, {}}, Phase{"Co", 0.2, true, 1.0, 0.3, {}}};
    Rng rng(5);
    const Tessellation3 t = tessellate_3d(o, rng);
    REQUIRE(t.stats.collapsed_edges > 0);
    // Planar: each face's points within 1e-12 of the box of the plane of its first three.
    int triangles = 0, thin = 0;
    for (const Face3& f : t.faces) {
      const Vec3 a = t.vertices[f.ring[0]], b = t.vertices[f.ring[1]], c = t.vertices[f.ring[2]];
      Vec3 n = cross(b - a, c - a);
      n = n / norm(n);
      for (int v : f.ring) REQUIRE(std::abs(dot(t.vertices[v] - a, n)) < 1e-12);
      if (f.ring.size() == 3) {
        ++triangles;
        thin += smallest_angle(t.vertices, {{f.ring[0], f.ring[1], f.ring[2]}}) < 15.0 * kDeg;
      }
    }
    // Few of the triangles are thin: 55 of 2,463 below 15 degrees on the periodic cell,
    // where the diagonals alone left 193 of 1,737.
    CAPTURE(triangles, thin);
    REQUIRE(triangles > 300);
    REQUIRE(thin < triangles / 20);
  }
}
