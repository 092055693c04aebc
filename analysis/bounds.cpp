#include "analysis/bounds.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace grainmesh {

namespace {

// In-plane moduli (plane stress: the reduced lambda).
struct Moduli {
  double lambda, mu;
  double M() const { return lambda + 2 * mu; }
  double K() const { return lambda + mu; }  // 2D bulk
};

Moduli moduli(const FoamPhase& p, bool plane_stress) {
  const Lame l = lame(p, plane_stress);
  return {l.lambda, l.mu};
}

// Hashin-Shtrikman in 2D for two well-ordered isotropic phases (the stiffer in both K
// and mu); the reference phase `r` gives the upper bound when it is the stiffer.
std::pair<double, double> hashin_shtrikman(const Moduli& r, const Moduli& o, double fr, double fo) {
  const double K = o.K() == r.K() ? r.K() : r.K() + fo / (1 / (o.K() - r.K()) + fr / (r.K() + r.mu));
  const double mu = o.mu == r.mu ? r.mu
                                 : r.mu + fo / (1 / (o.mu - r.mu) + fr * (r.K() + 2 * r.mu) / (2 * r.mu * (r.K() + r.mu)));
  return {K, mu};
}

}  // namespace

Stiffness isotropic_stiffness(const FoamPhase& phase, bool plane_stress) {
  const Moduli m = moduli(phase, plane_stress);
  return {{{m.M(), m.lambda, 0.0}, {m.lambda, m.M(), 0.0}, {0.0, 0.0, m.mu}}};
}

Stiffness inverse(const Stiffness& c) {
  const double det = c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) - c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0]) +
                     c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0]);
  double scale = 0.0;
  for (const auto& row : c)
    for (double v : row) scale = std::max(scale, std::abs(v));
  if (!(std::abs(det) > 1e-14 * scale * scale * scale)) throw GeometryError("a singular stiffness");
  Stiffness inv{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      inv[i][j] = (c[i1][j1] * c[i2][j2] - c[i1][j2] * c[i2][j1]) / det;
    }
  return inv;
}

bool semidefinite_order(const Stiffness& lower, const Stiffness& upper, double rounding) {
  // Sylvester for semidefinite: every principal minor of the symmetric difference >= 0,
  // each to rounding.
  double a[3][3], scale = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      a[i][j] = 0.5 * (upper[i][j] + upper[j][i] - lower[i][j] - lower[j][i]);
      scale = std::max({scale, std::abs(upper[i][j]), std::abs(lower[i][j])});
    }
  const double tol = rounding * scale;
  for (int i = 0; i < 3; ++i)
    if (a[i][i] < -tol) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (a[i][i] * a[j][j] - a[i][j] * a[j][i] < -tol * scale) return false;
  const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                     a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  return det >= -tol * scale * scale;
}

TensorBounds tensor_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                           bool plane_stress) {
  TensorBounds b;
  Stiffness compliance{};
  for (std::size_t p = 0; p < phases.size(); ++p) {
    const Stiffness c = isotropic_stiffness(phases[p], plane_stress), s = inverse(c);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        b.voigt[i][j] += fractions[p] * c[i][j];
        compliance[i][j] += fractions[p] * s[i][j];
      }
  }
  b.reuss = inverse(compliance);
  if (phases.size() == 2) {
    const Moduli m0 = moduli(phases[0], plane_stress), m1 = moduli(phases[1], plane_stress);
    const bool first_stiffer = m0.mu >= m1.mu;
    const Moduli& hard = first_stiffer ? m0 : m1;
    const Moduli& soft = first_stiffer ? m1 : m0;
    const double f_hard = fractions[first_stiffer ? 0 : 1], f_soft = fractions[first_stiffer ? 1 : 0];
    if (hard.K() >= soft.K()) {
      std::tie(b.bulk_upper, b.shear_upper) = hashin_shtrikman(hard, soft, f_hard, f_soft);
      std::tie(b.bulk_lower, b.shear_lower) = hashin_shtrikman(soft, hard, f_soft, f_hard);
    }
  }
  return b;
}

double bulk_modulus(const Stiffness& c) { return 0.25 * (c[0][0] + c[1][1] + c[0][1] + c[1][0]); }

double shear_modulus(const Stiffness& c) {
  return 0.5 * c[2][2] + 0.125 * (c[0][0] + c[1][1] - c[0][1] - c[1][0]);
}

ElasticBounds elastic_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                             bool plane_stress) {
  // Under the thesis' load (the mean eps_yy zero) the uniform-strain bound is <C11>, the
  // uniform-stress one 1 / (S11 - S12 S21 / S22) of the mean compliance S.
  const TensorBounds t = tensor_bounds(phases, fractions, plane_stress);
  ElasticBounds b;
  b.voigt = t.voigt[0][0];
  const Stiffness s = inverse(t.reuss);
  b.reuss = 1.0 / (s[0][0] - s[0][1] * s[1][0] / s[1][1]);
  if (t.bulk_upper) {
    // Hashin-Shtrikman: the isotropic stiffness's C11 = K + mu at each bound.
    b.hs_upper = *t.bulk_upper + *t.shear_upper;
    b.hs_lower = *t.bulk_lower + *t.shear_lower;
  }
  return b;
}

}  // namespace grainmesh
