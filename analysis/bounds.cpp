#include "analysis/bounds.hpp"

#include <tuple>
#include <utility>

namespace grainmesh {

namespace {

// An isotropic phase's moduli in d dimensions: Lame's (2D: plane strain's or plane
// stress's), and the bulk modulus lambda + 2 mu / d.
struct Moduli {
  double lambda, mu, K;
};
Moduli moduli(const FoamPhase& p, int d, bool plane_stress) {
  const Lame l = lame(p, d == 2 && plane_stress);
  return {l.lambda, l.mu, l.lambda + 2.0 * l.mu / d};
}

// Hashin-Shtrikman's (K, mu) with reference phase r (bounds.hpp).
std::pair<double, double> hashin_shtrikman(const Moduli& r, const Moduli& o, double fr, double fo, int d) {
  const double K = o.K == r.K ? r.K : r.K + fo / (1.0 / (o.K - r.K) + fr / (r.K + 2.0 * (d - 1) * r.mu / d));
  const double H = r.mu * (d * r.K / 2.0 + (d + 1.0) * (d - 2.0) * r.mu / d) / (r.K + 2.0 * r.mu);
  const double mu = o.mu == r.mu ? r.mu : r.mu + fo / (1.0 / (o.mu - r.mu) + fr / (r.mu + H));
  return {K, mu};
}

}  // namespace

template <std::size_t N>
Stiffness<N> isotropic_stiffness(const FoamPhase& phase, bool plane_stress) {
  constexpr int d = static_cast<int>(voigt_dimensions<N>());
  const Moduli m = moduli(phase, d, plane_stress);
  Stiffness<N> c{};
  for (int i = 0; i < d; ++i) {
    for (int j = 0; j < d; ++j) c[i][j] = m.lambda;
    c[i][i] = m.lambda + 2.0 * m.mu;
  }
  for (std::size_t k = d; k < N; ++k) c[k][k] = m.mu;
  return c;
}

template <std::size_t N>
TensorBounds<N> tensor_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                              bool plane_stress) {
  constexpr int d = static_cast<int>(voigt_dimensions<N>());
  TensorBounds<N> b;
  Stiffness<N> compliance{};
  for (std::size_t p = 0; p < phases.size(); ++p) {
    const Stiffness<N> c = isotropic_stiffness<N>(phases[p], plane_stress), s = inverse(c);
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j) {
        b.voigt[i][j] += fractions[p] * c[i][j];
        compliance[i][j] += fractions[p] * s[i][j];
      }
  }
  b.reuss = inverse(compliance);
  if (phases.size() == 2) {
    const Moduli m0 = moduli(phases[0], d, plane_stress), m1 = moduli(phases[1], d, plane_stress);
    const bool first_stiffer = m0.mu >= m1.mu;
    const Moduli& hard = first_stiffer ? m0 : m1;
    const Moduli& soft = first_stiffer ? m1 : m0;
    const double f_hard = fractions[first_stiffer ? 0 : 1], f_soft = fractions[first_stiffer ? 1 : 0];
    if (hard.K >= soft.K) {
      std::tie(b.bulk_upper, b.shear_upper) = hashin_shtrikman(hard, soft, f_hard, f_soft, d);
      std::tie(b.bulk_lower, b.shear_lower) = hashin_shtrikman(soft, hard, f_soft, f_hard, d);
    }
  }
  return b;
}

template Stiffness<3> isotropic_stiffness<3>(const FoamPhase&, bool);
template Stiffness<6> isotropic_stiffness<6>(const FoamPhase&, bool);
template TensorBounds<3> tensor_bounds<3>(const std::vector<FoamPhase>&, const std::vector<double>&, bool);
template TensorBounds<6> tensor_bounds<6>(const std::vector<FoamPhase>&, const std::vector<double>&, bool);

ElasticBounds elastic_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                             bool plane_stress) {
  // Under the thesis' load (the mean eps_yy zero) the uniform-strain bound is <C11>, the
  // uniform-stress one 1 / (S11 - S12 S21 / S22) of the mean compliance S.
  const TensorBounds<3> t = tensor_bounds<3>(phases, fractions, plane_stress);
  ElasticBounds b;
  b.voigt = t.voigt[0][0];
  const Stiffness<3> s = inverse(t.reuss);
  b.reuss = 1.0 / (s[0][0] - s[0][1] * s[1][0] / s[1][1]);
  if (t.bulk_upper) {
    // Hashin-Shtrikman: the isotropic stiffness's C11 = K + mu at each bound.
    b.hs_upper = *t.bulk_upper + *t.shear_upper;
    b.hs_lower = *t.bulk_lower + *t.shear_lower;
  }
  return b;
}

template <std::size_t N>
ElasticBounds mixed_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                           bool plane_stress) {
  if constexpr (N == 3) return elastic_bounds(phases, fractions, plane_stress);
  const TensorBounds<N> t = tensor_bounds<N>(phases, fractions);
  return {.voigt = t.voigt[0][0], .reuss = t.reuss[0][0], .hs_lower = {}, .hs_upper = {}};
}

template ElasticBounds mixed_bounds<3>(const std::vector<FoamPhase>&, const std::vector<double>&, bool);
template ElasticBounds mixed_bounds<6>(const std::vector<FoamPhase>&, const std::vector<double>&, bool);

}  // namespace grainmesh
