// The fine level of two nested finite-element levels solved iteratively: conjugate
// gradients preconditioned by a two-grid cycle — a forward Gauss–Seidel sweep, the coarse
// level's exact correction through the prolongation (the coarse space lies in the fine
// one), a backward sweep: symmetric, so the conjugate gradients hold. The loads' columns
// are solved in two groups, side by side on up to `threads` threads, each group's columns
// side by side in its sweeps; the sweeps read a single-precision copy of the matrix's
// values (fe_two_grid.cpp). Private to the finite-element solve: Eigen's types, included
// only by the .cpp files that wrap Eigen (fe_homogenise.cpp, fe_two_grid.cpp).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <functional>

namespace grainmesh {

struct TwoGridSolve {
  Eigen::MatrixXd u;       // a column per load
  int iterations = 0;      // the conjugate gradients' (each one cycle)
  bool converged = false;  // every column's residual within the tolerance of its load's norm
};

// Applies the coarse matrix's inverse to columns; called side by side by the groups of
// loads (two_grid_solve), so it must be safe to.
using CoarseSolve = std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>;

// Solves K u = f, K symmetric positive definite given by its lower triangle `k_lower`
// (column-major, diagonal first in each column), from `u0`; `prolongation` maps the
// coarse unknowns to the fine. Stops when every column's residual is below `tolerance`
// times its load's norm, or after `max_iterations` (converged false: the caller solves
// otherwise); `iterations` is the most any group took.
TwoGridSolve two_grid_solve(const Eigen::SparseMatrix<double>& k_lower, const Eigen::MatrixXd& f,
                            const Eigen::SparseMatrix<double>& prolongation, const CoarseSolve& coarse_solve,
                            const Eigen::MatrixXd& u0, double tolerance, int max_iterations, int threads);

// One cycle of the preconditioner on the columns of `r`: K^-1 r as one two-grid cycle
// approximates it, a symmetric positive definite operator wherever `coarse_solve` is one —
// so it may serve as a finer level's coarse solve (the cycles nested: a V-cycle).
Eigen::MatrixXd two_grid_cycle(const Eigen::SparseMatrix<double>& k_lower, const Eigen::MatrixXd& r,
                               const Eigen::SparseMatrix<double>& prolongation, const CoarseSolve& coarse_solve);

}  // namespace grainmesh
