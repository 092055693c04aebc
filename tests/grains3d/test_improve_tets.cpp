// Tetrahedral mesh improvement (flips, point insertion, smoothing) inside a region whose
// surface stays: on a cube cut into tetrahedra with a badly placed inner point, and on
// the grain meshes of a drawn cell against the same meshes unimproved.
#include <algorithm>
#include <map>

#include <catch2/catch.hpp>

#include "grains3d/conformity_3d.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "grains3d/improve_tets.hpp"
#include "mesh/tetmesh.hpp"
#include "tessellate/tessellation_3d.hpp"
#include "tessellate/tessellate_3d.hpp"

using namespace grainmesh;

namespace {

using Tet = std::array<int, 4>;

// Faces that belong to one tetrahedron only (the region's surface), as sorted triples.
std::vector<std::array<int, 3>> surface(const std::vector<Tet>& tets) {
  std::map<std::array<int, 3>, int> count;
  for (const Tet& t : tets)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      for (int i = 0, n = 0; i < 4; ++i)
        if (i != skip) f[n++] = t[i];
      std::sort(f.begin(), f.end());
      ++count[f];
    }
  std::vector<std::array<int, 3>> out;
  for (const auto& [f, n] : count) {
    REQUIRE(n <= 2);
    if (n == 1) out.push_back(f);
  }
  return out;
}

double volume(const std::vector<Vec3>& p, const std::vector<Tet>& tets, double* worst) {
  double v = 0.0;
  *worst = 1.0;
  for (const Tet& t : tets) {
    const double tv = tet_volume(p[t[0]], p[t[1]], p[t[2]], p[t[3]]);
    REQUIRE(tv > 0.0);
    v += tv;
    *worst = std::min(*worst, radius_ratio(p[t[0]], p[t[1]], p[t[2]], p[t[3]]));
  }
  return v;
}

}  // namespace

TEST_CASE("tetrahedra improved inside a cube: surface, corners and volume kept, worst raised", "[mesh3d][improve]") {
  // The unit cube's corners (x + 2y + 4z) cut into the six tetrahedra around its diagonal
  // 0-7, and a free point 8 put next to the face 1-3-7 of one of them, splitting it in four.
  std::vector<Vec3> points;
  for (int i = 0; i < 8; ++i) points.push_back({double(i & 1), double(i >> 1 & 1), double(i >> 2 & 1)});
  std::vector<Tet> tets{{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
  const Vec3 near_face = 0.02 * points[0] + (0.98 / 3.0) * (points[1] + points[3] + points[7]);
  points.push_back(near_face);
  tets.erase(tets.begin());
  for (int k = 0; k < 4; ++k) {
    Tet t{0, 1, 3, 7};
    t[k] = 8;
    tets.push_back(t);
  }
  for (Tet& t : tets)
    if (tet_volume(points[t[0]], points[t[1]], points[t[2]], points[t[3]]) < 0.0) std::swap(t[2], t[3]);
  const auto before_surface = surface(tets);
  REQUIRE(before_surface.size() == 12);
  double before_worst = 0.0;
  REQUIRE(volume(points, tets, &before_worst) == Approx(1.0).epsilon(1e-14));
  REQUIRE(before_worst < 0.1);

  std::vector<Vec3> p = points;
  std::vector<Tet> t = tets;
  const TetImprovement done = improve_tets(p, t, 8, 5);
  CAPTURE(done.edge_removals, done.face_flips, done.insertions, done.moves);
  REQUIRE(done.edge_removals + done.face_flips + done.insertions + done.moves > 0);
  for (int i = 0; i < 8; ++i) REQUIRE(p[i] == points[i]);  // the surface points bit for bit
  REQUIRE(surface(t) == before_surface);                    // the surface triangles
  double after_worst = 0.0;
  REQUIRE(volume(p, t, &after_worst) == Approx(1.0).epsilon(1e-12));
  CAPTURE(before_worst, after_worst);
  REQUIRE(after_worst > 0.5);

  // The same input, the same output.
  std::vector<Vec3> p2 = points;
  std::vector<Tet> t2 = tets;
  improve_tets(p2, t2, 8, 5);
  REQUIRE(p2 == p);
  REQUIRE(t2 == t);
}

TEST_CASE("improved grain meshes conform and beat the unimproved ones", "[mesh3d][improve]") {
  Tessellation3Options o;
  o.grains = 20;
  o.lloyd_iterations = 3;
  o.phases = {Phase{"WC", 0.8, false, 1.0, 0.3, {}}, Phase{"Co", 0.2, true, 1.0, 0.3, {}}};
  Rng rng(4);
  const Tessellation3 t = tessellate_3d(o, rng);
  const double size = size_for_tets_per_grain(t, 240);
  const GrainMesh3 plain = mesh_tessellation_3d(t, {.size = size, .improvement_passes = 0});
  const GrainMesh3 improved = mesh_tessellation_3d(t, {.size = size});
  REQUIRE_NOTHROW(check_conformity(t, improved));
  REQUIRE(improved.surface_points == plain.surface_points);
  for (int k = 0; k < improved.surface_points; ++k) REQUIRE(improved.mesh.points[k] == plain.mesh.points[k]);
  const TetQuality a = measure_quality(plain.mesh), b = measure_quality(improved.mesh);
  CAPTURE(a.q_mean, b.q_mean, a.q_min, b.q_min, a.share_dihedral_below_10, b.share_dihedral_below_10);
  REQUIRE(b.q_mean > a.q_mean + 0.02);
  REQUIRE(b.q_min >= a.q_min);  // the worst is on the surface here: the surface stays
  REQUIRE(b.share_dihedral_below_10 < 0.6 * a.share_dihedral_below_10);
}
