// Geometric predicates whose sign is exact: a fast floating-point filter decides the easy
// cases, CGAL's exact arithmetic the rest (in predicates.cpp, so no caller sees CGAL).
#pragma once

#include <cmath>

#include "common/geometry.hpp"

namespace grainmesh {

namespace detail {
int orient2d_exact(Vec2 a, Vec2 b, Vec2 c);
int incircle_exact(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
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

// Where d lies against the circle through a, b, c (counter-clockwise): +1 inside, -1
// outside, 0 exactly on it. Exact for all finite inputs.
inline int incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double bc = bdx * cdy, cb = cdx * bdy, ca = cdx * ady, ac = adx * cdy, ab = adx * bdy, ba = bdx * ady;
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bc - cb) + blift * (ca - ac) + clift * (ab - ba);
  // Shewchuk's first error bound for this expression: (10 + 96 eps) eps.
  constexpr double eps = 1.1102230246251565e-16;
  constexpr double bound = (10.0 + 96.0 * eps) * eps;
  const double permanent =
      (std::abs(bc) + std::abs(cb)) * alift + (std::abs(ca) + std::abs(ac)) * blift + (std::abs(ab) + std::abs(ba)) * clift;
  const double errbound = bound * permanent;
  if (det > errbound) return 1;
  if (-det > errbound) return -1;
  return detail::incircle_exact(a, b, c, d);
}

}  // namespace grainmesh
