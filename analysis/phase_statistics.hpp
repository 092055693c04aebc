// Where the stress is, in 2D and 3D alike: per phase, its share of the cell, the
// weighted mean stress tensor and the distributions of the von Mises, largest principal
// and hydrostatic stresses over the phase's cells (each cell weighted by its area in 2D,
// its volume in 3D: by its share of the phase), and the stress partition, the phase's mean
// of the loaded component over the cell's.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/stress_measures.hpp"
#include "mesh/cell_mesh.hpp"

namespace grainmesh {

// An area-weighted distribution: mean, standard deviation, the 50th, 90th and 99th
// percentiles (the smallest value at or below which that share of the area lies), maximum.
struct Distribution {
  double mean = 0.0, std = 0.0, p50 = 0.0, p90 = 0.0, p99 = 0.0, max = 0.0;
};
Distribution distribution(const std::vector<double>& values, const std::vector<double>& weights);

struct PhaseStresses {
  double volume_fraction = 0.0;  // the phase's share of the weights (the area in 2D)
  StressTensor mean{};           // weighted mean tensor, Pa
  Distribution von_mises, max_principal, hydrostatic;
  std::optional<double> partition;  // the phase's mean of the loaded component over the cell's
};

// Each phase's share of the cells' weights (areas or volumes; `phases` of them).
std::vector<double> phase_volume_fractions(const std::vector<double>& weight, const std::vector<int>& phase, int phases);

// Per phase (phase[c] of cell c, `phases` of them), from the cells' stresses and weights;
// `loaded` the Voigt index of the load case's loaded component (0 xx ... 5 xy), or -1 for
// none (no partition then). With `balanced` stresses (the face forces' virial,
// DiscreteTraction) the mean tensors and the partition are theirs: the phases' means then
// add up, weighted, to the cell's mean stress exactly; the distributions stay the cells'.
std::vector<PhaseStresses> phase_stresses(const std::vector<StressTensor>& stress, const std::vector<double>& weight,
                                          const std::vector<int>& phase, int phases, int loaded = -1,
                                          const std::vector<StressTensor>* balanced = nullptr);

// Each phase's weighted histogram of one value per cell (`weights` their areas or
// volumes): `bins` equal bins over the range of all cells, each point (the bin's centre,
// the share of the phase's weight in it).
std::vector<std::vector<Vec2>> phase_histograms(const std::vector<double>& values, const std::vector<double>& weights,
                                                const std::vector<int>& phase, int phases, int bins);
// Each phase's area-weighted histogram of the von Mises stress (phase_histograms).
std::vector<std::vector<Vec2>> von_mises_histograms(const std::vector<StressState>& cell_stress, const CellMesh& mesh,
                                                    const std::vector<int>& phase, int phases, int bins);

}  // namespace grainmesh
