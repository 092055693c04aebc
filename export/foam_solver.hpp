// How a written case is solved: the stopping rules and tolerances grainmesh's solve
// judges by, OpenFOAM's environment and command line (serial or MPI), the case's own stop,
// the stiffness interpolation, the linear solver and the dictionaries that say so
// (controlDict, fvSolution, decomposeParDict).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "export/foam_load.hpp"
#include "export/foam_options.hpp"

namespace grainmesh {

// How the written case solves: pseudo-time steps of one correction each, stopped when the
// displacement equation's initial residual falls below kSolverTolerance (OpenFOAM's own
// measure, in the case; grainmesh's solve judges a scale-aware one, see solve_monitor.hpp),
// or at kMaxCorrections. The answer is the effective stress: the case logs the force
// through its loaded sides every correction, and grainmesh's solve requires it to have
// settled - no correction of the last kStressWindow changed it by more than
// kStressTolerance (relative) - before it reports a number. The residual tolerance is
// where that holds with a wide margin (measured: the stress settles to 1e-6 around a
// residual of 1e-3 to 1e-4, and is within 1e-8 of its final value at 1e-5).
inline constexpr double kSolverTolerance = 1e-5;
inline constexpr double kStressTolerance = 1e-6;
inline constexpr int kStressWindow = 5;
inline constexpr int kMaxCorrections = 20000;
// The field every solved case holds the stress in, however it stopped: solidDisplacementFoam's
// sigmaD (the stress over rho, and rho is 1), written by the case's writeObjects.
inline constexpr const char* kStressField = "sigmaD";
// The displacement gradient a cyclic case writes beside it (grad(D), by a grad function object).
inline constexpr const char* kGradientField = "grad(D)";

// The environment OpenFOAM's programs run in, the written Allrun and grainmesh's solve
// alike: the Debian package's WM_PROJECT_DIR unless one is set, and glibc's allocator told
// to keep the memory it frees (common/allocator.hpp). The solver allocates and frees whole
// fields every correction; by default glibc maps and unmaps each from the kernel, which
// took half the solve's time (1,000 grains, 46k cells: 2.8 s, 1.3 s with these; the same
// numbers). A user's own GLIBC_TUNABLES follow ours, so theirs win. As NAME=value entries
// to add to this process's environment for a child.
inline constexpr const char* kFoamProjectDir = "/usr/share/openfoam";
std::vector<std::string> foam_environment();

// The command that solves a written case: solidDisplacementFoam, or on o.processes > 1
// `mpirun --oversubscribe -np N solidDisplacementFoam -parallel` (Open MPI; run as root,
// it needs OMPI_ALLOW_RUN_AS_ROOT and OMPI_ALLOW_RUN_AS_ROOT_CONFIRM, which
// foam_environment sets there and Allrun too).
std::vector<std::string> solver_command(const FoamOptions& options);

// The ratio of the stiffest phase's 2 mu + lambda to the softest's, and whether the case
// interpolates the stiffness harmonically (see FoamOptions::interpolation; a 3D case's
// `auto` is linear: harmonic diverged on tetrahedra, measured on a WC-Co cell at a
// contrast of 2.8 and on laminates of 3 and 20, and on their dual on the WC-Co cell).
bool harmonic_stiffness(const FoamCell& cell, const FoamOptions& options);

// Whether the case solves solidDisplacementFoam's compact form (2D, and 3D polyhedra),
// where the force through a face is gamma_f |S| snGrad(D) + S . (sigma - gamma
// grad(D))_f, or the plain one (3D tetrahedra), where it is S . sigma_f
// (analysis/traction.hpp).
inline bool compact_normal_stress(const FoamCell& cell, const FoamOptions& options) {
  return cell.dimensions() == 2 || options.cells == FoamOptions::Cells::polygons;
}

// The linear solver a case uses: options.linear_solver, automatic resolved by the cell's
// dimensions.
FoamOptions::LinearSolver linear_solver(const FoamCell& cell, const FoamOptions& options);
// Its name in OpenFOAM (GAMG, PCG).
const char* linear_solver_name(FoamOptions::LinearSolver solver);
// Writes DIR/system/fvSolution of the case write_foam_case writes.
void write_fv_solution(const std::filesystem::path& dir, const FoamCell& cell, const FoamOptions& options);

// The case's own stop (runTimeControl): OpenFOAM's initial residual of D below
// `tolerance` (kSolverTolerance, a hundredth of it for a cyclic case), of one component
// alone, at a hundredth again, when the others' exact solution is zero (one material
// under a load that moves it along one axis only: the default load, or a cyclic case's
// normal strain).
struct CaseStop {
  int alone = -1;  // the component watched alone (0 x, 1 y, 2 z); -1 all
  double tolerance = kSolverTolerance;
};
CaseStop case_stop(const FoamCell& cell, const FoamOptions& options);

// Writes DIR/system/controlDict of the case write_foam_case writes, its run bounded at
// `end_step` corrections (where it is written if it gets there), its own stop at
// `tighter` times the usual tolerance; from time 0, or (`start` > 0) continued from the
// latest time written.
void write_control_dict(const std::filesystem::path& dir, const FoamCell& cell, const FoamOptions& options,
                        int end_step, double tighter = 1.0, int start = 0);

// system/decomposeParDict: o.processes pieces, the cell cut into nx x ny (x nz in 3D)
// blocks as near cubic as the count allows (hierarchical: Debian's OpenFOAM has no
// working scotch or metis), each cyclic face kept on one processor with its partner
// (fixedJump does not cross processors).
void write_decompose_dict(const std::filesystem::path& dir, const FoamCell& cell, const FoamOptions& options);

}  // namespace grainmesh
