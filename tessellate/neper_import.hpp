// A Neper tessellation (neper_tess.hpp) as our own: its cells as grains with their seeds,
// in a cell whose low corner is the domain's, shared vertices exact, the statistics of a
// generated one. A periodic file's whole cells are cut by the box into pieces that match
// across its sides, as a generated periodic cell's are. Phases come from the cells' groups
// through a table, or by our rules (by area or volume, in the arrangement asked).
// Everything downstream (mesh, export, solve, pictures) takes it unchanged.
#pragma once

#include <string>
#include <vector>

#include "common/random.hpp"
#include "tessellate/neper_tess.hpp"
#include "tessellate/read_tessellation.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// How the phases are given: `phases` with, when `group_phases` is not empty, the phase of
// each of the file's cell groups; else by our rules in `arrangement`.
struct NeperPhases {
  std::vector<Phase> phases;
  Arrangement arrangement = Arrangement::random;
  std::vector<LabelPhase> group_phases;
};

// GeometryError naming `source` when the tessellation is not a 2D (3D) one of a square
// (cube) domain, is periodic along some axes only, its periodic images do not lie a
// period apart, or its cells do not tile the domain; UnnamedLabelError (a GeometryError)
// when a group has no phase in the table or the file has no groups.
Tessellation plane_tessellation(const NeperTess& n, const NeperPhases& phases, Rng& rng, const std::string& source);
Tessellation3 solid_tessellation(const NeperTess& n, const NeperPhases& phases, Rng& rng, const std::string& source);

}  // namespace grainmesh
