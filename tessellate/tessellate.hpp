// The 2D tessellation stage: seeds to a cut, labelled, periodic cell of grains.
#pragma once

#include "common/random.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

// Draws N seeds from `rng` (or takes the given ones), builds the (periodic) power
// diagram, relaxes, regularises, assigns phases, chooses the window and cuts it. Throws
// ConfigError for options that cannot be met (fractions, unreachable matrix fraction),
// TimeLimitError when the deadline passes, GeometryError otherwise.
Tessellation tessellate(const TessellationOptions& options, Rng& rng);

// The statistics of a tessellation whose grains (ids, phases, seeds, neighbours; the
// matrix grain last) and regions are set: the grains' areas from their regions, sizes,
// shortest edge, sharpest corner, the phases' fractions and descriptors; validates it.
// Shared by the tessellations read from files (read_tessellation.hpp).
void measure_tessellation(Tessellation& t);

}  // namespace grainmesh
