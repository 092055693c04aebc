// Geometric predicates whose sign is exact: a fast floating-point filter decides the easy
// cases, CGAL's exact arithmetic the rest (in predicates.cpp, so no caller sees CGAL).
#pragma once

#include <cmath>

#include "common/geometry.hpp"

namespace grainmesh {

namespace detail {
int orient2d_exact(Vec2 a, Vec2 b, Vec2 c);
}

// Sign of the turn a -> b -> c: +1 counter-clockwise (c left of a->b), -1 clockwise,
// 0 exactly collinear. Exact for all finite inputs.
inline int orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const double left = (a.x - c.x) * (b.y - c.y);
  const double right = (a.y - c.y) * (b.x - c.x);
  const double det = left - right;
  // Shewchuk's first error bound for this expression: (3 + 16 eps) eps.
  constexpr double eps = 1.1102230246251565e-16;  // 2^-53
  constexpr double bound = (3.0 + 16.0 * eps) * eps;
  const double errbound = bound * (std::abs(left) + std::abs(right));
  if (det > errbound) return 1;
  if (-det > errbound) return -1;
  return detail::orient2d_exact(a, b, c);
}

}  // namespace grainmesh
