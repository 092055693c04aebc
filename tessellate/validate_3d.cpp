// validate(Tessellation3): the invariants of a cut 3D tessellation.
#include <cmath>
#include <map>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "tessellate/validate_3d.hpp"

namespace grainmesh {

namespace {

[[noreturn]] void fail(const std::string& what) { throw GeometryError("3D tessellation invalid: " + what); }

}  // namespace


void validate(const Tessellation3& t) {
  const int nr = static_cast<int>(t.regions.size());
  const int nv = static_cast<int>(t.vertices.size());
  for (int f = 0; f < static_cast<int>(t.faces.size()); ++f) {
    const Face3& face = t.faces[f];
    const std::string name = "face " + std::to_string(f);
    if (face.ring.size() < 3) fail(name + " has fewer than 3 vertices");
    for (int id : face.ring)
      if (id < 0 || id >= nv) fail(name + " has a vertex id out of range");
    if (face.back < 0 || face.back >= nr || face.front >= nr || face.front == face.back)
      fail(name + " does not lie between two regions");
    if (face.front < 0 && box_side(t, face.ring).first < 0) fail(name + " bounds one region only but is not on the box");
  }
  double total = 0.0;
  std::vector<double> grain_volume(t.grains.size(), 0.0);
  for (int r = 0; r < nr; ++r) {
    const Region3& region = t.regions[r];
    const std::string name = "region " + std::to_string(r);
    if (region.faces.size() < 4) fail(name + " has fewer than 4 faces");
    if (region.grain < 0 || region.grain >= static_cast<int>(t.grains.size())) fail(name + " has no grain");
    if (region.phase != t.grains[region.grain].phase) fail(name + " and its grain differ in phase");
    // Closed and outward: each edge, as its face runs it seen from outside, once each way.
    std::map<std::pair<int, int>, int> edges;
    for (int f : region.faces) {
      const Face3& face = t.faces[f];
      if (face.back != r && face.front != r) fail(name + " lists face " + std::to_string(f) + " that does not bound it");
      const std::size_t n = face.ring.size();
      for (std::size_t k = 0; k < n; ++k) {
        int a = face.ring[k], b = face.ring[(k + 1) % n];
        if (face.back != r) std::swap(a, b);
        if (++edges[{a, b}] > 1) fail(name + " runs an edge twice the same way");
      }
    }
    for (const auto& [e, count] : edges)
      if (!edges.contains({e.second, e.first})) fail(name + " is not closed at edge " + std::to_string(e.first) + "-" + std::to_string(e.second));
    const double v = region_volume(t, region);
    if (!(v > 0.0)) fail(name + " has volume " + to_text(v));
    if (std::abs(v - region.volume) > 1e-12 * std::abs(v) + 1e-300) fail(name + "'s stored volume differs from its faces'");
    total += v;
    grain_volume[region.grain] += v;
  }
  const double box = t.width * t.height * t.depth;
  if (std::abs(total - box) > 1e-9 * box)
    fail("the regions' volumes sum to " + to_text(total, 15) + ", the box's is " + to_text(box, 15));
  for (std::size_t g = 0; g < t.grains.size(); ++g)
    if (std::abs(grain_volume[g] - t.grains[g].volume) > 1e-9 * t.grains[g].volume)
      fail("grain " + std::to_string(g) + "'s volume differs from its regions'");
  const Vec3 size = t.size();
  for (int a = 0; a < 3; ++a)
    for (const auto& [lo, hi] : t.partners.axis[a]) {
      Vec3 shifted = t.vertices[lo];
      shifted[a] += size[a];
      if (t.vertices[lo][a] != 0.0 || !(shifted == t.vertices[hi]))
        fail("periodic partners " + std::to_string(lo) + " and " + std::to_string(hi) + " are not images");
    }
  if (!t.periodic)
    for (const auto& pairs : t.partners.axis)
      if (!pairs.empty()) fail("periodic partners in a bounded box");
}

}  // namespace grainmesh
