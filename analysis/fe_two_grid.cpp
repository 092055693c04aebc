#include "analysis/fe_two_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

#include "common/side_by_side.hpp"

namespace grainmesh {

namespace {

// The sweeps' and products' loops run ten thousand times a solve: the sanitizer build
// leaves them uninstrumented (a tenfold slower make test otherwise), their indices are the
// matrix's own, and the tests hold the result to the factorised solve's.
#define GM_HOT_LOOP __attribute__((no_sanitize("address", "undefined")))

// Columns stored row by row: a node's loads side by side for the sweeps.
using Block = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The symmetric matrix from its lower triangle, as raw column-major arrays; its values in
// double, and for the cycle's sweeps in single precision where `values_f` holds them. The
// sweeps stream the matrix from memory four times a cycle: single-precision values read a
// third fewer bytes (the 1,000-grain 3D answer 60.4 -> 55.7 s, paired runs; 400 MB more
// at its peak). The cycle is then the symmetric two-grid cycle of the rounded matrix, still
// symmetric positive definite, and the conjugate gradients' products and residuals stay in
// double: the answer is solved to the same residual (it moved by 1e-14 on the 3D example).
struct Lower {
  const int* outer;
  const int* inner;
  const double* value;
  int n;
  std::vector<float> values_f;

  explicit Lower(const Eigen::SparseMatrix<double>& k)
      : outer(k.outerIndexPtr()), inner(k.innerIndexPtr()), value(k.valuePtr()), n(static_cast<int>(k.outerSize())) {}
  const float* value_of(float) const { return values_f.data(); }
  const double* value_of(double) const { return value; }
};

// The loops over the matrix for blocks of M columns, M known to the compiler: each
// entry's update of a row's M loads unrolled (twice the speed of a loop over a run-time
// count on the 1,000-grain cell).
template <int M, class V = double>
struct Sweeps {
  static double* row(Block& x, int i) { return x.data() + static_cast<std::ptrdiff_t>(i) * M; }
  static const double* row(const Block& x, int i) { return x.data() + static_cast<std::ptrdiff_t>(i) * M; }

  // y = K x.
  GM_HOT_LOOP static void product(const Lower& k, const Block& x, Block& y) {
    const V* value = k.value_of(V{});
    y.setZero();
    for (int j = 0; j < k.n; ++j) {
      const double* xj = row(x, j);
      double* yj = row(y, j);
      double sum[M] = {};
      for (int p = k.outer[j]; p < k.outer[j + 1]; ++p) {
        const int i = k.inner[p];
        const double v = static_cast<double>(value[p]);
        const double* xi = row(x, i);
        double* yi = row(y, i);
        for (int c = 0; c < M; ++c) sum[c] += v * xi[c];
        if (i != j)
          for (int c = 0; c < M; ++c) yi[c] += v * xj[c];
      }
      for (int c = 0; c < M; ++c) yj[c] += sum[c];
    }
  }

  // y = L^T x, L the strict lower triangle: after a forward sweep z = (D + L)^-1 r, the
  // residual r - K z is -L^T z at half a product's cost.
  GM_HOT_LOOP static void strict_upper_product(const Lower& k, const Block& x, Block& y) {
    const V* value = k.value_of(V{});
    for (int j = 0; j < k.n; ++j) {
      double sum[M] = {};
      for (int p = k.outer[j] + 1; p < k.outer[j + 1]; ++p) {
        const double* xi = row(x, k.inner[p]);
        for (int c = 0; c < M; ++c) sum[c] += static_cast<double>(value[p]) * xi[c];
      }
      double* yj = row(y, j);
      for (int c = 0; c < M; ++c) yj[c] = sum[c];
    }
  }

  // x = (D + L)^-1 b: the forward Gauss–Seidel sweep from zero, column by column.
  GM_HOT_LOOP static void forward_sweep(const Lower& k, Block& x) {
    const V* value = k.value_of(V{});
    for (int j = 0; j < k.n; ++j) {
      double* xj = row(x, j);
      const int d = k.outer[j];  // the diagonal, first in its column
      for (int c = 0; c < M; ++c) xj[c] /= static_cast<double>(value[d]);
      for (int p = d + 1; p < k.outer[j + 1]; ++p) {
        double* xi = row(x, k.inner[p]);
        for (int c = 0; c < M; ++c) xi[c] -= static_cast<double>(value[p]) * xj[c];
      }
    }
  }

