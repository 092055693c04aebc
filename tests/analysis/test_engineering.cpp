// Engineering constants of a stiffness, 2D and 3D: the isotropic tensor's own constants,
// and the universal anisotropy index of square and cubic tensors against its closed forms.
#include <catch2/catch.hpp>

#include <cmath>

#include "analysis/bounds.hpp"
#include "analysis/engineering.hpp"

using namespace grainmesh;

TEST_CASE("engineering constants of an isotropic phase's tensor are its own, in 2D and 3D", "[analysis][engineering]") {
  const FoamPhase carbide{"WC", 700e9, 0.24};
  const double E = carbide.youngs_modulus, nu = carbide.poisson_ratio, mu = E / (2 * (1 + nu));
  const EngineeringConstants three = engineering_constants(isotropic_stiffness<6>(carbide));
  REQUIRE(three.constants.size() == 3 + 3 + 6);
  for (const char* name : {"E_x", "E_y", "E_z"}) CHECK(three[name] == Approx(E).epsilon(1e-12));
  for (const char* name : {"G_yz", "G_xz", "G_xy"}) CHECK(three[name] == Approx(mu).epsilon(1e-12));
  for (const char* name : {"nu_xy", "nu_yx", "nu_xz", "nu_zx", "nu_yz", "nu_zy"})
    CHECK(three[name] == Approx(nu).epsilon(1e-12));
  CHECK(std::abs(three.universal_anisotropy) < 1e-12);
  CHECK_FALSE(three.normal_anisotropy);
  // Plane strain: E' = E / (1 - nu^2), nu' = nu / (1 - nu) in plane; plane stress: E, nu.
  for (const bool plane_stress : {false, true}) {
    const EngineeringConstants two = engineering_constants(isotropic_stiffness<3>(carbide, plane_stress));
    REQUIRE(two.constants.size() == 2 + 1 + 2);
    CHECK(two["E_x"] == Approx(plane_stress ? E : E / (1 - nu * nu)).epsilon(1e-12));
    CHECK(two["nu_yx"] == Approx(plane_stress ? nu : nu / (1 - nu)).epsilon(1e-12));
    CHECK(two["G_xy"] == Approx(mu).epsilon(1e-12));
    CHECK(std::abs(two.universal_anisotropy) < 1e-12);
    CHECK(*two.shear_anisotropy == Approx(1.0).epsilon(1e-12));
    CHECK(*two.normal_anisotropy == 0.0);
  }
  CHECK_THROWS_AS(three["E_w"], std::out_of_range);
}

TEST_CASE("the universal anisotropy index of square (2D) and cubic (3D) tensors has its closed form",
          "[analysis][engineering]") {
  // Cubic, C11 = 250, C12 = 100, C44 = 100 GPa: Zener's A = 2 C44 / (C11 - C12) = 4/3, and
  // A^U = 6/5 (A + 1/A - 2) = 0.1 exactly; E = (C11 - C12)(C11 + 2 C12) / (C11 + C12),
  // nu = C12 / (C11 + C12), G = C44.
  Stiffness<6> cubic{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) cubic[i][j] = i == j ? 250e9 : 100e9;
    cubic[3 + i][3 + i] = 100e9;
  }
  const EngineeringConstants c = engineering_constants(cubic);
  CHECK(c.universal_anisotropy == Approx(0.1).epsilon(1e-12));
  CHECK(c["E_x"] == Approx(150e9 * 450e9 / 350e9).epsilon(1e-12));
  CHECK(c["nu_xy"] == Approx(100.0 / 350.0).epsilon(1e-12));
  CHECK(c["G_xy"] == Approx(100e9).epsilon(1e-12));
  // Square in 2D, the same entries: K_V = K_R, G_V / G_R = (2 + A + 1/A) / 4 with A = 4/3,
  // so A^U = 2 G_V / G_R - 2 = (A + 1/A - 2) / 2 = 1/24; shear 2 C66 / (C11 - C12) = A.
  const Stiffness<3> square{{{250e9, 100e9, 0}, {100e9, 250e9, 0}, {0, 0, 100e9}}};
  const EngineeringConstants s = engineering_constants(square);
  CHECK(s.universal_anisotropy == Approx(1.0 / 24).epsilon(1e-12));
  CHECK(*s.shear_anisotropy == Approx(4.0 / 3).epsilon(1e-12));
  CHECK(s["E_x"] == Approx(250e9 - 100e9 * 100e9 / 250e9).epsilon(1e-12));
  CHECK(s["nu_xy"] == Approx(100.0 / 250.0).epsilon(1e-12));
  // Anisotropic tensors are never below zero: a rotated square one, and a laminate-like one.
  const Stiffness<3> layered{{{300e9, 80e9, 5e9}, {80e9, 200e9, -3e9}, {5e9, -3e9, 70e9}}};
  CHECK(engineering_constants(layered).universal_anisotropy > 0.0);
}
