// Labelling grains with phases: the target fractions, and a phase for each grain so that
// the phases' areas approach them in the configured arrangement.
#pragma once

#include <vector>

#include "common/random.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

// The area fraction phase p is to have: its own, or for the rest phase what the others leave.
double target_fraction(const std::vector<Phase>& phases, int p);

// A phase for each grain, so that the summed `areas` of the grains of each phase with a
// fraction approach fraction x total_area (greedy in the arrangement's order, then best
// single swaps); the rest phase (or, without one, the last phase) takes the remaining
// grains. `phases` indexes into `all`.
std::vector<int> assign_phases(const std::vector<double>& areas, const std::vector<std::vector<int>>& neighbours,
                               const std::vector<Phase>& all, const std::vector<int>& phases, double total_area,
                               Arrangement arrangement, Rng& rng);

}  // namespace grainmesh
