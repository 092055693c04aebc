// Running solidDisplacementFoam on a written case and following it to convergence.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "common/deadline.hpp"
#include "export/foam_load.hpp"
#include "export/foam_options.hpp"
#include "export/foam_solver.hpp"

namespace grainmesh {

struct SolveRun {
  int corrections = 0;                          // solver corrections
  double final_residual = 0.0;                  // the convergence measure at the last (solve_monitor.hpp)
  std::vector<double> component_residuals;      // OpenFOAM's own residuals of Dx, Dy (and Dz in 3D) there
  double stress_change = 0.0;                   // the largest relative change of the effective stress
                                                // over the last kStressWindow corrections
  std::filesystem::path result_dir;             // the time directory holding the fields
  std::string linear_solver;                    // OpenFOAM's linear solver of D (GAMG, PCG)
  std::string linear_solver_fallback;           // why it is not the case's first (GAMG diverged), or empty
  // Wall-clock seconds of OpenFOAM's steps: the solver's runs, and around them on several
  // processes decomposePar and reconstructPar (zero on one).
  double solver_seconds = 0.0, decompose_seconds = 0.0, reconstruct_seconds = 0.0;
};

// How many cases to solve side by side when each runs on `processes` MPI processes: as
// many as the machine's cores take, at least one.
int solves_side_by_side(int processes);

// Runs solidDisplacementFoam in `case_dir` (written by write_foam_case, or
// write_foam_case, for a mesh of `cell` with `o`), following its log: it is stopped
// once converged (solve_monitor.hpp), or killed within a few hundred corrections of
// stalling or diverging. A case whose multigrid linear solver diverges is solved again
// from its start with conjugate gradients (SolveRun says so). Throws IoError when
// OpenFOAM is missing, SolveError (one line naming the field and `load_case` when given,
// what happened and what to do, and the log as found under `case_shown_as`, when given)
// when it fails, and TimeLimitError when `deadline` passes.
SolveRun run_solver(const std::filesystem::path& case_dir, const FoamCell& cell, const FoamOptions& o,
                    const Deadline& deadline = {}, const std::filesystem::path& case_shown_as = {},
                    const std::string& load_case = {});

}  // namespace grainmesh
