// The sparse factors of the finite-element solve and the coarse of its two nested levels.
// Private to that solve: Eigen's and CHOLMOD's types, included only by the .cpp files that
// wrap them (fe_homogenise.cpp, fe_coarse_level.cpp).
#pragma once

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "analysis/fe_homogenise.hpp"
#include "analysis/fe_nodes.hpp"

namespace grainmesh {

using Factor = Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower>;

// CHOLMOD's analysis of `k` (its lower triangle, its unknowns already in a fill-reducing
// order, fe_nodes.hpp): the factor's pattern, its nonzeros and operations counted before
// any is made.
std::unique_ptr<Factor> analyse(const Eigen::SparseMatrix<double>& k);

// The sparse Cholesky factor of `k` from its analysis, refused before it is made when it
// would not fit beside `beside` bytes the solve holds besides: ConfigError naming
// homogenise.solver (or .reference). GeometryError when `k` is not positive definite.
std::unique_ptr<Factor> factorise(std::unique_ptr<Factor> analysed, const Eigen::SparseMatrix<double>& k, int loads,
                                  const FeOptions& o, double beside = 0.0);

// The stiffness of a level's linear elements (its lower triangle) in linear_columns'
// numbering, given that numbering: P^T K P for K the quadratic elements' and P
// linear_prolongation, which it equals (the linear functions are quadratic ones and the
// quadrature is exact for their products), assembled directly (fe_homogenise.cpp).
using LinearStiffness = std::function<Eigen::SparseMatrix<double>(const std::vector<int>& columns)>;

// The coarse level's solves: by its own factor where that costs at most
// FeOptions::coarse_factor_flops (CHOLMOD's count), else by conjugate gradients with a
// two-grid cycle on its linear elements, whose factor is small (`linear`'s stiffness, P
// from linear_prolongation). Either way the level's answer is solved to the fine level's
// tolerance, and its cycle (the fine level's coarse correction) is the factor's solve or
// one two-grid cycle: the fine level's cycle is then a V-cycle over three levels.
class CoarseLevel {
 public:
  // `k` (kept by reference) the level's matrix, its lower triangle; `nodes` its quadratic
  // nodes; the fine level beside it 2^D times its elements.
  template <int D>
  CoarseLevel(const Eigen::SparseMatrix<double>& k, const FeNodes<D>& nodes, const LinearStiffness& linear, int loads,
              const FeOptions& o);

  // The level solved, each load's residual to `tolerance` of its norm; factorised after
  // all when `max_iterations` cycles do not reach it.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& f, double tolerance, int max_iterations);
  // The fine level's coarse correction: the factor's solve, or one cycle. Safe to call
  // side by side (the fine level's groups of loads): only the factor's solve, which
  // CHOLMOD's workspace makes unsafe, is taken one call at a time, not the cycle's sweeps.
  Eigen::MatrixXd cycle(const Eigen::MatrixXd& r) const;
  // The conjugate gradients' cycles of the last solve (0: factorised).
  int iterations() const { return iterations_; }

 private:
  Eigen::MatrixXd factor_solve(const Eigen::MatrixXd& r) const {
    const std::lock_guard<std::mutex> hold(factor_lock_);
    return factor_->solve(r);
  }
  bool cycled() const { return linear_.size() != 0; }  // solved by cycles, not by its own factor

  const Eigen::SparseMatrix<double>& k_;
  int loads_;
  FeOptions options_;
  std::unique_ptr<Factor> factor_;      // the level's own, or its linear elements'
  mutable std::mutex factor_lock_;      // its solve, one call at a time
  Eigen::SparseMatrix<double> linear_;  // the prolongation from the linear elements; empty: `factor_` is the level's own
  int iterations_ = 0;
  double fine_ = 0.0;  // bytes the fine level holds beside this one
};

// The linear elements' numbering: per class of tied quadratic nodes (its unknowns' first
// / D), its column block among the corners' (in the quadratic level's order), or -1 for a
// class of midside nodes only. The linear unknowns are D per corner class, D x column + d.
template <int D>
std::vector<int> linear_columns(const FeNodes<D>& nodes);

// The linear elements of a level's own mesh inside its quadratic ones: the prolongation
// from the corners' unknowns (linear_columns) to the level's — a corner node's its own, a
// midside node's the mean of its edge's ends'.
template <int D>
Eigen::SparseMatrix<double> linear_prolongation(const FeNodes<D>& nodes, const std::vector<int>& columns);

}  // namespace grainmesh
