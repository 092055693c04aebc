// One region of a tessellation meshed by the DistMesh engine, its boundary the shared edge
// seeds, fixed: the engine keeps them bit for bit, which is how its output finds them.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "grains/edge_index.hpp"
#include "grains/feature_size.hpp"
#include "grains/grain_mesh_options.hpp"

namespace grainmesh {

// The seeds of every tessellation edge and the mesh node id of each edge's first seed
// (the others follow it in order).
struct EdgeNodes {
  std::vector<std::vector<Vec2>> seeds;
  std::vector<int> first_id;
};

// A region's triangles before assembly: node ids >= 0 are the mesh's (tessellation
// vertices and edge seeds), < 0 are -(1 + k) for the region's own interior point k.
struct RegionMesh {
  std::vector<Vec2> interior;                  // new points, in the engine's order
  std::vector<std::array<int, 3>> triangles;
  int iterations = 0;
  bool converged = true;
};

// Meshes region r at its phase's size, the field `size` capped by it, with its stream of
// random numbers derived from (options.seed, r): the same whichever thread runs it.
// Throws GeometryError (a side of the region that is no edge, the engine's failures).
RegionMesh mesh_region(const Tessellation& t, int r, const EdgeIndex& index, const EdgeNodes& nodes,
                       const std::shared_ptr<const FeatureSize>& size, const GrainMeshOptions& options);

}  // namespace grainmesh
