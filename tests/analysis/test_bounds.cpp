// Bounds on the effective stiffness, one contract in 2D (N = 3, plane strain and plane
// stress) and 3D (N = 6): the isotropic stiffness and its compliance, Voigt and Reuss
// tensors and Hashin-Shtrikman moduli against exact values (one phase; two phases of equal
// shear modulus, where Hill's exact bulk modulus closes the bounds; the Voigt and Reuss
// means of isotropic phases; the classical 2D and 3D forms of the bounds), and the bounds
// of the thesis' 2D mixed load.
#include <catch2/catch.hpp>

#include <type_traits>

#include "analysis/bounds.hpp"

using namespace grainmesh;

namespace {

const FoamPhase kWC{"WC", 700e9, 0.24, 0.0};
const FoamPhase kCo{"Co", 211e9, 0.31, 0.0};

template <std::size_t N>
constexpr int dims() {
  return N == 3 ? 2 : 3;
}

// A phase's shear and bulk moduli as the bounds have them: in 2D the plane-strain (or
// plane-stress) bulk modulus lambda + mu, in 3D lambda + 2 mu / 3.
double shear(const FoamPhase& p) { return p.youngs_modulus / (2.0 * (1.0 + p.poisson_ratio)); }
double bulk(const FoamPhase& p, int d, bool plane_stress = false) {
  const double E = p.youngs_modulus, nu = p.poisson_ratio;
  if (d == 3) return E / (3.0 * (1.0 - 2.0 * nu));
  return plane_stress ? E / (2.0 * (1.0 - nu)) : E / (2.0 * (1.0 + nu) * (1.0 - 2.0 * nu));
}
// The phase (plane strain in 2D) of bulk modulus K and shear modulus mu.
FoamPhase phase_of(double K, double mu, int d) {
  const double nu = d == 3 ? (3.0 * K - 2.0 * mu) / (2.0 * (3.0 * K + mu)) : 0.5 * (1.0 - mu / K);
  return FoamPhase{"p", 2.0 * mu * (1.0 + nu), nu, 0.0};
}

}  // namespace

using Sizes = std::tuple<std::integral_constant<std::size_t, 3>, std::integral_constant<std::size_t, 6>>;

TEMPLATE_LIST_TEST_CASE("isotropic stiffness: its compliance holds 1/E, -nu/E and 1/mu (3D and plane stress), the "
                        "inverse exact, K and mu its own",
                        "[homogenise]", Sizes) {
  constexpr std::size_t N = TestType::value;
  constexpr int d = dims<N>();
  const bool plane_stress = d == 2;  // the 2D compliance of plane stress is the 3D one's in-plane block
  const Stiffness<N> c = isotropic_stiffness<N>(kWC, plane_stress), s = inverse(c);
  for (int i = 0; i < d; ++i) {
    REQUIRE(s[i][i] == Approx(1.0 / kWC.youngs_modulus).epsilon(1e-12));
    for (int j = 0; j < d; ++j)
      if (j != i) REQUIRE(s[i][j] == Approx(-kWC.poisson_ratio / kWC.youngs_modulus).epsilon(1e-12));
  }
  for (std::size_t k = d; k < N; ++k) REQUIRE(s[k][k] == Approx(1.0 / shear(kWC)).epsilon(1e-12));
  REQUIRE(bulk_modulus(c) == Approx(bulk(kWC, d, plane_stress)).epsilon(1e-12));
  REQUIRE(shear_modulus(c) == Approx(shear(kWC)).epsilon(1e-12));
  // An anisotropic stiffness (the Voigt mean plus a shear coupling) times its inverse.
  Stiffness<N> a = tensor_bounds<N>({kWC, kCo}, {0.7, 0.3}).voigt;
  a[0][N - 1] = a[N - 1][0] = 0.1 * a[N - 1][N - 1];
  const Stiffness<N> b = inverse(a);
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) {
      double sum = 0.0;
      for (std::size_t k = 0; k < N; ++k) sum += a[i][k] * b[k][j];
      REQUIRE(sum == Approx(i == j ? 1.0 : 0.0).margin(1e-12));
    }
  CHECK_THROWS(inverse(Stiffness<N>{}));
}

