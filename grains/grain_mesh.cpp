#include "grains/grain_mesh.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>

#include "common/errors.hpp"
#include "grains/conformity.hpp"
#include "grains/edge_seeds.hpp"
#include "grains/region_mesh.hpp"
#include "grains/size_field.hpp"

namespace grainmesh {

namespace {

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void check_options(const GrainMeshOptions& o) {
  if (!(o.size > 0.0) || !std::isfinite(o.size)) throw ConfigError("mesh: the element size must be positive");
  for (const auto& [value, name] : {std::pair{o.boundary_size, "boundary size"}, {o.junction_size, "junction size"}})
    if (!(value >= 0.0) || !std::isfinite(value)) throw ConfigError(std::string("mesh: the ") + name + " must be >= 0");
  if (!(o.gradient > 0.0) || !std::isfinite(o.gradient)) throw ConfigError("mesh: the size gradient must be positive");
}

// Every region meshed, options.threads at a time; an error names the region's grain.
std::vector<RegionMesh> mesh_regions(const Tessellation& t, const EdgeIndex& index, const EdgeNodes& nodes,
                                     const std::shared_ptr<const FeatureSize>& size, const GrainMeshOptions& o) {
  const int nr = static_cast<int>(t.regions.size());
  std::vector<RegionMesh> results(nr);
  tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
  std::mutex progress_mutex;
  int regions_done = 0;
  arena.execute([&] {
    tbb::parallel_for(0, nr, [&](int r) {
      const std::string where = "mesh: grain " + std::to_string(t.regions[r].grain) + ": ";
      try {
        results[r] = mesh_region(t, r, index, nodes, size, o);
      } catch (const TimeLimitError& e) {
        throw TimeLimitError(where + e.what());
      } catch (const ConfigError& e) {
        throw ConfigError(where + e.what());
      } catch (const GeometryError& e) {
        throw GeometryError(where + e.what());
      }
      if (!o.progress) return;
      const std::lock_guard<std::mutex> lock(progress_mutex);
      o.progress(++regions_done, nr);
    });
  });
  return results;
}

// The regions' points appended to `out`'s (in region order) and their triangles with the
// grain and phase of their region.
void assemble(const Tessellation& t, const std::vector<RegionMesh>& results, GrainMesh& out) {
  std::vector<Vec2>& pts = out.mesh.points;
  for (std::size_t r = 0; r < results.size(); ++r) {
    const int base = static_cast<int>(pts.size());
    pts.insert(pts.end(), results[r].interior.begin(), results[r].interior.end());
    for (auto tri : results[r].triangles) {
      for (int& v : tri)
        if (v < 0) v = base + (-1 - v);
      out.mesh.triangles.push_back(tri);
      out.grain.push_back(t.regions[r].grain);
      out.phase.push_back(t.regions[r].phase);
    }
    out.iterations_max = std::max(out.iterations_max, results[r].iterations);
    out.unconverged_regions += results[r].converged ? 0 : 1;
  }
  out.regions = static_cast<int>(results.size());
}

}  // namespace

GrainMesh mesh_tessellation(const Tessellation& t, const GrainMeshOptions& o) {
  check_options(o);
  const auto start = std::chrono::steady_clock::now();
  const auto size = std::make_shared<const FeatureSize>(tessellation_size(t, o));
  const EdgeIndex index(t);
  const std::vector<SidePartner> partner = side_partners(t, index);
  EdgeNodes nodes{.seeds = seed_edges(t, o, *size, index, partner), .first_id = {}};
  GrainMesh out;
  out.sizing_seconds = since(start);
  // Mesh nodes: tessellation vertices, then edge seeds, then each region's interior.
  out.mesh.points = t.vertices;
  for (const auto& seeds : nodes.seeds) {
    nodes.first_id.push_back(static_cast<int>(out.mesh.points.size()));
    out.mesh.points.insert(out.mesh.points.end(), seeds.begin(), seeds.end());
  }
  const auto regions_start = std::chrono::steady_clock::now();
  const std::vector<RegionMesh> results = mesh_regions(t, index, nodes, size, o);
  out.regions_seconds = since(regions_start);
  const auto merge_start = std::chrono::steady_clock::now();
  assemble(t, results, out);
  out.pairs = node_pairs(t, partner, nodes.first_id, nodes.seeds);
  validate(out.mesh);
  out.merge_seconds = since(merge_start);
  out.seconds = since(start);
  return out;
}

}  // namespace grainmesh
