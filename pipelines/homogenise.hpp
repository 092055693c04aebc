// Solving an exported case with OpenFOAM and homogenising the result: the volume-averaged
// stress and strain over the cell, the effective modulus in the loading direction, and
// the bounds that enclose it for the same load (Voigt, Reuss, Hashin-Shtrikman).
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "common/deadline.hpp"
#include "export/foam.hpp"

namespace grainmesh {

// Bounds on sigma_xx / eps_xx for the load of the export's default case: eps_xx imposed,
// the mean eps_yy zero (symmetry top and bottom), plane strain (or stress).
struct ElasticBounds {
  double voigt = 0.0;     // uniform strain: <M>
  double reuss = 0.0;     // uniform stress with zero mean eps_yy
  std::optional<double> hs_lower, hs_upper;  // two isotropic phases: Hashin-Shtrikman (2D)
};
ElasticBounds elastic_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                             bool plane_stress);

struct Homogenised {
  double sigma_xx = 0.0, sigma_yy = 0.0, sigma_xy = 0.0;  // Pa, area averages
  double strain_xx = 0.0;                                 // the imposed mean strain
  double modulus = 0.0;                                   // sigma_xx / strain_xx
  int corrections = 0;                                    // solver corrector iterations
  double final_residual = 0.0;                            // its last initial residual (max over D)
};

// The in-plane stress of every cell from an ASCII volSymmTensorField written by OpenFOAM
// (case/1/sigma). Throws GeometryError when it is missing or unreadable.
struct CellStress {
  double xx = 0.0, xy = 0.0, yy = 0.0;
};
std::vector<CellStress> read_cell_stress(const std::filesystem::path& sigma_file);

// The length of the displacement of every cell, from an ASCII volVectorField (case/1/D).
std::vector<double> read_cell_displacement(const std::filesystem::path& d_file);

// Runs solidDisplacementFoam in `case_dir` (written by write_foam_case for `m` with `o`),
// checks that it converged, and averages its stress over the cells. Throws IoError when
// OpenFOAM is missing, GeometryError when the solver fails or does not converge.
// The solver is killed when `deadline` passes (TimeLimitError).
Homogenised solve_and_homogenise(const std::filesystem::path& case_dir, const ExportMesh& m, const FoamOptions& o,
                                 const Deadline& deadline = {});

}  // namespace grainmesh