  // x = (D + L^T)^-1 b: the backward sweep, its transpose.
  GM_HOT_LOOP static void backward_sweep(const Lower& k, Block& x) {
    const V* value = k.value_of(V{});
    for (int j = k.n - 1; j >= 0; --j) {
      double* xj = row(x, j);
      const int d = k.outer[j];
      double sum[M] = {};
      for (int p = d + 1; p < k.outer[j + 1]; ++p) {
        const double* xi = row(x, k.inner[p]);
        for (int c = 0; c < M; ++c) sum[c] += static_cast<double>(value[p]) * xi[c];
      }
      for (int c = 0; c < M; ++c) xj[c] = (xj[c] - sum[c]) / static_cast<double>(value[d]);
    }
  }
};

// Each column's dot product of a and b.
Eigen::RowVectorXd column_dots(const Block& a, const Block& b) { return a.cwiseProduct(b).colwise().sum(); }

// The cycle on M columns: z = the cycle on r, pre-smoothed (a forward sweep), corrected
// on the coarse level, post-smoothed (a backward sweep): symmetric, and positive definite
// where the coarse solve is.
template <int M, class V>
struct Cycle {
  using S = Sweeps<M, V>;
  const Lower& k;
  const Eigen::SparseMatrix<double>& prolongation;
  const CoarseSolve& coarse_solve;
  Block work, t;
  Eigen::MatrixXd coarse;

  Cycle(const Lower& k_, const Eigen::SparseMatrix<double>& p, const CoarseSolve& c, Eigen::Index rows)
      : k(k_), prolongation(p), coarse_solve(c), work(rows, M), t(rows, M) {}

