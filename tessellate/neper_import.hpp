// A Neper tessellation (neper_tess.hpp) as our own: its cells as grains with their seeds,
// in a cell whose low corner is the domain's, phases assigned by our rules (by area or
// volume, in the arrangement asked), shared vertices exact, the statistics of a generated
// one. Everything downstream (mesh, export, solve, pictures) takes it unchanged.
#pragma once

#include <vector>

#include "common/random.hpp"
#include "tessellate/neper_tess.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// GeometryError naming `source` when the tessellation is not a 2D (3D) one of a square
// (cube) domain, is periodic (not read yet), or its cells do not tile the domain.
Tessellation plane_tessellation(const NeperTess& n, const std::vector<Phase>& phases, Arrangement arrangement,
                                Rng& rng, const std::string& source);
Tessellation3 solid_tessellation(const NeperTess& n, const std::vector<Phase>& phases, Arrangement arrangement,
                                 Rng& rng, const std::string& source);

}  // namespace grainmesh
