// Points as exact map keys: the same bits are the same point. For shared seeds and cut
// points, which are computed once and copied, never recomputed.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <unordered_map>
#include <utility>

#include "common/geometry.hpp"

namespace grainmesh {

using PointKey = std::pair<std::uint64_t, std::uint64_t>;

// -0.0 and 0.0 give one key.
inline PointKey point_key(Vec2 p) {
  PointKey k;
  const double x = p.x + 0.0, y = p.y + 0.0;
  std::memcpy(&k.first, &x, sizeof x);
  std::memcpy(&k.second, &y, sizeof y);
  return k;
}

struct PointKeyHash {
  std::size_t operator()(const PointKey& k) const {
    return std::hash<std::uint64_t>()(k.first * 0x9E3779B97F4A7C15ull ^ k.second);
  }
};

template <typename T>
using PointMap = std::unordered_map<PointKey, T, PointKeyHash>;

}  // namespace grainmesh
