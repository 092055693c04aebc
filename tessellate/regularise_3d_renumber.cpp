#include "tessellate/regularise_3d.hpp"

namespace grainmesh {

void renumber(Tessellation3& t, std::vector<Face3> faces, const std::vector<std::vector<int>>& replaced,
              const std::vector<bool>& removed) {
  std::vector<int> region_id(t.regions.size(), -1);
  std::vector<Region3> regions;
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    if (removed[r]) continue;
    region_id[r] = static_cast<int>(regions.size());
    Region3 region = t.regions[r];
    region.faces.clear();
    for (int f : t.regions[r].faces) region.faces.insert(region.faces.end(), replaced[f].begin(), replaced[f].end());
    regions.push_back(std::move(region));
  }
  for (Face3& f : faces) {
    f.back = region_id[f.back];
    if (f.front >= 0) f.front = region_id[f.front];
  }
  t.regions = std::move(regions);
  t.faces = std::move(faces);
  std::vector<int> id(t.vertices.size(), -1);
  std::vector<Vec3> kept;
  for (Face3& f : t.faces)
    for (int& v : f.ring) {
      if (id[v] < 0) {
        id[v] = static_cast<int>(kept.size());
        kept.push_back(t.vertices[v]);
      }
      v = id[v];
    }
  t.vertices = std::move(kept);
}

}  // namespace grainmesh
