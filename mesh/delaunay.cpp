#include "mesh/delaunay.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <string>
#include <utility>

#include "common/errors.hpp"

namespace grainmesh {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using Delaunay = CGAL::Delaunay_triangulation_2<K, Tds>;
}  // namespace

std::vector<std::array<int, 3>> delaunay_triangulation(std::span<const Vec2> points) {
  std::vector<std::pair<K::Point_2, int>> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!is_finite(points[i])) throw GeometryError("delaunay: point " + std::to_string(i) + " is not finite");
    input.emplace_back(K::Point_2(points[i].x, points[i].y), static_cast<int>(i));
  }
  std::vector<std::array<int, 3>> triangles;
  try {
    // The range insert sorts along a Hilbert curve first (deterministically).
    Delaunay dt(input.begin(), input.end());
    triangles.reserve(dt.number_of_faces());
    for (auto f : dt.finite_face_handles())
      triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  } catch (const CGAL::Failure_exception& e) {
    throw GeometryError(std::string("delaunay: CGAL failed: ") + e.what());
  }
  return triangles;
}

}  // namespace grainmesh