TEMPLATE_LIST_TEST_CASE("bounds of one phase all equal its own moduli", "[homogenise]", Sizes) {
  constexpr std::size_t N = TestType::value;
  const TensorBounds<N> b = tensor_bounds<N>({kWC, kWC}, {0.4, 0.6});
  const Stiffness<N> c = isotropic_stiffness<N>(kWC);
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) {
      REQUIRE(b.voigt[i][j] == Approx(c[i][j]).margin(1e-9 * c[0][0]));
      REQUIRE(b.reuss[i][j] == Approx(c[i][j]).margin(1e-9 * c[0][0]));
    }
  REQUIRE(*b.bulk_lower == Approx(bulk(kWC, dims<N>())));
  REQUIRE(*b.bulk_upper == Approx(bulk(kWC, dims<N>())));
  REQUIRE(*b.shear_lower == Approx(shear(kWC)));
  REQUIRE(*b.shear_upper == Approx(shear(kWC)));
}

TEMPLATE_LIST_TEST_CASE("Hashin-Shtrikman: equal shear moduli close the bulk bounds on Hill's exact value",
                        "[homogenise]", Sizes) {
  // Two phases of one shear modulus mu: every microstructure has K = [f1 / (K1 + c mu) +
  // f2 / (K2 + c mu)]^-1 - c mu, c = 2 (d - 1) / d: 1 in 2D, 4/3 in 3D (Hill 1963).
  constexpr std::size_t N = TestType::value;
  constexpr int d = dims<N>();
  const double mu = 100e9, K1 = 400e9, K2 = 150e9, f1 = 0.35, f2 = 0.65, c = 2.0 * (d - 1) / d;
  const TensorBounds<N> b = tensor_bounds<N>({phase_of(K1, mu, d), phase_of(K2, mu, d)}, {f1, f2});
  const double hill = 1.0 / (f1 / (K1 + c * mu) + f2 / (K2 + c * mu)) - c * mu;
  REQUIRE(*b.bulk_lower == Approx(hill).epsilon(1e-12));
  REQUIRE(*b.bulk_upper == Approx(hill).epsilon(1e-12));
  REQUIRE(*b.shear_lower == Approx(mu).epsilon(1e-12));
  REQUIRE(*b.shear_upper == Approx(mu).epsilon(1e-12));
}

TEST_CASE("Hashin-Shtrikman in d dimensions is the classical 2D and 3D bounds", "[homogenise]") {
  // The forms as published for each dimension (Hashin 1965 in 2D; Hashin and Shtrikman
  // 1963 in 3D), the stiffer phase 1 the reference of the upper bound.
  const double f1 = 0.85, f2 = 0.15;
  {
    const double K1 = bulk(kWC, 2), G1 = shear(kWC), K2 = bulk(kCo, 2), G2 = shear(kCo);
    const TensorBounds<3> b = tensor_bounds<3>({kWC, kCo}, {f1, f2});
    CHECK(*b.bulk_upper == Approx(K1 + f2 / (1 / (K2 - K1) + f1 / (K1 + G1))).epsilon(1e-12));
    CHECK(*b.shear_upper == Approx(G1 + f2 / (1 / (G2 - G1) + f1 * (K1 + 2 * G1) / (2 * G1 * (K1 + G1)))).epsilon(1e-12));
    CHECK(*b.bulk_lower == Approx(K2 + f1 / (1 / (K1 - K2) + f2 / (K2 + G2))).epsilon(1e-12));
    CHECK(*b.shear_lower == Approx(G2 + f1 / (1 / (G1 - G2) + f2 * (K2 + 2 * G2) / (2 * G2 * (K2 + G2)))).epsilon(1e-12));
  }
  {
    const double K1 = bulk(kWC, 3), G1 = shear(kWC), K2 = bulk(kCo, 3), G2 = shear(kCo);
    const TensorBounds<6> b = tensor_bounds<6>({kWC, kCo}, {f1, f2});
    CHECK(*b.bulk_upper == Approx(K1 + f2 / (1 / (K2 - K1) + 3 * f1 / (3 * K1 + 4 * G1))).epsilon(1e-12));
    CHECK(*b.shear_upper ==
          Approx(G1 + f2 / (1 / (G2 - G1) + 6 * f1 * (K1 + 2 * G1) / (5 * G1 * (3 * K1 + 4 * G1)))).epsilon(1e-12));
    CHECK(*b.bulk_lower == Approx(K2 + f1 / (1 / (K1 - K2) + 3 * f2 / (3 * K2 + 4 * G2))).epsilon(1e-12));
    CHECK(*b.shear_lower ==
          Approx(G2 + f1 / (1 / (G1 - G2) + 6 * f2 * (K2 + 2 * G2) / (5 * G2 * (3 * K2 + 4 * G2)))).epsilon(1e-12));
  }
}

