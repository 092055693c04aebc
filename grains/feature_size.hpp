// The element size a tessellation's own geometry asks for: short edges and thin layers
// (a binder between grains, a sliver of a grain cut by the cell's side) get at least two
// elements across, and the size grows away from them no faster than a gradient limit.
#pragma once

#include <memory>
#include <vector>

#include "common/geometry.hpp"
#include "common/spatial_grid.hpp"
#include "domain/size_function.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

// A point that wants elements of size h around it.
struct SizeSource {
  Vec2 p;
  double h = 0.0;
};

// h(x) = min(base, min over sources (s.h + gradient |x - s.p|)): absolute lengths.
class FeatureSize {
 public:
  FeatureSize(std::vector<SizeSource> sources, double base, double gradient);

  double operator()(Vec2 x) const { return at(x, base_); }
  // min(cap, h(x)), for a part (a phase) whose own size is below the base.
  double at(Vec2 x, double cap) const;
  double base() const { return base_; }
  std::size_t sources() const { return sources_.size(); }

 private:
  std::vector<SizeSource> sources_;
  double base_;
  double gradient_;
  // Sources binned in a uniform grid (none for a few sources), with the least size in
  // each bin.
  double finest_ = 0.0;
  GridFrame grid_;
  CellLists binned_;           // per bin: its sources
  std::vector<double> least_;  // per bin: the least size a source in it wants
  std::vector<double> floor_;  // per bin: the least size anywhere in it
};

// min(cap, size), as the size function the DistMesh engine takes; shares `size`.
SizeFunction capped_size(std::shared_ptr<const FeatureSize> size, double cap);

// Sources at the tessellation's vertices and along its edges (about every `spacing`):
// each wants `fraction` x its local feature size, the distance to the nearest edge that
// does not touch it (and, at a vertex, the length of its shortest edge). Only sources
// wanting less than `max_size` are kept; periodic cells get the images that reach across
// their sides.
std::vector<SizeSource> feature_sources(const Tessellation& t, double spacing, double max_size, double fraction,
                                        double gradient);

// Grading on purpose: sources along every grain boundary (cell sides excluded) wanting
// `boundary_size`, at every vertex of one wanting `junction_size` (0, or not below
// max_size, = none), and along every boundary between phases of different sizes
// (`phase_size`, one per phase) wanting the finer, with periodic images as above. The
// field grows away from them by the gradient, so no size jumps at a phase interface.
std::vector<SizeSource> grading_sources(const Tessellation& t, double boundary_size, double junction_size,
                                        const std::vector<double>& phase_size, double max_size, double gradient);

}  // namespace grainmesh
