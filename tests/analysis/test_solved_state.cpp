// The periodic homogenisation's bookkeeping, the same in 2D and 3D, on synthetic solved
// cases of a known anisotropic stiffness C (no solver): the load cases' strains, the
// stiffness assembled from the stresses they give, the thermal residual's expansion and
// free state, and the superposition of states.
#include <catch2/catch.hpp>

#include <cmath>

#include "analysis/solved_state.hpp"
#include "analysis/synthetic_cases.hpp"
#include "analysis/thermal.hpp"

using namespace grainmesh;
using namespace grainmesh::test;

namespace {

template <std::size_t N>
void check_bookkeeping() {
  const Stiffness<N> c = anisotropic_stiffness<N>();
  const double e = 1e-3, alpha = 5e-6, delta_T = -800.0, held = 0.7 * alpha * delta_T;
  const PeriodicHomogenised<N> h = synthetic_cases<N>(c, e, alpha, delta_T, held);
  REQUIRE(h.cases.size() == N + 1);
  for (std::size_t k = 0; k < N; ++k) {
    // Named by its component, e in a normal one, e / 2 (tensor) in a shear one.
    CHECK(h.cases[k].load.name == voigt_names<N>()[k]);
    for (std::size_t j = 0; j < N; ++j)
      CHECK(h.cases[k].load.strain[j] == (j != k ? 0.0 : k < voigt_dimensions<N>() ? e : 0.5 * e));
  }
  CHECK(h.cases[N].load.name == "thermal");
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) {
      CHECK(h.stiffness[i][j] == Approx(c[i][j]).epsilon(1e-12));
      CHECK(h.volume_average_stiffness[i][j] == Approx(c[i][j]).epsilon(1e-12));
    }
  // Free on average, the cell takes its own free expansion: alpha in every normal
  // direction, no shear; the free state's strain is alpha delta_T, the loaded one's
  // e more in xx.
  const ThermalResidual<N> r = thermal_residual(h);
  CHECK(r.delta_T == delta_T);
  for (std::size_t k = 0; k < N; ++k) {
    const double expected = k < voigt_dimensions<N>() ? alpha : 0.0;
    CHECK(r.expansion[k] == Approx(expected).margin(1e-12 * alpha));
    CHECK(r.free.fields.displacement.values[k] == Approx(expected * delta_T).margin(1e-12 * e));
    CHECK(r.loaded.fields.displacement.values[k] == Approx(expected * delta_T + (k == 0 ? e : 0.0)).margin(1e-12 * e));
    // Its mean stress is zero: the state superposed to carry none.
    CHECK(std::abs(r.free.fields.stress.values[k]) < 1e-9 * c[0][0] * e);
  }
  // A case with no thermal case is refused.
  PeriodicHomogenised<N> mechanical = h;
  mechanical.cases.pop_back();
  CHECK_THROWS(thermal_residual(mechanical));
}

}  // namespace

TEST_CASE("periodic bookkeeping in 2D: load cases, the assembled stiffness, the thermal residual", "[analysis][thermal]") {
  check_bookkeeping<3>();
}

TEST_CASE("periodic bookkeeping in 3D: load cases, the assembled stiffness, the thermal residual", "[analysis][thermal]") {
  check_bookkeeping<6>();
}
