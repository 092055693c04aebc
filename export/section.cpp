#include "export/section.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace grainmesh {

Section tessellation_section(const Tessellation3& t, double z) {
  Section s;
  std::map<std::pair<int, int>, int> point_of;  // (a, b) edge crossing, or (v, v) a vertex on the plane
  auto point_id = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, added] = point_of.emplace(key, static_cast<int>(s.cells.points.size()));
    if (added) {
      const Vec3 p = t.vertices[key.first], q = t.vertices[key.second];
      const double u = key.first == key.second ? 0.0 : (z - p.z) / (q.z - p.z);
      s.cells.points.push_back({p.x + u * (q.x - p.x), p.y + u * (q.y - p.y)});
    }
    return it->second;
  };
  for (const Region3& r : t.regions) {
    std::vector<int> ring;
    bool below = false, above = false;  // a region only touching the plane has no section
    for (int f : r.faces)
      for (int id : t.faces[f].ring) {
        below = below || t.vertices[id].z < z;
        above = above || t.vertices[id].z > z;
      }
    if (!below || !above) continue;
    for (int f : r.faces) {
      const std::vector<int>& v = t.faces[f].ring;
      for (std::size_t k = 0; k < v.size(); ++k) {
        const int a = v[k], b = v[(k + 1) % v.size()];
        const double da = t.vertices[a].z - z, db = t.vertices[b].z - z;
        if (da == 0.0) ring.push_back(point_id(a, a));
        else if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) ring.push_back(point_id(a, b));
      }
    }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    if (ring.size() < 3) continue;
    Vec2 c{};
    for (int id : ring) c += s.cells.points[id];
    c = c / static_cast<double>(ring.size());
    std::sort(ring.begin(), ring.end(), [&](int a, int b) {
      const Vec2 pa = s.cells.points[a] - c, pb = s.cells.points[b] - c;
      return std::atan2(pa.y, pa.x) < std::atan2(pb.y, pb.x);
    });
    s.cells.add_cell(ring);
    s.grain.push_back(r.grain);
    s.phase.push_back(r.phase);
  }
  return s;
}

}  // namespace grainmesh
