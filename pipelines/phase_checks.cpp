#include "pipelines/phase_checks.hpp"

#include <cmath>

#include "common/format.hpp"

namespace grainmesh {

void check_phases_have_grains(const std::vector<Phase>& phases, const std::vector<PhaseStats>& stats, int grains,
                              const ConfigOrigin& origin, int matrix_phase) {
  // A phase without a grain is not in the microstructure at all: its properties would
  // never reach the solver. A grain has about 1 / N of the cell, so 1 / fraction grains
  // give every phase one.
  for (std::size_t p = 0; p < phases.size(); ++p) {
    const PhaseStats& s = stats[p];
    if (s.grains > 0 || static_cast<int>(p) == matrix_phase) continue;
    origin.fail("phase." + phases[p].name + ".fraction",
                "a fraction of " + to_text(s.target_fraction) + " gives the phase none of the " +
                    std::to_string(grains) + " grains: use at least " + to_text(std::ceil(1.0 / s.target_fraction - 1e-9)) +
                    " grains (tessellation.grains), about 50 for fractions within 1 %");
  }
}

std::vector<std::string> phase_fraction_warnings(const std::vector<Phase>& phases, const std::vector<PhaseStats>& stats,
                                                 int grains) {
  std::vector<std::string> warnings;
  for (std::size_t p = 0; p < phases.size(); ++p) {
    const PhaseStats& s = stats[p];
    if (std::abs(s.achieved_fraction - s.target_fraction) > 0.01)
      warnings.push_back("phase." + phases[p].name + ".fraction: " + to_text(s.achieved_fraction, 4) +
                         " achieved for a target of " + to_text(s.target_fraction, 4) + " with " +
                         std::to_string(grains) + " grains (about 50 or more meet targets within 0.01)");
  }
  return warnings;
}

}  // namespace grainmesh
