#include "grains3d/smooth_interior.hpp"

#include <algorithm>

#include "mesh/tetmesh.hpp"

namespace grainmesh {

namespace {

// The circumcentre of tetrahedron abcd.
Vec3 circumcentre(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const Vec3 num = dot(u, u) * cross(v, w) + dot(v, v) * cross(w, u) + dot(w, w) * cross(u, v);
  return a + num / (2.0 * dot(u, cross(v, w)));
}

}  // namespace

int smooth_free_points(std::vector<Vec3>& points, const std::vector<std::array<int, 4>>& tets, int first_free, int passes) {
  const int n = static_cast<int>(points.size());
  std::vector<std::vector<int>> star(n > first_free ? n - first_free : 0);
  for (int t = 0; t < static_cast<int>(tets.size()); ++t)
    for (int v : tets[t])
      if (v >= first_free) star[v - first_free].push_back(t);
  // The smallest radius ratio over the star of p with p at `at`; 0 when one turns over.
  auto worst = [&](int p, Vec3 at) {
    const Vec3 keep = points[p];
    points[p] = at;
    double q = 1.0;
    for (int t : star[p - first_free]) {
      const auto& k = tets[t];
      const Vec3 a = points[k[0]], b = points[k[1]], c = points[k[2]], d = points[k[3]];
      if (!(tet_volume(a, b, c, d) > 0.0)) {
        q = 0.0;
        break;
      }
      q = std::min(q, radius_ratio(a, b, c, d));
    }
    points[p] = keep;
    return q;
  };
  int moved = 0;
  for (int pass = 0; pass < passes; ++pass) {
    moved = 0;
    for (int p = first_free; p < n; ++p) {
      const auto& s = star[p - first_free];
      if (s.empty()) continue;
      Vec3 mean{}, odt{};
      double volume = 0.0;
      int count = 0;
      for (int t : s) {
        const auto& k = tets[t];
        for (int v : k)
          if (v != p) {
            mean += points[v];
            ++count;
          }
        const double vol = tet_volume(points[k[0]], points[k[1]], points[k[2]], points[k[3]]);
        odt += vol * circumcentre(points[k[0]], points[k[1]], points[k[2]], points[k[3]]);
        volume += vol;
      }
      mean = mean / static_cast<double>(count);
      odt = odt / volume;
      const double now = worst(p, points[p]), by_mean = worst(p, mean), by_odt = worst(p, odt);
      if (std::max(by_mean, by_odt) > now) {
        points[p] = by_odt >= by_mean ? odt : mean;
        ++moved;
      }
    }
  }
  return moved;
}

}  // namespace grainmesh
