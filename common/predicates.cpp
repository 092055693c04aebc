#include "common/predicates.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace grainmesh::detail {

int orient2d_exact(Vec2 a, Vec2 b, Vec2 c) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto o = CGAL::orientation(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y), K::Point_2(c.x, c.y));
  return o == CGAL::LEFT_TURN ? 1 : (o == CGAL::RIGHT_TURN ? -1 : 0);
}

}  // namespace grainmesh::detail
