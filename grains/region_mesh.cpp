#include "grains/region_mesh.hpp"

#include <algorithm>
#include <string>

#include "common/errors.hpp"
#include "common/point_key.hpp"
#include "common/random.hpp"

namespace grainmesh {
namespace {

// A region's boundary as the engine takes it: its rings with every edge's seeds, the
// constraint segments between consecutive points, and each point's mesh node id.
struct RegionBoundary {
  std::vector<std::vector<Vec2>> rings;
  std::vector<Vec2> fixed;
  std::vector<int> ids;
  std::vector<std::array<int, 2>> constraints;
};

RegionBoundary region_boundary(const Tessellation& t, int r, const EdgeIndex& index, const EdgeNodes& nodes) {
  RegionBoundary b;
  for (const auto& ring : t.regions[r].rings) {
    std::vector<Vec2> loop;
    const int base = static_cast<int>(b.ids.size());
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const int v = ring[k], w = ring[(k + 1) % ring.size()];
      loop.push_back(t.vertices[v]);
      b.ids.push_back(v);
      const int e = index.find(v, w);
      if (e < 0) throw GeometryError("mesh: region " + std::to_string(r) + " has a side that is no edge");
      const auto& seeds = nodes.seeds[e];
      const int n = static_cast<int>(seeds.size());
      const bool forward = t.edges[e].v0 == v;
      for (int q = 0; q < n; ++q) {
        const int s = forward ? q : n - 1 - q;
        loop.push_back(seeds[s]);
        b.ids.push_back(nodes.first_id[e] + s);
      }
    }
    const int count = static_cast<int>(loop.size());
    for (int k = 0; k < count; ++k) b.constraints.push_back({base + k, base + (k + 1) % count});
    b.fixed.insert(b.fixed.end(), loop.begin(), loop.end());
    b.rings.push_back(std::move(loop));
  }
  return b;
}

}  // namespace

RegionMesh mesh_region(const Tessellation& t, int r, const EdgeIndex& index, const EdgeNodes& nodes,
                       const std::shared_ptr<const FeatureSize>& size, const GrainMeshOptions& o) {
  const double h = region_size(o, t.regions[r].phase);
  RegionBoundary b = region_boundary(t, r, index, nodes);
  const DistanceFunction domain = polygon(b.rings);
  // The finest size is on the boundary, where the features are; a margin for the
  // stretches between seeds.
  double h0 = h;
  for (const Vec2 p : b.fixed) h0 = std::min(h0, 0.9 * size->at(p, h));
  const DistMeshProblem pb{.domain = domain, .size = capped_size(size, h), .h0 = h0, .bbox = domain.bounds(),
                           .fixed = std::move(b.fixed), .interface = {}, .constraints = std::move(b.constraints),
                           .absolute_size = true};
  // Fixed points come back with their bits: that is how the engine's output finds them.
  PointMap<int> fixed_id;
  for (std::size_t k = 0; k < pb.fixed.size(); ++k) fixed_id.emplace(point_key(pb.fixed[k]), b.ids[k]);
  Rng rng(derived_seed(o.seed, static_cast<std::uint64_t>(r)));
  const DistMeshResult res = distmesh(pb, o.distmesh, rng);
  RegionMesh out;
  std::vector<int> local(res.mesh.points.size());
  for (std::size_t i = 0; i < res.mesh.points.size(); ++i) {
    const auto it = fixed_id.find(point_key(res.mesh.points[i]));
    if (it != fixed_id.end()) {
      local[i] = it->second;
    } else {
      local[i] = -1 - static_cast<int>(out.interior.size());
      out.interior.push_back(res.mesh.points[i]);
    }
  }
  for (const auto& tri : res.mesh.triangles) out.triangles.push_back({local[tri[0]], local[tri[1]], local[tri[2]]});
  out.iterations = res.stats.iterations;
  out.converged = res.stats.converged;
  return out;
}

}  // namespace grainmesh
