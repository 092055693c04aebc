// The peer "CGAL Delaunay_mesher_2 + Lloyd" of make bench's disk case: the unit disk's
// boundary as constraint segments of about h, refined by CGAL's Delaunay mesher (the
// default shape bound, 0.125: angles above about 20.6 degrees) with edges at most
// `size_bound`, then CGAL's Lloyd smoothing. Writes the mesh as a Gmsh 2.2 .msh file and
// prints one JSON line: {"seconds": refine + Lloyd, "refine_seconds", "lloyd_seconds"}.
// CGAL's Lloyd costs more than linearly in the mesh (about 30 s for 70k triangles on our
// machine), so it stops at LLOYD_SECONDS if its iterations are not done by then.
// Usage: bench_cgal_disk H SIZE_BOUND LLOYD_ITERATIONS LLOYD_SECONDS OUT.msh
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/lloyd_optimize_mesh_2.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <numbers>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: bench_cgal_disk H SIZE_BOUND LLOYD_ITERATIONS LLOYD_SECONDS OUT.msh\n");
    return 2;
  }
  const double h = std::atof(argv[1]), bound = std::atof(argv[2]);
  const int lloyd = std::atoi(argv[3]);
  const double lloyd_limit = std::atof(argv[4]);
  auto since = [](auto t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };

  const auto start = std::chrono::steady_clock::now();
  Cdt cdt;
  const int n = static_cast<int>(std::ceil(2.0 * std::numbers::pi / h));
  std::vector<Cdt::Vertex_handle> ring;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * std::numbers::pi * k / n;
    ring.push_back(cdt.insert(K::Point_2(std::cos(a), std::sin(a))));
  }
  for (int k = 0; k < n; ++k) cdt.insert_constraint(ring[k], ring[(k + 1) % n]);
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, bound));
  const double refine_seconds = since(start);
  const auto smooth = std::chrono::steady_clock::now();
  CGAL::Mesh_optimization_return_code code = CGAL::MESH_OPTIMIZATION_UNKNOWN_ERROR;
  if (lloyd > 0)
    code = CGAL::lloyd_optimize_mesh_2(cdt, CGAL::parameters::max_iteration_number = lloyd,
                                       CGAL::parameters::time_limit = lloyd_limit);
  const double lloyd_seconds = since(smooth);
  const double seconds = since(start);

  std::ofstream out(argv[5]);
  std::map<Cdt::Vertex_handle, int> id;
  for (auto v : cdt.finite_vertex_handles()) id.emplace(v, static_cast<int>(id.size()) + 1);
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << id.size() << "\n";
  out.precision(17);
  for (const auto& [v, i] : id) out << i << " " << v->point().x() << " " << v->point().y() << " 0\n";
  std::size_t faces = 0;
  for (auto f : cdt.finite_face_handles()) faces += f->is_in_domain();
  out << "$EndNodes\n$Elements\n" << faces << "\n";
  std::size_t e = 0;
  for (auto f : cdt.finite_face_handles())
    if (f->is_in_domain())
      out << ++e << " 2 0 " << id[f->vertex(0)] << " " << id[f->vertex(1)] << " " << id[f->vertex(2)] << "\n";
  out << "$EndElements\n";
  std::printf("{\"seconds\": %.6f, \"refine_seconds\": %.6f, \"lloyd_seconds\": %.6f, \"lloyd_stop\": \"%s\"}\n",
              seconds, refine_seconds, lloyd_seconds,
              lloyd == 0 ? "none"
              : code == CGAL::TIME_LIMIT_REACHED ? "time limit"
              : code == CGAL::MAX_ITERATION_NUMBER_REACHED ? "iterations"
              : "converged");
  return 0;
}