TEMPLATE_LIST_TEST_CASE("bounds of WC-Co: Reuss below Hashin-Shtrikman below Voigt, the means exact", "[homogenise]",
                        Sizes) {
  constexpr std::size_t N = TestType::value;
  constexpr int d = dims<N>();
  const double f = 0.15;
  const TensorBounds<N> b = tensor_bounds<N>({kWC, kCo}, {1.0 - f, f});
  // Voigt and Reuss means of isotropic phases are isotropic with the phases' mean moduli
  // and mean compliances.
  REQUIRE(bulk_modulus(b.voigt) == Approx((1.0 - f) * bulk(kWC, d) + f * bulk(kCo, d)).epsilon(1e-12));
  REQUIRE(shear_modulus(b.voigt) == Approx((1.0 - f) * shear(kWC) + f * shear(kCo)).epsilon(1e-12));
  REQUIRE(bulk_modulus(b.reuss) == Approx(1.0 / ((1.0 - f) / bulk(kWC, d) + f / bulk(kCo, d))).epsilon(1e-12));
  REQUIRE(shear_modulus(b.reuss) == Approx(1.0 / ((1.0 - f) / shear(kWC) + f / shear(kCo))).epsilon(1e-12));
  REQUIRE(bulk_modulus(b.reuss) < *b.bulk_lower);
  REQUIRE(*b.bulk_lower < *b.bulk_upper);
  REQUIRE(*b.bulk_upper < bulk_modulus(b.voigt));
  REQUIRE(shear_modulus(b.reuss) < *b.shear_lower);
  REQUIRE(*b.shear_lower < *b.shear_upper);
  REQUIRE(*b.shear_upper < shear_modulus(b.voigt));
  REQUIRE(semidefinite_order(b.reuss, b.voigt));
  REQUIRE_FALSE(semidefinite_order(b.voigt, b.reuss));
  REQUIRE(semidefinite_order(b.voigt, b.voigt));
}

TEST_CASE("elastic bounds of the 2D mixed load: ordered, and equal for one material", "[homogenise]") {
  const std::vector<FoamPhase> one{{"a", 200e9, 0.3}, {"b", 200e9, 0.3}};
  const ElasticBounds same = elastic_bounds(one, {0.4, 0.6}, false);
  const double M = 200e9 * 0.7 / (1.3 * 0.4);
  CHECK(same.voigt == Approx(M));
  CHECK(same.reuss == Approx(M));
  CHECK(*same.hs_lower == Approx(M));
  CHECK(*same.hs_upper == Approx(M));

  const std::vector<FoamPhase> two{{"hard", 800e9, 0.1}, {"soft", 300e9, 0.1}};
  for (double f : {0.1, 0.5, 0.9}) {
    const ElasticBounds b = elastic_bounds(two, {1 - f, f}, false);
    CHECK(b.reuss < *b.hs_lower);
    CHECK(*b.hs_lower < *b.hs_upper);
    CHECK(*b.hs_upper < b.voigt);
  }
  // Voigt is the plain average of M; with equal nu, Reuss is the harmonic mean of M.
  const ElasticBounds half = elastic_bounds(two, {0.5, 0.5}, false);
  const double M1 = 800e9 * 0.9 / (1.1 * 0.8), M2 = 300e9 * 0.9 / (1.1 * 0.8);
  CHECK(half.voigt == Approx(0.5 * (M1 + M2)));
  CHECK(half.reuss == Approx(2.0 / (1 / M1 + 1 / M2)));
}
