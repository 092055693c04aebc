// Eigen and CHOLMOD are included here (through fe_coarse_level.hpp, private to the
// finite-element solve).
#include "analysis/fe_coarse_level.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "analysis/fe_two_grid.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/memory.hpp"

namespace grainmesh {

namespace {

// Refuses a factor that would not fit: CHOLMOD's count of its nonzeros (known after the
// analysis, before any is made), 8 bytes each and 60 % more for the supernodes' padding
// and CHOLMOD's workspace, beside the matrix (three copies), the loads' columns (right
// sides and solutions) and the BLAS's own buffers (OpenBLAS takes 128 MiB per call of the
// dense factorisation, and retries for ever where it cannot: under ulimit -v the run
// would hang), and `beside` bytes the solve holds besides (nested levels: the other
// levels' matrices and columns). On the 3D example, its coarse level factorised: 4.9 GiB
// estimated, 5.2 GiB measured (the run's peak, OpenFOAM's stage included).
constexpr double kBlasBufferMiB = 256.0;
void check_memory(double factor_nonzeros, const Eigen::SparseMatrix<double>& k, int loads, std::size_t unknowns,
                  const FeOptions& o, double beside) {
  constexpr double kMiB = 1024.0 * 1024.0;
  const double need = (1.6 * 8.0 * factor_nonzeros + 3.0 * 12.0 * static_cast<double>(k.nonZeros()) +
                       3.0 * 8.0 * static_cast<double>(loads) * static_cast<double>(unknowns) + beside) / kMiB +
                      kBlasBufferMiB;
  const double have = o.memory_mib > 0.0 ? o.memory_mib : available_memory_mib();
  auto size = [](double mib) { return mib < 1024.0 ? to_text(mib, 3) + " MiB" : to_text(mib / 1024.0, 3) + " GiB"; };
  const std::string key = o.reference ? "homogenise.reference" : "homogenise.solver";
  if (need > have)
    throw ConfigError(key + " = fe: the finite elements on this mesh (" + std::to_string(unknowns) +
                      " unknowns) need about " + size(need) + ", more than the " + size(have) + " available: set " +
                      key + (o.reference ? " = none" : " = openfoam") + ", or mesh coarser or fewer grains");
}

// Levels up to this many unknowns (the tests' cells) have their linear elements' stiffness
// checked against P^T K P, which it is to rounding (4.6e-16 of the largest entry measured
// on the 100- and 1,000-grain 3D cells): cheap there, and a wrong one would only slow the
// cycles, not change the answer.
constexpr Eigen::Index kCheckedRows = 30000;

void check_linear_stiffness(const Eigen::SparseMatrix<double>& k, const Eigen::SparseMatrix<double>& p,
                            const Eigen::SparseMatrix<double>& k_linear) {
  const Eigen::SparseMatrix<double> full = k.selfadjointView<Eigen::Lower>();
  const Eigen::SparseMatrix<double> galerkin =
      Eigen::SparseMatrix<double>(p.transpose() * full * p).triangularView<Eigen::Lower>();
  const double largest = galerkin.coeffs().cwiseAbs().maxCoeff();
  const auto differs = [&] {
    return !(Eigen::SparseMatrix<double>(galerkin - k_linear).coeffs().cwiseAbs().maxCoeff() <= 1e-12 * largest);
  };
  if (galerkin.rows() != k_linear.rows() || differs())
    throw GeometryError("finite elements: the linear elements' stiffness is not P^T K P (a grainmesh bug, please "
                        "report it)");
}

}  // namespace

std::unique_ptr<Factor> analyse(const Eigen::SparseMatrix<double>& k) {
  auto factor = std::make_unique<Factor>();
  factor->cholmod().nmethods = 1;  // the unknowns are numbered in a fill-reducing order (fe_nodes.hpp)
  factor->cholmod().method[0].ordering = CHOLMOD_NATURAL;
  factor->analyzePattern(k);
  return factor;
}

std::unique_ptr<Factor> factorise(std::unique_ptr<Factor> factor, const Eigen::SparseMatrix<double>& k, int loads,
                                  const FeOptions& o, double beside) {
  check_memory(factor->cholmod().lnz, k, loads, static_cast<std::size_t>(k.rows()), o, beside);
  factor->factorize(k);
  if (factor->info() != Eigen::Success)
    throw GeometryError("finite-element reference: the stiffness matrix is not positive definite (a phase without "
                        "stiffness, or a mesh the periodic ties do not hold)");
  return factor;
}

template <int D>
std::vector<int> linear_columns(const FeNodes<D>& n) {
  std::vector<int> column(n.unknowns / D, -1);  // per node class: its corner's column, or -1
  for (const auto& nodes : n.element)
    for (int a = 0; a <= D; ++a)
      if (const int r = n.first[static_cast<std::size_t>(nodes[static_cast<std::size_t>(a)])]; r >= 0)
        column[static_cast<std::size_t>(r / D)] = 0;
  int corners = 0;
  for (int& c : column)
    if (c == 0) c = corners++;
  return column;
}

template std::vector<int> linear_columns(const FeNodes<2>&);
template std::vector<int> linear_columns(const FeNodes<3>&);

template <int D>
Eigen::SparseMatrix<double> linear_prolongation(const FeNodes<D>& n, const std::vector<int>& column) {
  constexpr auto edges = Simplex<D>::edges();
  const auto corners = static_cast<int>(std::count_if(column.begin(), column.end(), [](int c) { return c >= 0; }));
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<char> done(column.size(), 0);
  for (const auto& nodes : n.element)
    for (int a = 0; a < Simplex<D>::kNodes; ++a) {
      const int r = n.first[static_cast<std::size_t>(nodes[static_cast<std::size_t>(a)])];
      if (r < 0 || done[static_cast<std::size_t>(r / D)]) continue;
      done[static_cast<std::size_t>(r / D)] = 1;
      for (int end = 0; end < (a <= D ? 1 : 2); ++end) {
        const int corner = a <= D ? a : edges[static_cast<std::size_t>(a - D - 1)][static_cast<std::size_t>(end)];
        const int s = n.first[static_cast<std::size_t>(nodes[static_cast<std::size_t>(corner)])];
        if (s < 0) continue;  // the held node: no unknowns
        for (int d = 0; d < D; ++d)
          entries.emplace_back(r + d, D * column[static_cast<std::size_t>(s / D)] + d, a <= D ? 1.0 : 0.5);
      }
    }
  Eigen::SparseMatrix<double> out(static_cast<Eigen::Index>(n.unknowns), static_cast<Eigen::Index>(D) * corners);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

template Eigen::SparseMatrix<double> linear_prolongation(const FeNodes<2>&, const std::vector<int>&);
template Eigen::SparseMatrix<double> linear_prolongation(const FeNodes<3>&, const std::vector<int>&);

template <int D>
CoarseLevel::CoarseLevel(const Eigen::SparseMatrix<double>& k, const FeNodes<D>& nodes, const LinearStiffness& linear,
                         int loads, const FeOptions& o)
    : k_(k), loads_(loads), options_(o) {
  // The fine level beside (2^D times the coarse level's elements, about as many times its
  // unknowns and entries): its matrix (and its values' single-precision copy for the
  // cycle's sweeps) and its conjugate gradients' eight blocks of columns.
  constexpr double kSplit = 1 << D;
  const auto entries = static_cast<double>(k.nonZeros());
  const double columns = 64.0 * loads * static_cast<double>(k.rows());  // eight blocks of the loads' columns
  fine_ = kSplit * (16.0 * entries + columns);
  factor_ = analyse(k);
  if (factor_->cholmod().fl <= o.coarse_factor_flops) {
    factor_ = factorise(std::move(factor_), k, loads, o, fine_);
    return;
  }
  // Beside the linear elements' factor: the coarse level's matrix, its conjugate gradients'
  // columns, and the fine level; refused before the linear elements are made where even
  // they, without their (small) factor, would not fit.
  const double beside = 12.0 * entries + columns + fine_;
  check_memory(0.0, k, loads, static_cast<std::size_t>(k.rows()), o, beside);
  const std::vector<int> corner_columns = linear_columns(nodes);
  linear_ = linear_prolongation(nodes, corner_columns);
  const Eigen::SparseMatrix<double> k_linear = linear(corner_columns);
  if (k.rows() <= kCheckedRows) check_linear_stiffness(k, linear_, k_linear);
  factor_ = factorise(analyse(k_linear), k_linear, loads, o, beside);
}

template CoarseLevel::CoarseLevel(const Eigen::SparseMatrix<double>&, const FeNodes<2>&, const LinearStiffness&, int,
                                  const FeOptions&);
template CoarseLevel::CoarseLevel(const Eigen::SparseMatrix<double>&, const FeNodes<3>&, const LinearStiffness&, int,
                                  const FeOptions&);

Eigen::MatrixXd CoarseLevel::cycle(const Eigen::MatrixXd& r) const {
  if (!cycled()) return factor_solve(r);
  return two_grid_cycle(k_, r, linear_, [this](const Eigen::MatrixXd& x) { return factor_solve(x); });
}

Eigen::MatrixXd CoarseLevel::solve(const Eigen::MatrixXd& f, double tolerance, int max_iterations) {
  iterations_ = 0;
  if (!cycled()) return factor_solve(f);
  const TwoGridSolve s = two_grid_solve(
      k_, f, linear_, [this](const Eigen::MatrixXd& x) { return factor_solve(x); },
      Eigen::MatrixXd::Zero(f.rows(), f.cols()), tolerance, max_iterations, 1);  // beside the fine assembly
  if (s.converged) {
    iterations_ = s.iterations;
    return s.u;
  }
  linear_.resize(0, 0);
  factor_ = factorise(analyse(k_), k_, loads_, options_, fine_);
  return factor_solve(f);
}

}  // namespace grainmesh
