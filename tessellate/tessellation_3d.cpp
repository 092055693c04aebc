#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

Vec3 ring_normal(const std::vector<Vec3>& p, const std::vector<int>& ring) {
  Vec3 n{};
  for (std::size_t k = 0; k < ring.size(); ++k) n += cross(p[ring[k]], p[ring[(k + 1) % ring.size()]]);
  return n;
}

double face_area(const Tessellation3& t, const Face3& f) { return 0.5 * norm(ring_normal(t.vertices, f.ring)); }

double region_volume(const Tessellation3& t, const Region3& r) {
  // Divergence theorem over fans of the outward faces, about the first face's first vertex.
  const Vec3 o = t.vertices[t.faces[r.faces[0]].ring[0]];
  const int self = static_cast<int>(&r - t.regions.data());
  double v = 0.0;
  for (int f : r.faces) {
    const Face3& face = t.faces[f];
    const double sign = face.back == self ? 1.0 : -1.0;
    const Vec3 a = t.vertices[face.ring[0]] - o;
    for (std::size_t k = 1; k + 1 < face.ring.size(); ++k)
      v += sign * dot(a, cross(t.vertices[face.ring[k]] - o, t.vertices[face.ring[k + 1]] - o)) / 6.0;
  }
  return v;
}

std::pair<int, int> box_side(const Tessellation3& t, const std::vector<int>& ring) {
  const Vec3 box = t.size();
  for (int a = 0; a < 3; ++a) {
    bool low = true, high = true;
    for (int id : ring) {
      low = low && t.vertices[id][a] == 0.0;
      high = high && t.vertices[id][a] == box[a];
    }
    if (low) return {a, 0};
    if (high) return {a, 1};
  }
  return {-1, 0};
}

}  // namespace grainmesh
