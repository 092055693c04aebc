// Solving an exported case with OpenFOAM and homogenising the result: the volume-averaged
// stress and strain over the cell, the effective modulus in the loading direction, and
// the bounds that enclose it for the same load (Voigt, Reuss, Hashin-Shtrikman).
#pragma once

#include <array>
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
  int corrections = 0;                                    // solver corrections
  double final_residual = 0.0;                            // the convergence measure at the last (solve_monitor.hpp)
  std::array<double, 2> component_residuals{};            // OpenFOAM's own residuals of Dx and Dy there
  std::filesystem::path result_dir;                       // the time directory holding D and sigma
};

// The in-plane stress of every cell from an ASCII volSymmTensorField written by OpenFOAM
// (CASE/TIME/sigmaD, kStressField). Throws GeometryError when it is missing or unreadable.
struct CellStress {
  double xx = 0.0, xy = 0.0, yy = 0.0;
};
std::vector<CellStress> read_cell_stress(const std::filesystem::path& sigma_file);

// The length of the displacement of every cell, from an ASCII volVectorField (CASE/TIME/D).
std::vector<double> read_cell_displacement(const std::filesystem::path& d_file);

// The case's latest time directory: where the solver wrote D and sigma. Throws
// SolveError when there is none.
std::filesystem::path latest_time_dir(const std::filesystem::path& case_dir);

// Runs solidDisplacementFoam in `case_dir` (written by write_foam_case for `m` with `o`),
// following its log: it is stopped once converged (solve_monitor.hpp), or killed within
// a few hundred corrections of stalling or diverging. Then averages its stress over the
// cells. Throws IoError when OpenFOAM is missing, SolveError (one line naming the field,
// what happened and what to do, and the log as found under `case_shown_as`, when given)
// when it fails, and TimeLimitError when `deadline` passes.
Homogenised solve_and_homogenise(const std::filesystem::path& case_dir, const ExportMesh& m, const FoamOptions& o,
                                 const Deadline& deadline = {}, const std::filesystem::path& case_shown_as = {});

}  // namespace grainmesh
