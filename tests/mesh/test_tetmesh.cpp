// Tetrahedron measures against exact values: the regular tetrahedron, the unit corner
// tetrahedron, a flat one.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "mesh/tetmesh.hpp"

using namespace grainmesh;

TEST_CASE("tetrahedron volume, radius ratio and dihedral angles are exact on known shapes", "[tetmesh]") {
  constexpr double deg = 180.0 / std::numbers::pi;
  // Regular: radius ratio 1, every dihedral angle acos(1/3) = 70.5288 degrees.
  const Vec3 a{1, 1, 1}, b{1, -1, -1}, c{-1, 1, -1}, d{-1, -1, 1};
  REQUIRE(std::abs(tet_volume(a, b, c, d)) == Approx(8.0 / 3.0));
  REQUIRE(radius_ratio(a, b, c, d) == Approx(1.0).epsilon(1e-14));
  for (double angle : dihedral_angles(a, b, c, d)) REQUIRE(angle * deg == Approx(std::acos(1.0 / 3.0) * deg));
  // The unit corner: volume 1/6, r_in = 1 / (3 + sqrt 3), r_circ = sqrt(3) / 2, angles 90
  // degrees at the three axes' edges and acos(1 / sqrt 3) at the others.
  const Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  REQUIRE(tet_volume(o, x, y, z) == Approx(1.0 / 6.0));
  REQUIRE(tet_volume(o, y, x, z) == Approx(-1.0 / 6.0));
  REQUIRE(radius_ratio(o, x, y, z) == Approx(3.0 / (3.0 + std::sqrt(3.0)) / (std::sqrt(3.0) / 2.0)));
  const auto angles = dihedral_angles(o, x, y, z);  // at ox, oy, oz, xy, xz, yz
  for (int k : {0, 1, 2}) REQUIRE(angles[k] * deg == Approx(90.0));
  for (int k : {3, 4, 5}) REQUIRE(angles[k] * deg == Approx(std::acos(1.0 / std::sqrt(3.0)) * deg));
  // Flat: no volume, radius ratio 0.
  REQUIRE(radius_ratio(o, x, y, Vec3{1, 1, 0}) == 0.0);
  // Flat to rounding, its corners on one circle (a rectangle a 3D mesh once held at the
  // box's edge: volume 2e-21 from rounding, the circumsphere 0 / 0): 0, not infinity.
  const Vec3 p0{0.95, 0.0, 0.1875}, p1{1.0, 0.0375, 0.15}, p2{1.0, 0.0, 0.1875}, p3{0.95, 0.0375, 0.15};
  REQUIRE(radius_ratio(p0, p1, p2, p3) == 0.0);
  REQUIRE(radius_ratio(p0, p1, p3, p2) == 0.0);
  // The smallest dihedral sine over the regular's: 1 for the regular, sin(acos(1 / sqrt 3)) =
  // sqrt(2/3) over 2 sqrt(2) / 3 for the corner, 0 when flat; on random tetrahedra the
  // sines of dihedral_angles' angles.
  REQUIRE(dihedral_sine_ratio(a, b, c, d) == Approx(1.0).epsilon(1e-14));
  REQUIRE(dihedral_sine_ratio(o, x, y, z) == Approx(std::sqrt(2.0 / 3.0) / (2.0 * std::sqrt(2.0) / 3.0)));
  REQUIRE(dihedral_sine_ratio(o, x, y, Vec3{1, 1, 0}) == Approx(0.0).margin(1e-15));
  std::uint64_t state = 7;
  auto next = [&] { state = state * 6364136223846793005u + 1442695040888963407u; return static_cast<double>(state >> 11) / 9007199254740992.0; };
  for (int k = 0; k < 100; ++k) {
    const Vec3 r0{next(), next(), next()}, r1{next(), next(), next()}, r2{next(), next(), next()}, r3{next(), next(), next()};
    double lowest = 1.0;
    for (double angle : dihedral_angles(r0, r1, r2, r3)) lowest = std::min(lowest, std::sin(angle));
    REQUIRE(dihedral_sine_ratio(r0, r1, r2, r3) == Approx(lowest / (2.0 * std::sqrt(2.0) / 3.0)).epsilon(1e-9));
    const TetShape shape = tet_shape(r0, r1, r2, r3);  // the two found together: the same bits
    REQUIRE(shape.dihedral_sine_ratio == dihedral_sine_ratio(r0, r1, r2, r3));
    REQUIRE(shape.radius_ratio == radius_ratio(r0, r1, r2, r3));
  }
  // The quality summary of a mesh of the two.
  const TetMesh m{{a, b, c, d, o, x, y, z}, {{0, 1, 2, 3}, {4, 5, 6, 7}}};
  const TetQuality q = measure_quality(m);
  REQUIRE(q.q_min == Approx(radius_ratio(o, x, y, z)));
  REQUIRE(q.min_dihedral_deg == Approx(std::acos(1.0 / std::sqrt(3.0)) * deg));
  REQUIRE(q.max_dihedral_deg == Approx(90.0));
  REQUIRE(q.share_dihedral_below_10 == 0.0);
  // The regular tetrahedron's edge and volume, each the other's inverse.
  REQUIRE(regular_tet_volume(std::sqrt(8.0)) == Approx(8.0 / 3.0));
  REQUIRE(regular_tet_edge(regular_tet_volume(0.3)) == Approx(0.3));
}
