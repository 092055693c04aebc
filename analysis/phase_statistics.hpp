// Where the stress is: per phase, the area-weighted mean stress tensor and the
// distributions of the von Mises, largest principal and hydrostatic stresses over the
// phase's cells (area-weighted: a cell counts by its share of the phase's area), and the
// stress partition, the phase's mean of the loaded component over the cell's.
#pragma once

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
  double area_fraction = 0.0;
  StressState mean;  // area-weighted mean tensor
  Distribution von_mises, max_principal, hydrostatic;
  double partition = 0.0;  // the phase's mean of the loaded component over the cell's mean
};

// Per phase (phase[t] of triangle t, `phases` of them), from the cells' stresses; the
// loaded component of the load case: 0 xx, 1 yy, 2 xy, -1 none (the partition then 0).
// With `balanced` stresses (the face forces' virial, DiscreteTraction::virial_stress), the
// in-plane mean tensor and the partition are theirs: the phases' means then add up,
// area-weighted, to the cell's mean stress exactly.
std::vector<PhaseStresses> phase_stresses(const std::vector<StressState>& cell_stress, const CellMesh& mesh,
                                          const std::vector<int>& phase, int phases, int loaded_component,
                                          const std::vector<StressState>* balanced = nullptr);

// Each phase's weighted histogram of one value per cell (`weights` their areas or
// volumes): `bins` equal bins over the range of all cells, each point (the bin's centre,
// the share of the phase's weight in it).
std::vector<std::vector<Vec2>> phase_histograms(const std::vector<double>& values, const std::vector<double>& weights,
                                                const std::vector<int>& phase, int phases, int bins);
// Each phase's area-weighted histogram of the von Mises stress (phase_histograms).
std::vector<std::vector<Vec2>> von_mises_histograms(const std::vector<StressState>& cell_stress, const CellMesh& mesh,
                                                    const std::vector<int>& phase, int phases, int bins);

}  // namespace grainmesh
