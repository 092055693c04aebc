// The 3D tessellation stage: seeds to a cut, labelled, periodic box of polyhedral grains.
#pragma once

#include "common/random.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// Draws N seeds from `rng` (or takes the given ones), builds the (periodic) Laguerre
// diagram, relaxes it, places the box on the torus clear of the diagram's vertices, cuts
// it exactly, collapses short edges (regularise_3d.hpp) and assigns phases by volume. Throws ConfigError for options that
// cannot be met, TimeLimitError when the deadline passes, GeometryError otherwise.
Tessellation3 tessellate_3d(const Tessellation3Options& options, Rng& rng);

// The statistics of a tessellation whose grains (phases, volumes, faces, neighbours) and
// regions are set: sizes, shortest edge, smallest face, sharpest dihedral, the phases'
// fractions and contiguity. Shared by the tessellations read from files (neper_import).
void measure_tessellation(Tessellation3& t);

}  // namespace grainmesh
