#include "view/section.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace grainmesh {

namespace {

// The points where the plane z = `z` cuts segments between 3D points, each made once and
// numbered in `out`: a segment by its ends (a, b), a point on the plane as (v, v).
class PlanePoints {
 public:
  PlanePoints(const std::vector<Vec3>& points, double z, std::vector<Vec2>& out) : points_(points), z_(z), out_(out) {}
  int at(int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, added] = ids_.emplace(key, static_cast<int>(out_.size()));
    if (added) {
      const Vec3 p = points_[key.first], q = points_[key.second];
      const double u = key.first == key.second ? 0.0 : (z_ - p.z) / (q.z - p.z);
      out_.push_back({p.x + u * (q.x - p.x), p.y + u * (q.y - p.y)});
    }
    return it->second;
  }

 private:
  const std::vector<Vec3>& points_;
  double z_;
  std::vector<Vec2>& out_;
  std::map<std::pair<int, int>, int> ids_;
};

}  // namespace

Section tessellation_section(const Tessellation3& t, double z) {
  Section s;
  PlanePoints plane(t.vertices, z, s.cells.points);
  for (const Region3& r : t.regions) {
    bool below = false, above = false;  // a region only touching the plane has no section
    for (int f : r.faces)
      for (int id : t.faces[f].ring) {
        below = below || t.vertices[id].z < z;
        above = above || t.vertices[id].z > z;
      }
    if (!below || !above) continue;
    // Each face the plane crosses gives a segment; the segments chain into the ring.
    std::map<int, std::vector<int>> next;
    for (int f : r.faces) {
      const std::vector<int>& v = t.faces[f].ring;
      std::vector<int> cut;
      for (std::size_t k = 0; k < v.size(); ++k) {
        const int a = v[k], b = v[(k + 1) % v.size()];
        const double da = t.vertices[a].z - z, db = t.vertices[b].z - z;
        if (da == 0.0) cut.push_back(plane.at(a, a));
        else if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) cut.push_back(plane.at(a, b));
      }
      std::sort(cut.begin(), cut.end());
      cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
      if (cut.size() != 2) continue;  // touches the plane in a point, or lies in it
      next[cut[0]].push_back(cut[1]);
      next[cut[1]].push_back(cut[0]);
    }
    if (next.size() < 3) continue;
    std::vector<int> ring{next.begin()->first};
    int previous = -1;
    while (true) {
      const std::vector<int>& to = next[ring.back()];
      if (to.size() != 2) break;
      const int step = to[0] != previous ? to[0] : to[1];
      if (step == ring.front()) break;
      previous = ring.back();
      ring.push_back(step);
    }
    if (ring.size() != next.size()) continue;  // a degenerate touch: left out of the picture
    double area2 = 0.0;
    for (std::size_t k = 0; k < ring.size(); ++k)
      area2 += cross(s.cells.points[ring[k]], s.cells.points[ring[(k + 1) % ring.size()]]);
    if (area2 < 0.0) std::reverse(ring.begin(), ring.end());
    s.cells.add_cell(ring);
    s.grain.push_back(r.grain);
    s.phase.push_back(r.phase);
  }
  return s;
}

double section_height(const Tessellation3& t, double z) {
  std::vector<double> levels;
  for (const Vec3& v : t.vertices) levels.push_back(v.z);
  levels.push_back(0.0);
  levels.push_back(t.depth);
  std::sort(levels.begin(), levels.end());
  const double tolerance = 1e-9 * t.depth;
  const auto at = std::lower_bound(levels.begin(), levels.end(), z - tolerance);
  if (at == levels.end() || *at > z + tolerance) return z;  // no vertex in the plane
  // Not the gap's middle: the surface mesh puts points at edges' equal divisions.
  constexpr double kInto = 0.4142;
  const auto above = std::upper_bound(levels.begin(), levels.end(), *at + tolerance);
  if (above != levels.end()) return *at + kInto * (*above - *at);
  const auto below = std::lower_bound(levels.begin(), levels.end(), *at - tolerance);
  return below == levels.begin() ? z : *at - kInto * (*at - *(below - 1));
}

Section mesh_section(const TetMesh& mesh, const std::vector<int>& grain, const std::vector<int>& phase, double z) {
  Section s;
  PlanePoints plane(mesh.points, z, s.cells.points);
  // A point within rounding of the plane lies in it (else its tetrahedra's crossings
  // would meet in points a rounding apart: polygons folded over each other).
  double extent = 0.0;
  for (const Vec3& p : mesh.points) extent = std::max(extent, std::abs(p.z));
  const double tolerance = 1e-12 * std::max(extent, 1.0);
  auto height = [&](int v) {
    const double d = mesh.points[v].z - z;
    return std::abs(d) <= tolerance ? 0.0 : d;
  };
  for (std::size_t k = 0; k < mesh.tets.size(); ++k) {
    const auto& t = mesh.tets[k];
    bool below = false, above = false;
    for (int v : t) {
      below = below || height(v) < 0.0;
      above = above || height(v) > 0.0;
    }
    if (!below || !above) continue;
    std::vector<int> ring;
    for (int i = 0; i < 4; ++i) {
      const double di = height(t[i]);
      if (di == 0.0) ring.push_back(plane.at(t[i], t[i]));
      for (int j = i + 1; j < 4; ++j) {
        const double dj = height(t[j]);
        if ((di < 0.0 && dj > 0.0) || (di > 0.0 && dj < 0.0)) ring.push_back(plane.at(t[i], t[j]));
      }
    }
    if (ring.size() < 3) continue;
    Vec2 c{};
    for (int id : ring) c += s.cells.points[id];
    c = c / static_cast<double>(ring.size());
    std::sort(ring.begin(), ring.end(), [&](int a, int b) {
      const Vec2 pa = s.cells.points[a] - c, pb = s.cells.points[b] - c;
      return std::atan2(pa.y, pa.x) < std::atan2(pb.y, pb.x);
    });
    s.cells.add_cell(ring);
    s.grain.push_back(grain[k]);
    s.phase.push_back(phase[k]);
    s.tet.push_back(static_cast<int>(k));
  }
  return s;
}

}  // namespace grainmesh
