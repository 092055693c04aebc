// The 3D tessellation stage: seeds to a cut, labelled, periodic box of polyhedral grains.
#pragma once

#include <vector>

#include "common/random.hpp"
#include "tessellate/laguerre_3d.hpp"
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

// The regions and their shared faces from an exact cut's pieces (a face met twice lies
// between two regions, a face met once on the box), each piece a region of the grain
// grain_of_piece[k] (cut.pieces[k]'s) with that grain's phase. The grains must be set.
void assemble_box_cut(const LaguerreCut& cut, const std::vector<int>& grain_of_piece, Tessellation3& t);

// Each vertex on a low side of the box with the vertex at its position plus the box's
// edge; GeometryError naming a side vertex without its image.
PeriodicPairs box_partners(const Tessellation3& t);

}  // namespace grainmesh
