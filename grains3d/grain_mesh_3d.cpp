#include "grains3d/grain_mesh_3d.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/process.hpp"
#include "grains3d/improve_tets.hpp"
#include "grains3d/surface_mesh.hpp"
#include "grains3d/tetgen_fill.hpp"

namespace grainmesh {

namespace {

// A region's tetrahedra before assembly: ids >= 0 are surface points, < 0 are -(1 + k)
// for the region's own interior point k.
struct RegionTets {
  std::vector<Vec3> interior;
  std::vector<std::array<int, 4>> tets;
};

// Fills region r: its surface triangles (outward) filled by TetGen (tetgen_fill.hpp), the
// inner points improved.
RegionTets fill_region(const Tessellation3& t, int r, const std::vector<Vec3>& points,
                       const std::vector<std::vector<std::array<int, 3>>>& faces, const GrainMesh3Options& o,
                       const TetgenRunner& tetgen) {
  std::map<int, int> local;
  std::vector<int> global;
  std::vector<std::array<int, 3>> tris;
  for (int f : t.regions[r].faces)
    for (auto tr : faces[f]) {
      if (t.faces[f].back != r) std::swap(tr[1], tr[2]);
      for (int& v : tr) {
        const auto [it, added] = local.emplace(v, static_cast<int>(global.size()));
        if (added) global.push_back(v);
        v = it->second;
      }
      tris.push_back(tr);
    }
  std::vector<Vec3> surface;
  for (int v : global) surface.push_back(points[v]);
  const TetgenOptions to{.radius_edge = o.radius_edge,
                         .min_dihedral_deg = o.min_dihedral_deg,
                         .max_volume = regular_tet_volume(
                             o.core_size > 0.0 && !t.grains[t.regions[r].grain].matrix ? o.core_size : o.size),
                         .deadline = o.deadline};
  TetgenFill fill =
      tetgen.fill(surface, tris, to, "region " + std::to_string(r) + " (grain " + std::to_string(t.regions[r].grain) + ")");
  const int nb = static_cast<int>(global.size());
  improve_tets(fill.points, fill.tets, nb, o.improvement_passes);
  RegionTets out;
  out.interior.assign(fill.points.begin() + nb, fill.points.end());
  for (const auto& tet : fill.tets) {
    std::array<int, 4> mapped{};
    for (int c = 0; c < 4; ++c) mapped[c] = tet[c] < nb ? global[tet[c]] : -1 - (tet[c] - nb);
    out.tets.push_back(mapped);
  }
  return out;
}

}  // namespace

double size_for_tets_per_grain(const Tessellation3& t, double per_grain) {
  constexpr double kTetsPerBound = 1.05;
  const auto grains = std::count_if(t.grains.begin(), t.grains.end(), [](const Grain3& g) { return !g.matrix; });
  const double grain = t.width * t.height * t.depth / static_cast<double>(std::max<std::ptrdiff_t>(1, grains));
  return regular_tet_edge(kTetsPerBound * grain / per_grain);
}

GrainMesh3 mesh_tessellation_3d(const Tessellation3& t, const GrainMesh3Options& o) {
  if (!(o.size > 0.0)) throw GeometryError("3D mesh: the element size must be positive");
  const auto start = std::chrono::steady_clock::now();
  auto since = [](auto from) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count(); };
  SurfaceMesh surface = mesh_surfaces(t, o.size);
  GrainMesh3 m;
  m.surface_seconds = since(start);
  m.surface_points = static_cast<int>(surface.points.size());
  for (const auto& f : surface.faces) m.surface_triangles += static_cast<int>(f.size());

  const auto fill_start = std::chrono::steady_clock::now();
  const int nr = static_cast<int>(t.regions.size());
  std::vector<RegionTets> pieces(nr);
  tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
  TetgenRunner tetgen;
  arena.execute([&] {
    tbb::parallel_for(0, nr, [&](int r) { pieces[r] = fill_region(t, r, surface.points, surface.faces, o, tetgen); });
  });
  m.fill_seconds = since(fill_start);

  m.mesh.points = std::move(surface.points);
  m.pairs = std::move(surface.pairs);
  m.faces = std::move(surface.faces);
  for (int r = 0; r < nr; ++r) {
    const int first = static_cast<int>(m.mesh.points.size());
    m.mesh.points.insert(m.mesh.points.end(), pieces[r].interior.begin(), pieces[r].interior.end());
    for (auto tet : pieces[r].tets) {
      for (int& v : tet)
        if (v < 0) v = first + (-1 - v);
      const auto& p = m.mesh.points;
      if (tet_volume(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]) < 0.0) std::swap(tet[2], tet[3]);
      m.mesh.tets.push_back(tet);
      m.grain.push_back(t.regions[r].grain);
      m.phase.push_back(t.regions[r].phase);
      m.region.push_back(r);
    }
  }
  m.seconds = since(start);
  return m;
}

}  // namespace grainmesh