  void operator()(const Block& r, Block& z) {
    z = r;
    S::forward_sweep(k, z);
    S::strict_upper_product(k, z, work);
    coarse.noalias() = prolongation.transpose() * work;
    z.noalias() -= prolongation * coarse_solve(coarse);
    S::product(k, z, work);
    t = r - work;
    S::backward_sweep(k, t);
    z += t;
  }
};

// One group of M columns solved: the conjugate gradients of the header, each cycle's
// coarse correction through `coarse_solve`.
template <int M, class V>
TwoGridSolve solve_columns(const Lower& k, const Eigen::MatrixXd& f, const Eigen::SparseMatrix<double>& prolongation,
                           const CoarseSolve& coarse_solve, const Eigen::MatrixXd& u0, double tolerance,
                           int max_iterations) {
  using S = Sweeps<M>;
  Cycle<M, V> cycle(k, prolongation, coarse_solve, f.rows());
  TwoGridSolve out;
  Block x = u0;
  S::product(k, x, cycle.work);  // the cycle's work space, free before its first cycle
  Block r = Block(f) - cycle.work;
  const Eigen::RowVectorXd limit = tolerance * f.colwise().norm();
  auto done = [&] { return (r.colwise().norm().array() <= limit.array()).all(); };
  if (done()) {
    out.u = x;
    out.converged = true;
    return out;
  }
  Block z(f.rows(), M);
  cycle(r, z);
  Block p = z;
  Eigen::RowVectorXd rz = column_dots(r, z);
  Block q(f.rows(), M);
  for (out.iterations = 1; out.iterations <= max_iterations; ++out.iterations) {
    S::product(k, p, q);
    const Eigen::RowVectorXd pq = column_dots(p, q);
    const Eigen::VectorXd alpha = (pq.array() > 0.0).select(rz.array() / pq.array(), 0.0).transpose();
    x += p * alpha.asDiagonal();
    r -= q * alpha.asDiagonal();
    if (done()) {
      out.converged = true;
      break;
    }
    cycle(r, z);
    const Eigen::RowVectorXd rz_next = column_dots(r, z);
    const Eigen::VectorXd beta = (rz.array() > 0.0).select(rz_next.array() / rz.array(), 0.0).transpose();
    p = z + p * beta.asDiagonal();
    rz = rz_next;
  }
  out.u = x;
  return out;
}

// The loads in two groups (two cores: the machines measured here), none wider than eight
// columns (the 3D loads with the heat are seven).
constexpr int kGroups = 2;
constexpr int kMaxColumns = 8;

template <int M = 1>
TwoGridSolve solve_group(int columns, const Lower& k, const Eigen::MatrixXd& f,
                         const Eigen::SparseMatrix<double>& prolongation, const CoarseSolve& coarse_solve,
                         const Eigen::MatrixXd& u0, double tolerance, int max_iterations) {
  if constexpr (M < kMaxColumns)
    if (columns != M)
      return solve_group<M + 1>(columns, k, f, prolongation, coarse_solve, u0, tolerance, max_iterations);
  if (!k.values_f.empty()) return solve_columns<M, float>(k, f, prolongation, coarse_solve, u0, tolerance, max_iterations);
  return solve_columns<M, double>(k, f, prolongation, coarse_solve, u0, tolerance, max_iterations);
}

// One cycle on the columns of `r`, M of them.
template <int M = 1>
Eigen::MatrixXd cycle_columns(int columns, const Lower& k, const Eigen::MatrixXd& r,
                              const Eigen::SparseMatrix<double>& prolongation, const CoarseSolve& coarse_solve) {
  if constexpr (M < kMaxColumns)
    if (columns != M) return cycle_columns<M + 1>(columns, k, r, prolongation, coarse_solve);
  Cycle<M, double> cycle(k, prolongation, coarse_solve, r.rows());
  Block z(r.rows(), M);
  cycle(Block(r), z);
  return z;
}

}  // namespace

TwoGridSolve two_grid_solve(const Eigen::SparseMatrix<double>& k_lower, const Eigen::MatrixXd& f,
                            const Eigen::SparseMatrix<double>& prolongation, const CoarseSolve& coarse_solve,
                            const Eigen::MatrixXd& u0, double tolerance, int max_iterations, int threads) {
  Lower k(k_lower);
  k.values_f.assign(k_lower.valuePtr(), k_lower.valuePtr() + k_lower.nonZeros());
  const auto columns = static_cast<int>(f.cols());
  // The groups depend on the loads alone, not on the threads: the answer is the same to
  // the bit on one thread or many (each group stops when all of its loads are there).
  const int groups = std::max({1, std::min(kGroups, columns), (columns + kMaxColumns - 1) / kMaxColumns});
  std::vector<TwoGridSolve> solved(static_cast<std::size_t>(groups));
  std::vector<int> order(static_cast<std::size_t>(groups));
  std::iota(order.begin(), order.end(), 0);
  auto first = [&](int g) { return g * columns / groups; };
  side_by_side(order, std::min(threads, groups), [&](int g) {
    const int begin = first(g), width = first(g + 1) - begin;
    solved[static_cast<std::size_t>(g)] =
        solve_group(width, k, f.middleCols(begin, width), prolongation, coarse_solve,
                    u0.middleCols(begin, width), tolerance, max_iterations);
  });
  TwoGridSolve out;
  out.u.resize(f.rows(), f.cols());
  out.converged = true;
  for (int g = 0; g < groups; ++g) {
    TwoGridSolve& s = solved[static_cast<std::size_t>(g)];
    out.u.middleCols(first(g), first(g + 1) - first(g)) = s.u;
    out.iterations = std::max(out.iterations, s.iterations);
    out.converged = out.converged && s.converged;
  }
  return out;
}

Eigen::MatrixXd two_grid_cycle(const Eigen::SparseMatrix<double>& k_lower, const Eigen::MatrixXd& r,
                               const Eigen::SparseMatrix<double>& prolongation, const CoarseSolve& coarse_solve) {
  const Lower k(k_lower);
  Eigen::MatrixXd z(r.rows(), r.cols());
  for (Eigen::Index begin = 0; begin < r.cols(); begin += kMaxColumns) {
    const auto width = static_cast<int>(std::min<Eigen::Index>(kMaxColumns, r.cols() - begin));
    z.middleCols(begin, width) = cycle_columns(width, k, r.middleCols(begin, width), prolongation, coarse_solve);
  }
  return z;
}

}  // namespace grainmesh
