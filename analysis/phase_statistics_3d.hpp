// Where the stress is in a 3D cell: per phase, the volume-weighted mean stress tensor and
// the distributions of the von Mises and hydrostatic stresses over its cells (each cell
// by its share of the phase's volume; phase_statistics.hpp's Distribution).
#pragma once

#include <vector>

#include "analysis/foam_fields.hpp"
#include "analysis/phase_statistics.hpp"

namespace grainmesh {

struct PhaseStresses3 {
  double volume_fraction = 0.0;
  std::array<double, 6> mean{};  // xx yy zz yz xz xy
  Distribution von_mises, hydrostatic;
};

// The von Mises stress of a symmetric tensor as OpenFOAM writes it (xx xy xz yy yz zz).
double von_mises_3d(const double* sigma);
// Each phase's share of the cells' volume (`phases` of them).
std::vector<double> phase_volume_fractions(const std::vector<double>& volume, const std::vector<int>& phase, int phases);

// From the cells' stresses (sigma as OpenFOAM writes it: xx xy xz yy yz zz), volumes and
// phases (`phases` of them). With `balanced` stresses (the face forces' virial,
// DiscreteTraction::virial_stress_tensor) the mean tensors are theirs: the phases' means
// then add up, volume-weighted, to the cell's mean stress exactly.
std::vector<PhaseStresses3> phase_stresses_3d(const FieldValues& sigma, const std::vector<double>& volume,
                                              const std::vector<int>& phase, int phases,
                                              const FieldValues* balanced = nullptr);

}  // namespace grainmesh
