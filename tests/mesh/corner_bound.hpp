// The quality bound the mesh stage promises, sharp corners included: every triangle has
// q >= min(0.6, 0.9 q*(alpha)), alpha the sharpest region corner it touches and q*(alpha)
// the best radius ratio a triangle in that corner can have (on random cells of every
// kind, unregularised Laguerre cells with edges a millionth long included, 0.55 in place
// of 0.6).
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "grains/grain_mesh.hpp"
#include "mesh/quality.hpp"

namespace grainmesh::test {

// q*(alpha): a triangle in a corner of angle alpha with its other two angles equal,
// 8 sin(alpha/2) sin^2(45 deg - alpha/4).
inline double best_in_corner(double alpha) {
  const double s = std::sin(std::numbers::pi / 4 - alpha / 4);
  return 8.0 * std::sin(alpha / 2) * s * s;
}

// Interior angle of each region at each of its vertices, by (grain, vertex); a grain's
// pieces never share a vertex, so the grain names the piece.
inline std::map<std::pair<int, int>, double> corner_angles(const Tessellation& t) {
  std::map<std::pair<int, int>, double> angle;
  for (const Region& r : t.regions)
    for (const auto& ring : r.rings)
      for (std::size_t k = 0, n = ring.size(); k < n; ++k) {
        const Vec2 prev = t.vertices[ring[(k + n - 1) % n]], v = t.vertices[ring[k]], next = t.vertices[ring[(k + 1) % n]];
        double a = std::atan2(cross(next - v, prev - v), dot(next - v, prev - v));
        if (a < 0.0) a += 2.0 * std::numbers::pi;
        const auto key = std::make_pair(r.grain, ring[k]);
        const auto it = angle.find(key);
        if (it == angle.end() || a < it->second) angle[key] = a;
      }
  return angle;
}

struct CornerBoundCheck {
  int failures = 0;
  double sharpest_corner = std::numbers::pi;  // radians, over the triangles' corners
  std::string first;                          // the first failure, described
};

// Every triangle against min(plain, 0.9 q*(alpha)).
inline CornerBoundCheck check_corner_bound(const Tessellation& t, const GrainMesh& m, double plain = 0.6) {
  CornerBoundCheck out;
  const auto angle = corner_angles(t);
  const std::vector<double> q = triangle_quality(m.mesh);
  const int nv = static_cast<int>(t.vertices.size());
  for (std::size_t k = 0; k < q.size(); ++k) {
    double alpha = std::numbers::pi;  // no corner: the plain bound
    for (int v : m.mesh.triangles[k])
      if (v < nv) {
        const auto it = angle.find({m.grain[k], v});
        if (it != angle.end()) alpha = std::min(alpha, it->second);
      }
    out.sharpest_corner = std::min(out.sharpest_corner, alpha);
    if (q[k] < std::min(plain, 0.9 * best_in_corner(alpha))) {
      if (out.failures++ == 0)
        out.first = "triangle " + std::to_string(k) + " has q " + std::to_string(q[k]) + " at a corner of " +
                    std::to_string(alpha * 180 / std::numbers::pi) + " deg";
    }
  }
  return out;
}

}  // namespace grainmesh::test
