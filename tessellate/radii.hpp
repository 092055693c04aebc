// Seed radii for Laguerre tessellations, 2D and 3D.
#pragma once

#include <vector>

#include "common/random.hpp"

namespace grainmesh {

// Lognormal radii of median 1 with coefficient of variation `cv`, one per seed: the
// Laguerre sizes of both the 2D and the 3D stage (Box-Muller, two draws per radius).
std::vector<double> lognormal_radii(int n, double cv, Rng& rng);

}  // namespace grainmesh
