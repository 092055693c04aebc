// What a tessellation's phases tell its user, plane and solid cells alike: a phase left
// without grains is refused, a fraction missed is a warning.
#pragma once

#include <string>
#include <vector>

#include "pipelines/config_origin.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

// Refuses (ConfigError naming its fraction, through `origin`) a phase that got none of the
// `grains` grains (but the binder mode's `matrix_phase`), with the grain count that would
// give it one: the commands' check before meshing, plane and solid cells alike.
void check_phases_have_grains(const std::vector<Phase>& phases, const std::vector<PhaseStats>& stats, int grains,
                              const ConfigOrigin& origin, int matrix_phase = -1);
// What a tessellation should tell its user: phase fractions that missed their target by
// more than 0.01.
std::vector<std::string> phase_fraction_warnings(const std::vector<Phase>& phases, const std::vector<PhaseStats>& stats,
                                                 int grains);

}  // namespace grainmesh
