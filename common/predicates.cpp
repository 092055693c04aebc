#include "common/predicates.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace grainmesh::detail {

int orient2d_exact(Vec2 a, Vec2 b, Vec2 c) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto o = CGAL::orientation(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y), K::Point_2(c.x, c.y));
  return o == CGAL::LEFT_TURN ? 1 : (o == CGAL::RIGHT_TURN ? -1 : 0);
}

int incircle_exact(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto s = CGAL::side_of_oriented_circle(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y), K::Point_2(c.x, c.y),
                                               K::Point_2(d.x, d.y));
  return s == CGAL::ON_POSITIVE_SIDE ? 1 : (s == CGAL::ON_NEGATIVE_SIDE ? -1 : 0);
}

}  // namespace grainmesh::detail
