// What the 2D mesh stage is given and gives back: its options, the grain mesh (triangles
// with a grain and a phase each, paired side nodes), and the size a region gets.
#pragma once


#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "common/periodic_pairs.hpp"
#include "mesh/distmesh.hpp"
#include "mesh/trimesh.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

struct GrainMeshOptions {
  double size = 0.0;                 // element edge length, the tessellation's unit; > 0
  std::vector<double> phase_size;    // per phase (index as in the tessellation); 0 or
                                     // missing = `size`
  int threads = 0;                   // regions meshed in parallel; 0 = all cores
  std::uint64_t seed = 1;            // region r uses a stream derived from (seed, r)
  bool feature_size = true;          // refine at short edges and thin layers
  double feature_fraction = 0.5;     // element size there, x the local feature size
  double boundary_size = 0.0;        // element size on grain boundaries; 0 = the phase size
  double junction_size = 0.0;        // element size at triple junctions; 0 = no refinement
  double gradient = 0.3;             // how fast the size grows away from all of these
  // The engine's constants. Bars a little less compressed than the thesis' 1.2: with
  // every boundary seeded at the wanted size, 1.15 gives the best interior fit (mean q
  // 0.973 against 0.971 on 200-grain cells). A region stops after 1000 iterations (still
  // a valid mesh): the quality is reached long before the last points settle in thin layers.
  DistMeshOptions distmesh{.fscale = 1.15, .ttol = 0.2, .max_iterations = 1000};
  // Called after each region with (regions done, regions), from the meshing threads one
  // at a time; for a progress display. Empty = none.
  std::function<void(int, int)> progress{};
};

struct GrainMesh {
  TriMesh mesh;
  std::vector<int> grain;            // #T grain of each triangle
  std::vector<int> phase;            // #T phase of each triangle
  // Periodic node pairs: the tessellation's vertex partners extended to the edge seeds
  // copied across (node_pairs in edge_seeds.hpp); empty when not periodic.
  PeriodicPairs pairs;
  int regions = 0;
  int iterations_max = 0;            // the most force iterations any region needed
  int unconverged_regions = 0;       // regions that hit the iteration limit (still valid)
  double seconds = 0.0;
  double sizing_seconds = 0.0;       // of them: the size field and the edge seeds,
  double regions_seconds = 0.0;      // ... the regions (in parallel),
  double merge_seconds = 0.0;        // ... and merging, pairing and validating
};

// The size every edge and region gets away from small features: options.size, or the
// phase's own.
double region_size(const GrainMeshOptions& options, int phase);

}  // namespace grainmesh
