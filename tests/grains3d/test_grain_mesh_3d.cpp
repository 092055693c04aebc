// The 3D mesh stage: conforming tetrahedra grain by grain on hand-made and drawn cells,
// periodic and bounded: the conformity checker, exact grain volumes, paired surface
// points, the quality reached, and the same mesh whatever the thread count.
#include <cmath>

#include <catch2/catch.hpp>

#include "grains3d/conformity_3d.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "mesh/tetmesh.hpp"
#include "tessellate/tessellation_3d.hpp"
#include "tessellate/tessellate_3d.hpp"

using namespace grainmesh;

namespace {

Phase phase(const std::string& name, double fraction, bool rest = false) {
  return Phase{.name = name, .fraction = fraction, .rest = rest, .youngs_modulus = 1.0, .poisson_ratio = 0.3, .alpha = {}};
}

Tessellation3 cell(int grains, bool periodic, std::uint64_t seed, int lloyd = 3) {
  Tessellation3Options o;
  o.grains = grains;
  o.periodic = periodic;
  o.lloyd_iterations = lloyd;
  o.phases = {phase("WC", 0.8), phase("Co", 0.2, true)};
  if (grains == 1) o.phases = {phase("WC", 1.0)};
  Rng rng(seed);
  return tessellate_3d(o, rng);
}

}  // namespace

TEST_CASE("3D mesh: one grain fills the box exactly, conforming", "[mesh3d]") {
  const Tessellation3 t = cell(1, false, 1);
  const GrainMesh3 m = mesh_tessellation_3d(t, {.size = 0.2});
  REQUIRE_NOTHROW(check_conformity(t, m));
  double v = 0.0;
  for (const auto& tet : m.mesh.tets)
    v += tet_volume(m.mesh.points[tet[0]], m.mesh.points[tet[1]], m.mesh.points[tet[2]], m.mesh.points[tet[3]]);
  REQUIRE(v == Approx(1.0).epsilon(1e-12));
  REQUIRE(m.mesh.tets.size() > 100);
}

TEST_CASE("3D mesh: drawn cells conform, periodic surfaces pair up, grain volumes exact", "[mesh3d]") {
  for (bool periodic : {true, false})
    for (std::uint64_t seed : {1u, 2u}) {
      CAPTURE(periodic, seed);
      const Tessellation3 t = cell(20, periodic, seed);
      const GrainMesh3 m = mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 300)});
      REQUIRE_NOTHROW(check_conformity(t, m));  // also the grain volumes to 1e-9
      if (periodic)
        for (int a = 0; a < 3; ++a) REQUIRE(m.pairs.axis[a].size() > t.partners.axis[a].size());
      const TetQuality q = measure_quality(m.mesh);
      CAPTURE(q.q_min, q.q_mean, q.min_dihedral_deg, m.mesh.tets.size());
      REQUIRE(q.q_min > 0.0);
      REQUIRE(q.q_mean > 0.6);
      const double per_grain = static_cast<double>(m.mesh.tets.size()) / static_cast<double>(t.grains.size());
      REQUIRE(per_grain > 150);
      REQUIRE(per_grain < 1000);
    }
}

TEST_CASE("3D mesh: the same mesh for 1 and 2 threads", "[mesh3d]") {
  const Tessellation3 t = cell(20, true, 3);
  const GrainMesh3 one = mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 200), .threads = 1});
  const GrainMesh3 two = mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 200), .threads = 2});
  REQUIRE(one.mesh.points == two.mesh.points);
  REQUIRE(one.mesh.tets == two.mesh.tets);
  REQUIRE(one.grain == two.grain);
}
