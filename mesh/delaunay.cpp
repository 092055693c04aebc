#include "mesh/delaunay.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <string>
#include <utility>

#include "common/errors.hpp"

namespace grainmesh {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fb = CGAL::Triangulation_face_base_with_info_2<int, K>;  // index among the kept faces
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Delaunay = CGAL::Delaunay_triangulation_2<K, Tds>;
using CVb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using CFbInfo = CGAL::Triangulation_face_base_with_info_2<int, K>;  // nesting depth, then index
using CFb = CGAL::Constrained_triangulation_face_base_2<K, CFbInfo>;
using CTds = CGAL::Triangulation_data_structure_2<CVb, CFb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, CTds, CGAL::Exact_predicates_tag>;

std::vector<std::pair<K::Point_2, int>> with_ids(std::span<const Vec2> points) {
  std::vector<std::pair<K::Point_2, int>> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!is_finite(points[i])) throw GeometryError("delaunay: point " + std::to_string(i) + " is not finite");
    input.emplace_back(K::Point_2(points[i].x, points[i].y), static_cast<int>(i));
  }
  return input;
}

// The faces `keep` accepts, with their neighbours among them. Face info is overwritten
// with the face's index (-1 for faces not kept).
template <typename T, typename Keep>
Triangulation flat(T& tri, Keep keep) {
  Triangulation out;
  out.triangles.reserve(tri.number_of_faces());
  for (auto f : tri.all_face_handles()) {
    if (tri.is_infinite(f) || !keep(f)) {
      f->info() = -1;
      continue;
    }
    f->info() = static_cast<int>(out.triangles.size());
    out.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  }
  out.neighbours.resize(out.triangles.size());
  for (auto f : tri.finite_face_handles())
    if (f->info() >= 0)
      for (int i = 0; i < 3; ++i) out.neighbours[f->info()][i] = f->neighbor(i)->info();
  return out;
}
}  // namespace

Triangulation delaunay_triangulation(std::span<const Vec2> points) {
  const auto input = with_ids(points);
  try {
    // The range insert sorts along a Hilbert curve first (deterministically).
    Delaunay dt(input.begin(), input.end());
    return flat(dt, [](auto) { return true; });
  } catch (const CGAL::Failure_exception& e) {
    throw GeometryError(std::string("delaunay: CGAL failed: ") + e.what());
  }
}

Triangulation constrained_delaunay_triangulation(std::span<const Vec2> points,
                                                 std::span<const std::array<int, 2>> constraints) {
  const auto input = with_ids(points);
  try {
    Cdt cdt;
    cdt.insert(input.begin(), input.end());
    std::vector<Cdt::Vertex_handle> handle(points.size());
    for (auto v : cdt.finite_vertex_handles()) handle[static_cast<std::size_t>(v->info())] = v;
    for (const auto& [a, b] : constraints) {
      for (int i : {a, b})
        if (i < 0 || static_cast<std::size_t>(i) >= points.size())
          throw GeometryError("delaunay: constraint names point " + std::to_string(i) + " that does not exist");
      // A point coincident with another has no vertex of its own: insert finds the other.
      for (int i : {a, b})
        if (handle[i] == Cdt::Vertex_handle()) handle[i] = cdt.insert(input[i].first);
      if (handle[a] != handle[b]) cdt.insert_constraint(handle[a], handle[b]);
    }
    // Nesting depth by a breadth-first walk from the outside: crossing a constraint
    // goes one deeper.
    for (auto f : cdt.all_face_handles()) f->info() = -1;
    std::vector<Cdt::Face_handle> level{cdt.infinite_face()}, deeper;
    for (int d = 0; !level.empty(); ++d) {
      for (std::size_t k = 0; k < level.size(); ++k) {  // level grows while walked
        const Cdt::Face_handle f = level[k];
        if (f->info() >= 0) continue;
        f->info() = d;
        for (int i = 0; i < 3; ++i) {
          const Cdt::Face_handle n = f->neighbor(i);
          if (n->info() < 0) (cdt.is_constrained(Cdt::Edge(f, i)) ? deeper : level).push_back(n);
        }
      }
      level.swap(deeper);
      deeper.clear();
    }
    return flat(cdt, [](auto f) { return f->info() % 2 == 1; });
  } catch (const CGAL::Failure_exception& e) {
    throw GeometryError(std::string("delaunay: CGAL failed: ") + e.what());
  }
}

}  // namespace grainmesh
