#include "tessellate/torus.hpp"

#include <cmath>

namespace grainmesh {

std::vector<Vec2> TorusGraph::polygon(int c) const {
  std::vector<Vec2> out;
  out.reserve(rings[c].size());
  for (const Corner& k : rings[c]) out.push_back(point(k));
  return out;
}

int TorusGraph::live_cells() const {
  int n = 0;
  for (const auto& r : rings) n += r.empty() ? 0 : 1;
  return n;
}

Vec2 reduce_periodic(Vec2 p, double width, double height, Corner* shift) {
  const int i = static_cast<int>(std::floor(p.x / width));
  const int j = static_cast<int>(std::floor(p.y / height));
  Vec2 r{p.x - i * width, p.y - j * height};
  // Rounding can land exactly on the far side; keep [0, W).
  int ii = i, jj = j;
  if (r.x >= width) { r.x -= width; ++ii; }
  if (r.x < 0.0) { r.x += width; --ii; }
  if (r.y >= height) { r.y -= height; ++jj; }
  if (r.y < 0.0) { r.y += height; --jj; }
  if (shift) *shift = Corner{0, ii, jj};
  return r;
}

}  // namespace grainmesh
