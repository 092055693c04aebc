// The 3D mesh stage: conforming tetrahedra grain by grain on hand-made and drawn cells,
// periodic and bounded: the conformity checker, exact grain volumes, paired surface
// points, the quality reached, and the same mesh whatever the thread count.
#include <cmath>
#include <map>
#include <set>

#include <catch2/catch.hpp>

#include "grains3d/conformity_3d.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "mesh/tetmesh.hpp"
#include "tessellate/bent_face.hpp"
#include "tessellate/tessellation_3d.hpp"
#include "tessellate/tessellate_3d.hpp"

using namespace grainmesh;

namespace {

Phase phase(const std::string& name, double fraction, bool rest = false) {
  return Phase{.name = name, .fraction = fraction, .rest = rest, .youngs_modulus = 1.0, .poisson_ratio = 0.3, .alpha = {}};
}

Tessellation3 cell(int grains, bool periodic, std::uint64_t seed, int lloyd = 3, double min_edge = 0.1) {
  Tessellation3Options o;
  o.grains = grains;
  o.periodic = periodic;
  o.lloyd_iterations = lloyd;
  o.min_edge = min_edge;
  o.phases = {phase("WC", 0.8), phase("Co", 0.2, true)};
  if (grains == 1) o.phases = {phase("WC", 1.0)};
  Rng rng(seed);
  return tessellate_3d(o, rng);
}

// The bent faces: two or more triangles between the same two regions (bent_face.hpp).
std::map<std::pair<int, int>, std::vector<int>> pieces_between(const Tessellation3& t) {
  std::map<std::pair<int, int>, std::vector<int>> between;
  for (int f = 0; f < static_cast<int>(t.faces.size()); ++f)
    if (t.faces[f].front >= 0 && t.faces[f].ring.size() == 3) between[std::minmax(t.faces[f].back, t.faces[f].front)].push_back(f);
  std::erase_if(between, [](const auto& group) { return group.second.size() < 2; });
  return between;
}

// Whether a triangle of a piece has another piece's corner: the pieces meshed as one.
bool meshed_across(const Tessellation3& t, const GrainMesh3& m, const std::vector<int>& pieces) {
  for (int f : pieces) {
    const std::set<int> corners(t.faces[f].ring.begin(), t.faces[f].ring.end());
    for (const auto& tr : m.faces[f])
      for (int v : tr)
        if (v < static_cast<int>(t.vertices.size()) && !corners.contains(v)) return true;
  }
  return false;
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
      const GrainMesh3 m = mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 240)});
      REQUIRE_NOTHROW(check_conformity(t, m));  // also the grain volumes (kBentFaceVolume)
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

TEST_CASE("3D mesh: a bent face's pieces meshed as one surface, every point on a piece, volumes within the bound",
          "[mesh3d]") {
  int bent = 0, across = 0;  // bent faces met, and those meshed across their pieces
  for (std::uint64_t seed : {1u, 2u}) {
    CAPTURE(seed);
    const Tessellation3 t = cell(20, true, seed);
    const GrainMesh3 m = mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 240)});
    REQUIRE_NOTHROW(check_conformity(t, m));  // the tetrahedra fill the surfaces to 1e-9
    for (const auto& [regions, pieces] : pieces_between(t)) {
      ++bent;
      for (int f : pieces)
        for (const auto& tr : m.faces[f])
          for (int v : tr) {
            double off = 1e300;  // from the nearest piece's plane
            for (int g : pieces) {
              const auto& r = t.faces[g].ring;
              const Vec3 n = ring_normal(t.vertices, r);
              off = std::min(off, std::abs(dot(m.mesh.points[v] - t.vertices[r[0]], n)) / norm(n));
            }
            REQUIRE(off < 1e-12);
          }
      across += meshed_across(t, m, pieces) ? 1 : 0;
    }
    const std::vector<double> enclosed = surface_volumes(t, m);
    for (std::size_t g = 0; g < t.grains.size(); ++g) {
      CHECK(std::abs(enclosed[g] - t.grains[g].volume) < kBentFaceVolume * t.grains[g].volume);
    }
  }
  CHECK(bent > 0);
  CHECK(across > 0);
}

TEST_CASE("3D mesh: a bent face that meets a side of the box twice is meshed whole, no edge of it in the side",
          "[mesh3d]") {
  // Its outer ring has two corners on one side not next to each other (or three): an edge
  // of its triangles between two points on that side would lie in the side, where the
  // box's own face is. Such faces are meshed as one surface unless that happens.
  int touching = 0, whole = 0;
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    CAPTURE(seed);
    const Tessellation3 t = cell(40, true, seed, 5);
    const GrainMesh3 m = mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 240)});
    REQUIRE_NOTHROW(check_conformity(t, m));
    for (const auto& [regions, pieces] : pieces_between(t)) {
      std::map<std::pair<int, int>, int> uses, ring_uses;
      for (int f : pieces) {
        const auto& r = t.faces[f].ring;
        for (int k = 0; k < 3; ++k) ++ring_uses[std::minmax(r[k], r[(k + 1) % 3])];
        for (const auto& tr : m.faces[f])
          for (int k = 0; k < 3; ++k) ++uses[std::minmax(tr[k], tr[(k + 1) % 3])];
      }
      auto shared = [&](int a, int b) { return side_mask(m.mesh.points[a], t.size()) & side_mask(m.mesh.points[b], t.size()); };
      // Inside the face (two of its triangles on the edge): not in a side.
      for (const auto& [e, n] : uses)
        if (n == 2) REQUIRE(shared(e.first, e.second) == 0);
      // The ring's corners (edges of one piece only) on one side, not joined by a ring edge.
      std::set<int> corners;
      for (const auto& [e, n] : ring_uses)
        if (n == 1) corners.insert({e.first, e.second});
      bool twice = false;
      for (int a : corners)
        for (int b : corners)
          twice = twice || (a < b && shared(a, b) != 0 && !(ring_uses.contains({a, b}) && ring_uses.at({a, b}) == 1));
      if (!twice) continue;
      ++touching;
      whole += meshed_across(t, m, pieces) ? 1 : 0;
    }
  }
  CAPTURE(touching, whole);
  CHECK(touching > 0);
  CHECK(whole > 0);
}

TEST_CASE("3D mesh: bent faces move no grain's volume by more than their budget, however much they bend", "[mesh3d]") {
  // Edges up to 0.3 x the grain size collapsed: faces bent further (meshed whole, the
  // grains would move by up to 0.77 %).
  const Tessellation3 t = cell(40, true, 1, 5, 0.3);
  const GrainMesh3 m = mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 160)});
  REQUIRE_NOTHROW(check_conformity(t, m));
  const std::vector<double> enclosed = surface_volumes(t, m);
  double largest = 0.0;
  for (std::size_t g = 0; g < t.grains.size(); ++g)
    largest = std::max(largest, std::abs(enclosed[g] - t.grains[g].volume) / t.grains[g].volume);
  CHECK(largest <= kBentFaceVolume + 1e-12);
  CHECK(largest > 0.0);
}

TEST_CASE("3D mesh: the same mesh for 1 and 2 threads", "[mesh3d]") {
  const Tessellation3 t = cell(20, true, 3);
  const GrainMesh3 one = mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 160), .threads = 1});
  const GrainMesh3 two = mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 160), .threads = 2});
  REQUIRE(one.mesh.points == two.mesh.points);
  REQUIRE(one.mesh.tets == two.mesh.tets);
  REQUIRE(one.grain == two.grain);
}
