#include "analysis/bounds_3d.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/errors.hpp"

namespace grainmesh {

namespace {

struct Moduli {
  double K, mu;  // 3D bulk and shear
};

Moduli moduli(const FoamPhase& p) {
  const double mu = p.youngs_modulus / (2.0 * (1.0 + p.poisson_ratio));
  const double K = p.youngs_modulus / (3.0 * (1.0 - 2.0 * p.poisson_ratio));
  return {K, mu};
}

// Hashin-Shtrikman in 3D for two well-ordered isotropic phases (the stiffer in both K and
// mu); the reference phase `r` gives the upper bound when it is the stiffer.
std::pair<double, double> hashin_shtrikman_3d(const Moduli& r, const Moduli& o, double fr, double fo) {
  const double K = o.K == r.K ? r.K : r.K + fo / (1.0 / (o.K - r.K) + 3.0 * fr / (3.0 * r.K + 4.0 * r.mu));
  const double mu = o.mu == r.mu ? r.mu
                                 : r.mu + fo / (1.0 / (o.mu - r.mu) +
                                                6.0 * fr * (r.K + 2.0 * r.mu) / (5.0 * r.mu * (3.0 * r.K + 4.0 * r.mu)));
  return {K, mu};
}

double largest_entry(const Stiffness6& c) {
  double scale = 0.0;
  for (const auto& row : c)
    for (double v : row) scale = std::max(scale, std::abs(v));
  return scale;
}

}  // namespace

Stiffness6 isotropic_stiffness_3d(const FoamPhase& phase) {
  const Moduli m = moduli(phase);
  const double lambda = m.K - 2.0 * m.mu / 3.0;
  Stiffness6 c{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) c[i][j] = lambda;
    c[i][i] = lambda + 2.0 * m.mu;
    c[3 + i][3 + i] = m.mu;
  }
  return c;
}

Stiffness6 inverse(const Stiffness6& c) {
  std::array<std::array<double, 12>, 6> a{};
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) a[i][j] = c[i][j];
    a[i][6 + i] = 1.0;
  }
  const double scale = largest_entry(c);
  for (int col = 0; col < 6; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 6; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (!(std::abs(a[pivot][col]) > 1e-14 * scale)) throw GeometryError("a singular stiffness");
    std::swap(a[col], a[pivot]);
    const double d = a[col][col];
    for (double& v : a[col]) v /= d;
    for (int r = 0; r < 6; ++r) {
      if (r == col) continue;
      const double f = a[r][col];
      for (int j = 0; j < 12; ++j) a[r][j] -= f * a[col][j];
    }
  }
  Stiffness6 inv{};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) inv[i][j] = a[i][6 + j];
  return inv;
}

bool semidefinite_order(const Stiffness6& lower, const Stiffness6& upper, double rounding) {
  double a[6][6];
  const double scale = std::max(largest_entry(lower), largest_entry(upper));
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) a[i][j] = 0.5 * (upper[i][j] + upper[j][i] - lower[i][j] - lower[j][i]);
  const double tol = rounding * scale;
  // LDL^T without pivoting: a pivot at or below the tolerance is taken as zero, and then
  // its column must vanish too (to the tolerance) for the matrix to stay semidefinite.
  for (int k = 0; k < 6; ++k) {
    const double d = a[k][k];
    if (d < -tol) return false;
    if (d <= tol) {
      for (int i = k + 1; i < 6; ++i)
        if (std::abs(a[i][k]) > std::sqrt(tol * scale)) return false;
      continue;
    }
    for (int i = k + 1; i < 6; ++i)
      for (int j = k + 1; j < 6; ++j) a[i][j] -= a[i][k] * a[k][j] / d;
  }
  return true;
}

TensorBounds3 tensor_bounds_3d(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions) {
  TensorBounds3 b;
  Stiffness6 compliance{};
  for (std::size_t p = 0; p < phases.size(); ++p) {
    const Stiffness6 c = isotropic_stiffness_3d(phases[p]), s = inverse(c);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) {
        b.voigt[i][j] += fractions[p] * c[i][j];
        compliance[i][j] += fractions[p] * s[i][j];
      }
  }
  b.reuss = inverse(compliance);
  if (phases.size() == 2) {
    const Moduli m0 = moduli(phases[0]), m1 = moduli(phases[1]);
    const bool first_stiffer = m0.mu >= m1.mu;
    const Moduli& hard = first_stiffer ? m0 : m1;
    const Moduli& soft = first_stiffer ? m1 : m0;
    const double f_hard = fractions[first_stiffer ? 0 : 1], f_soft = fractions[first_stiffer ? 1 : 0];
    if (hard.K >= soft.K) {
      std::tie(b.bulk_upper, b.shear_upper) = hashin_shtrikman_3d(hard, soft, f_hard, f_soft);
      std::tie(b.bulk_lower, b.shear_lower) = hashin_shtrikman_3d(soft, hard, f_soft, f_hard);
    }
  }
  return b;
}

double bulk_modulus_3d(const Stiffness6& c) {
  return (c[0][0] + c[1][1] + c[2][2] + 2.0 * (c[0][1] + c[0][2] + c[1][2])) / 9.0;
}

double shear_modulus_3d(const Stiffness6& c) {
  return (c[0][0] + c[1][1] + c[2][2] - (c[0][1] + c[0][2] + c[1][2]) + 3.0 * (c[3][3] + c[4][4] + c[5][5])) / 15.0;
}

}  // namespace grainmesh
