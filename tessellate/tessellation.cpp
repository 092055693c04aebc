#include "tessellate/tessellation.hpp"

#include "common/cell_side.hpp"
#include "common/ring.hpp"

namespace grainmesh {

CellSide cell_side(const Tessellation& t, Vec2 a, Vec2 b) { return side_along(Box{{0.0, 0.0}, {t.width, t.height}}, a, b); }

std::vector<Vec2> ring_points(const std::vector<Vec2>& vertices, const std::vector<int>& ring) {
  std::vector<Vec2> pts;
  pts.reserve(ring.size());
  for (int v : ring) pts.push_back(vertices[v]);
  return pts;
}

double region_area(const Tessellation& t, const Region& r) {
  double a = 0.0;
  for (std::size_t q = 0; q < r.rings.size(); ++q)
    a += (q == 0 ? 1.0 : -1.0) * polygon_area(ring_points(t.vertices, r.rings[q]));
  return a;
}

}  // namespace grainmesh
