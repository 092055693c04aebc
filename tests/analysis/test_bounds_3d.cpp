// 3D bounds on the effective stiffness: the isotropic stiffness and its inverse, Voigt and
// Reuss tensors and Hashin-Shtrikman moduli against exact values (one phase; two phases
// of equal shear modulus, where Hill's exact bulk modulus closes the bounds; the Voigt and
// Reuss means of isotropic phases).
#include <catch2/catch.hpp>

#include "analysis/bounds_3d.hpp"

using namespace grainmesh;

namespace {

const FoamPhase kWC{"WC", 700e9, 0.24, 0.0};
const FoamPhase kCo{"Co", 211e9, 0.31, 0.0};

double bulk(const FoamPhase& p) { return p.youngs_modulus / (3.0 * (1.0 - 2.0 * p.poisson_ratio)); }
double shear(const FoamPhase& p) { return p.youngs_modulus / (2.0 * (1.0 + p.poisson_ratio)); }

}  // namespace

TEST_CASE("3D isotropic stiffness: its compliance holds 1/E, -nu/E and 1/mu, and the inverse is exact", "[homogenise]") {
  const Stiffness6 c = isotropic_stiffness_3d(kWC), s = inverse(c);
  for (int i = 0; i < 3; ++i) {
    REQUIRE(s[i][i] == Approx(1.0 / kWC.youngs_modulus).epsilon(1e-12));
    for (int j = 0; j < 3; ++j)
      if (j != i) REQUIRE(s[i][j] == Approx(-kWC.poisson_ratio / kWC.youngs_modulus).epsilon(1e-12));
    REQUIRE(s[3 + i][3 + i] == Approx(1.0 / shear(kWC)).epsilon(1e-12));
  }
  REQUIRE(bulk_modulus_3d(c) == Approx(bulk(kWC)).epsilon(1e-12));
  REQUIRE(shear_modulus_3d(c) == Approx(shear(kWC)).epsilon(1e-12));
  // An anisotropic stiffness (the Voigt mean plus a shear coupling) times its inverse.
  Stiffness6 a = tensor_bounds_3d({kWC, kCo}, {0.7, 0.3}).voigt;
  a[0][5] = a[5][0] = 0.1 * a[5][5];
  const Stiffness6 b = inverse(a);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      double sum = 0.0;
      for (int k = 0; k < 6; ++k) sum += a[i][k] * b[k][j];
      REQUIRE(sum == Approx(i == j ? 1.0 : 0.0).margin(1e-12));
    }
  Stiffness6 singular{};
  CHECK_THROWS(inverse(singular));
}

TEST_CASE("3D bounds of one phase all equal its own moduli", "[homogenise]") {
  const TensorBounds3 b = tensor_bounds_3d({kWC, kWC}, {0.4, 0.6});
  const Stiffness6 c = isotropic_stiffness_3d(kWC);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      REQUIRE(b.voigt[i][j] == Approx(c[i][j]).margin(1e-9 * c[0][0]));
      REQUIRE(b.reuss[i][j] == Approx(c[i][j]).margin(1e-9 * c[0][0]));
    }
  REQUIRE(*b.bulk_lower == Approx(bulk(kWC)));
  REQUIRE(*b.bulk_upper == Approx(bulk(kWC)));
  REQUIRE(*b.shear_lower == Approx(shear(kWC)));
  REQUIRE(*b.shear_upper == Approx(shear(kWC)));
}

TEST_CASE("3D Hashin-Shtrikman: equal shear moduli close the bulk bounds on Hill's exact value", "[homogenise]") {
  // Two phases of one shear modulus mu: every microstructure has K = [f1 / (K1 + 4 mu / 3)
  // + f2 / (K2 + 4 mu / 3)]^-1 - 4 mu / 3 (Hill 1963).
  const double mu = 100e9, K1 = 400e9, K2 = 150e9, f1 = 0.35, f2 = 0.65;
  auto phase = [&](double K) {  // E and nu of K and mu
    const double E = 9.0 * K * mu / (3.0 * K + mu);
    return FoamPhase{"p", E, (3.0 * K - 2.0 * mu) / (2.0 * (3.0 * K + mu)), 0.0};
  };
  const TensorBounds3 b = tensor_bounds_3d({phase(K1), phase(K2)}, {f1, f2});
  const double hill = 1.0 / (f1 / (K1 + 4.0 * mu / 3.0) + f2 / (K2 + 4.0 * mu / 3.0)) - 4.0 * mu / 3.0;
  REQUIRE(*b.bulk_lower == Approx(hill).epsilon(1e-12));
  REQUIRE(*b.bulk_upper == Approx(hill).epsilon(1e-12));
  REQUIRE(*b.shear_lower == Approx(mu).epsilon(1e-12));
  REQUIRE(*b.shear_upper == Approx(mu).epsilon(1e-12));
}

TEST_CASE("3D bounds of WC-Co: Reuss below Hashin-Shtrikman below Voigt, the means exact", "[homogenise]") {
  const double f = 0.15;
  const TensorBounds3 b = tensor_bounds_3d({kWC, kCo}, {1.0 - f, f});
  // Voigt and Reuss means of isotropic phases are isotropic with the phases' mean moduli
  // and mean compliances.
  REQUIRE(bulk_modulus_3d(b.voigt) == Approx((1.0 - f) * bulk(kWC) + f * bulk(kCo)).epsilon(1e-12));
  REQUIRE(shear_modulus_3d(b.voigt) == Approx((1.0 - f) * shear(kWC) + f * shear(kCo)).epsilon(1e-12));
  REQUIRE(bulk_modulus_3d(b.reuss) == Approx(1.0 / ((1.0 - f) / bulk(kWC) + f / bulk(kCo))).epsilon(1e-12));
  REQUIRE(shear_modulus_3d(b.reuss) == Approx(1.0 / ((1.0 - f) / shear(kWC) + f / shear(kCo))).epsilon(1e-12));
  REQUIRE(bulk_modulus_3d(b.reuss) < *b.bulk_lower);
  REQUIRE(*b.bulk_lower < *b.bulk_upper);
  REQUIRE(*b.bulk_upper < bulk_modulus_3d(b.voigt));
  REQUIRE(shear_modulus_3d(b.reuss) < *b.shear_lower);
  REQUIRE(*b.shear_lower < *b.shear_upper);
  REQUIRE(*b.shear_upper < shear_modulus_3d(b.voigt));
  REQUIRE(semidefinite_order(b.reuss, b.voigt));
  REQUIRE_FALSE(semidefinite_order(b.voigt, b.reuss));
  REQUIRE(semidefinite_order(b.voigt, b.voigt));
}
