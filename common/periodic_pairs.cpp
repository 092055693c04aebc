#include "common/periodic_pairs.hpp"

#include <string>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace grainmesh {

PeriodicPairs pair_by_position(const std::vector<Vec2>& points, const Box& cell) {
  PeriodicPairs pairs;
  for (int axis = 0; axis < 2; ++axis) {
    auto across = [axis](Vec2 p) { return axis == 0 ? p.x : p.y; };
    auto along = [axis](Vec2 p) { return axis == 0 ? p.y : p.x; };
    const double low = axis == 0 ? cell.lo.x : cell.lo.y, high = axis == 0 ? cell.hi.x : cell.hi.y;
    std::unordered_map<double, int> image;
    std::size_t on_high = 0;
    for (int v = 0; v < static_cast<int>(points.size()); ++v)
      if (across(points[v]) == high) image[along(points[v])] = v, ++on_high;
    auto& out = axis == 0 ? pairs.axis[0] : pairs.axis[1];
    for (int v = 0; v < static_cast<int>(points.size()); ++v) {
      if (across(points[v]) != low) continue;
      const auto it = image.find(along(points[v]));
      if (it == image.end())
        throw GeometryError("the point at " + to_text(points[v]) + " on the " + (axis == 0 ? "left" : "bottom") +
                            " side has no periodic partner");
      out.emplace_back(v, it->second);
    }
    if (out.size() != on_high)
      throw GeometryError(std::string("a point on the ") + (axis == 0 ? "right" : "top") + " side has no periodic partner");
  }
  return pairs;
}

}  // namespace grainmesh
