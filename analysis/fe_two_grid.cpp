#include "analysis/fe_two_grid.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

namespace grainmesh {

namespace {

// The sweeps' and products' loops run ten thousand times a solve: the sanitizer build
// leaves them uninstrumented (a tenfold slower make test otherwise), their indices are the
// matrix's own, and the tests hold the result to the factorised solve's.
#define GM_HOT_LOOP __attribute__((no_sanitize("address", "undefined")))

// Columns stored row by row: a node's loads side by side for the sweeps.
using Block = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The symmetric matrix from its lower triangle, as raw column-major arrays.
struct Lower {
  const int* outer;
  const int* inner;
  const double* value;
  int n;

  explicit Lower(const Eigen::SparseMatrix<double>& k)
      : outer(k.outerIndexPtr()), inner(k.innerIndexPtr()), value(k.valuePtr()), n(static_cast<int>(k.outerSize())) {}
};

// y = K x.
GM_HOT_LOOP void product(const Lower& k, const Block& x, Block& y) {
  const auto m = x.cols();
  y.setZero();
  for (int j = 0; j < k.n; ++j) {
    const double* xj = x.data() + static_cast<std::ptrdiff_t>(j) * m;
    double* yj = y.data() + static_cast<std::ptrdiff_t>(j) * m;
    for (int p = k.outer[j]; p < k.outer[j + 1]; ++p) {
      const int i = k.inner[p];
      const double v = k.value[p];
      const double* xi = x.data() + static_cast<std::ptrdiff_t>(i) * m;
      double* yi = y.data() + static_cast<std::ptrdiff_t>(i) * m;
      for (Eigen::Index c = 0; c < m; ++c) yj[c] += v * xi[c];
      if (i != j)
        for (Eigen::Index c = 0; c < m; ++c) yi[c] += v * xj[c];
    }
  }
}

// y = L^T x, L the strict lower triangle: after a forward sweep z = (D + L)^-1 r, the
// residual r - K z is -L^T z at half a product's cost.
GM_HOT_LOOP void strict_upper_product(const Lower& k, const Block& x, Block& y) {
  const auto m = x.cols();
  for (int j = 0; j < k.n; ++j) {
    double* yj = y.data() + static_cast<std::ptrdiff_t>(j) * m;
    for (Eigen::Index c = 0; c < m; ++c) yj[c] = 0.0;
    for (int p = k.outer[j] + 1; p < k.outer[j + 1]; ++p) {
      const double* xi = x.data() + static_cast<std::ptrdiff_t>(k.inner[p]) * m;
      for (Eigen::Index c = 0; c < m; ++c) yj[c] += k.value[p] * xi[c];
    }
  }
}

// x = (D + L)^-1 b: the forward Gauss–Seidel sweep from zero, column by column.
GM_HOT_LOOP void forward_sweep(const Lower& k, Block& x) {
  const auto m = x.cols();
  for (int j = 0; j < k.n; ++j) {
    double* xj = x.data() + static_cast<std::ptrdiff_t>(j) * m;
    const int d = k.outer[j];  // the diagonal, first in its column
    for (Eigen::Index c = 0; c < m; ++c) xj[c] /= k.value[d];
    for (int p = d + 1; p < k.outer[j + 1]; ++p) {
      double* xi = x.data() + static_cast<std::ptrdiff_t>(k.inner[p]) * m;
      for (Eigen::Index c = 0; c < m; ++c) xi[c] -= k.value[p] * xj[c];
    }
  }
}

// x = (D + L^T)^-1 b: the backward sweep, its transpose.
GM_HOT_LOOP void backward_sweep(const Lower& k, Block& x) {
  const auto m = x.cols();
  for (int j = k.n - 1; j >= 0; --j) {
    double* xj = x.data() + static_cast<std::ptrdiff_t>(j) * m;
    const int d = k.outer[j];
    for (int p = d + 1; p < k.outer[j + 1]; ++p) {
      const double* xi = x.data() + static_cast<std::ptrdiff_t>(k.inner[p]) * m;
      for (Eigen::Index c = 0; c < m; ++c) xj[c] -= k.value[p] * xi[c];
    }
    for (Eigen::Index c = 0; c < m; ++c) xj[c] /= k.value[d];
  }
}

// Each column's dot product of a and b.
Eigen::RowVectorXd column_dots(const Block& a, const Block& b) { return a.cwiseProduct(b).colwise().sum(); }

}  // namespace

TwoGridSolve two_grid_solve(const Eigen::SparseMatrix<double>& k_lower, const Eigen::MatrixXd& f,
                            const Eigen::SparseMatrix<double>& prolongation,
                            const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& coarse_solve,
                            const Eigen::MatrixXd& u0, double tolerance, int max_iterations) {
  const Lower k(k_lower);
  Block work(f.rows(), f.cols()), t(f.rows(), f.cols());
  Eigen::MatrixXd coarse;
  // z = the cycle on r: pre-smoothed, corrected on the coarse level, post-smoothed.
  auto cycle = [&](const Block& r, Block& z) {
    z = r;
    forward_sweep(k, z);
    strict_upper_product(k, z, work);
    coarse.noalias() = prolongation.transpose() * work;
    z.noalias() -= prolongation * coarse_solve(coarse);
    product(k, z, work);
    t = r - work;
    backward_sweep(k, t);
    z += t;
  };
  TwoGridSolve out;
  Block x = u0;
  product(k, x, work);
  Block r = Block(f) - work;
  const Eigen::RowVectorXd limit = tolerance * f.colwise().norm();
  auto done = [&] { return (r.colwise().norm().array() <= limit.array()).all(); };
  if (done()) {
    out.u = x;
    out.converged = true;
    return out;
  }
  Block z(f.rows(), f.cols());
  cycle(r, z);
  Block p = z;
  Eigen::RowVectorXd rz = column_dots(r, z);
  Block q(f.rows(), f.cols());
  for (out.iterations = 1; out.iterations <= max_iterations; ++out.iterations) {
    product(k, p, q);
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

}  // namespace grainmesh
