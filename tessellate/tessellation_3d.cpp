#include "tessellate/tessellation_3d.hpp"

#include "tessellate/solid_moments.hpp"

namespace grainmesh {

Vec3 ring_normal(const std::vector<Vec3>& p, const std::vector<int>& ring) {
  Vec3 n{};
  for (std::size_t k = 0; k < ring.size(); ++k) n += cross(p[ring[k]], p[ring[(k + 1) % ring.size()]]);
  return n;
}

double face_area(const Tessellation3& t, const Face3& f) { return 0.5 * norm(ring_normal(t.vertices, f.ring)); }

double region_volume(const Tessellation3& t, const Region3& r) {
  // Fans of the faces turned outward, about the first face's first vertex.
  SolidMoments m(t.vertices[t.faces[r.faces[0]].ring[0]]);
  const int self = static_cast<int>(&r - t.regions.data());
  for (int f : r.faces) {
    const Face3& face = t.faces[f];
    const bool outward = face.back == self;
    for (std::size_t k = 1; k + 1 < face.ring.size(); ++k) {
      const Vec3 a = t.vertices[face.ring[0]], b = t.vertices[face.ring[k]], c = t.vertices[face.ring[k + 1]];
      outward ? m.add_triangle(a, b, c) : m.add_triangle(a, c, b);
    }
  }
  return m.volume();
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
