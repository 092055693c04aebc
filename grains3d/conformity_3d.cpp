// check_conformity(Tessellation3, GrainMesh3): the 3D conformity checker.
#include "grains3d/conformity_3d.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "tessellate/solid_moments.hpp"

namespace grainmesh {

namespace {

[[noreturn]] void fail(const std::string& what) { throw GeometryError("3D mesh not conforming: " + what); }

using Key = std::array<int, 3>;
Key key(int a, int b, int c) {
  Key k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

}  // namespace

std::vector<double> surface_volumes(const Tessellation3& t, const GrainMesh3& m) {
  const auto& p = m.mesh.points;
  // About the box's centre, near every point: the sums' rounding stays small.
  std::vector<SolidMoments> grain(t.grains.size(), SolidMoments(0.5 * t.size()));
  for (std::size_t f = 0; f < t.faces.size() && f < m.faces.size(); ++f)
    for (const auto& [a, b, c] : m.faces[f]) {
      // The triangle turns outward of the back region, inward of the front one.
      grain[t.regions[t.faces[f].back].grain].add_triangle(p[a], p[b], p[c]);
      if (t.faces[f].front >= 0) grain[t.regions[t.faces[f].front].grain].add_triangle(p[a], p[c], p[b]);
    }
  std::vector<double> volume;
  for (const SolidMoments& g : grain) volume.push_back(g.volume());
  return volume;
}

double grain_volume_change_max(const Tessellation3& t, const GrainMesh3& m) {
  const std::vector<double> enclosed = surface_volumes(t, m);
  double largest = 0.0;
  for (std::size_t g = 0; g < t.grains.size(); ++g)
    if (t.grains[g].volume > 0.0)
      largest = std::max(largest, std::abs(enclosed[g] - t.grains[g].volume) / t.grains[g].volume);
  return largest;
}

void check_conformity(const Tessellation3& t, const GrainMesh3& m) {
  const auto& p = m.mesh.points;
  const Vec3 box = t.size();
  const std::size_t nt = m.mesh.tets.size();
  if (m.grain.size() != nt || m.phase.size() != nt || m.region.size() != nt) fail("labels are not one per tetrahedron");
  std::vector<double> volume(t.grains.size(), 0.0);
  std::map<Key, std::vector<int>> sides;  // triangle -> the tetrahedra it bounds
  for (std::size_t k = 0; k < nt; ++k) {
    const auto& tet = m.mesh.tets[k];
    for (int v : tet)
      if (v < 0 || v >= static_cast<int>(p.size())) fail("tetrahedron " + std::to_string(k) + " has a point id out of range");
    const double v = tet_volume(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]);
    if (!(radius_ratio(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]) > 0.0) || !(v > 0.0))
      fail("tetrahedron " + std::to_string(k) + " is flat or turned (volume " + to_text(v) + ")");
    if (m.grain[k] != t.regions[m.region[k]].grain) fail("tetrahedron " + std::to_string(k) + " is not in its region's grain");
    volume[m.grain[k]] += v;
    for (const Key& f : {key(tet[0], tet[1], tet[2]), key(tet[0], tet[1], tet[3]), key(tet[0], tet[2], tet[3]),
                         key(tet[1], tet[2], tet[3])})
      sides[f].push_back(static_cast<int>(k));
  }
  for (const auto& [f, tets] : sides) {
    if (tets.size() > 2) fail("a triangle bounds " + std::to_string(tets.size()) + " tetrahedra");
    if (tets.size() == 2) continue;
    bool on_box = false;
    for (int a = 0; a < 3 && !on_box; ++a)
      for (double side : {0.0, box[a]})
        on_box = on_box || (p[f[0]][a] == side && p[f[1]][a] == side && p[f[2]][a] == side);
    if (!on_box) fail("a triangle inside the box bounds one tetrahedron only (a hole or a gap between regions)");
  }
  // The surfaces kept: each face's triangles are triangles of the mesh, with a tetrahedron
  // of the face's back region on one side and of its front region (or nothing) on the other.
  if (m.faces.size() != t.faces.size()) fail("the surface triangles are not one list per face");
  for (std::size_t f = 0; f < t.faces.size(); ++f) {
    const Face3& face = t.faces[f];
    for (const auto& tr : m.faces[f]) {
      const auto it = sides.find(key(tr[0], tr[1], tr[2]));
      if (it == sides.end()) fail("a triangle of face " + std::to_string(f) + " is no triangle of the mesh");
      std::vector<int> regions;
      for (int k : it->second) regions.push_back(m.region[k]);
      std::sort(regions.begin(), regions.end());
      std::vector<int> want{face.back};
      if (face.front >= 0) want.push_back(face.front);
      std::sort(want.begin(), want.end());
      if (regions != want) fail("a triangle of face " + std::to_string(f) + " lies between the wrong regions");
    }
  }
  const std::vector<double> enclosed = surface_volumes(t, m);
  for (std::size_t g = 0; g < t.grains.size(); ++g) {
    if (std::abs(volume[g] - enclosed[g]) > 1e-9 * t.grains[g].volume)
      fail("grain " + std::to_string(g) + "'s tetrahedra fill " + to_text(volume[g], 15) + ", its surface triangles enclose " +
           to_text(enclosed[g], 15));
    if (std::abs(enclosed[g] - t.grains[g].volume) > (kBentFaceVolume + 1e-9) * t.grains[g].volume)
      fail("grain " + std::to_string(g) + "'s surface triangles enclose " + to_text(enclosed[g], 15) + ", its polyhedron " +
           to_text(t.grains[g].volume, 15));
  }
  const double tol = 1e-12 * std::max({box.x, box.y, box.z});
  for (int a = 0; a < 3; ++a)
    for (const auto& [lo, hi] : m.pairs.axis[a]) {
      Vec3 d = p[hi] - p[lo];
      d[a] -= box[a];
      if (norm(d) > tol) fail("paired points " + std::to_string(lo) + " and " + std::to_string(hi) + " are not images across the box");
    }
}

}  // namespace grainmesh
