// Voigt-notation stiffnesses, one set of operations for 2D (N = 3) and 3D (N = 6): the
// symmetry error and symmetric part, and the semidefinite order the bounds are judged by.
#include <catch2/catch.hpp>

#include <type_traits>

#include "analysis/voigt.hpp"

using namespace grainmesh;

using Sizes = std::tuple<std::integral_constant<std::size_t, 3>, std::integral_constant<std::size_t, 6>>;

namespace {

// A cubic (3D) or square-symmetric (2D) stiffness: C11 = 250, C12 = 100, shears 100 GPa.
template <std::size_t N>
Stiffness<N> cubic() {
  constexpr std::size_t d = N == 3 ? 2 : 3;
  Stiffness<N> c{};
  for (std::size_t i = 0; i < d; ++i)
    for (std::size_t j = 0; j < d; ++j) c[i][j] = i == j ? 250e9 : 100e9;
  for (std::size_t k = d; k < N; ++k) c[k][k] = 100e9;
  return c;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("symmetry error: one pair off by 1 % of the largest entry, its symmetric part between",
                        "[homogenise]", Sizes) {
  constexpr std::size_t N = TestType::value;
  Stiffness<N> skew = cubic<N>();
  skew[0][1] += 2.5e9;
  CHECK(symmetry_error(skew) == Approx(0.01).epsilon(1e-12));
  CHECK(symmetric_part(skew)[0][1] == Approx(101.25e9).epsilon(1e-12));
  CHECK(symmetric_part(skew)[1][0] == symmetric_part(skew)[0][1]);
  CHECK(symmetry_error(symmetric_part(skew)) == 0.0);
  // A shear-normal coupling counts as much as a normal pair.
  Stiffness<N> coupled = cubic<N>();
  coupled[0][N - 1] = 5e9;
  CHECK(symmetry_error(coupled) == Approx(0.02).epsilon(1e-12));
}

TEMPLATE_LIST_TEST_CASE("semidefinite order: a stiffness above another by a semidefinite difference, within rounding",
                        "[homogenise]", Sizes) {
  constexpr std::size_t N = TestType::value;
  const Stiffness<N> c = cubic<N>();
  Stiffness<N> up = c;
  for (std::size_t i = 0; i < N; ++i) up[i][i] += 1e9;  // positive definite difference
  CHECK(semidefinite_order(c, up));
  CHECK_FALSE(semidefinite_order(up, c));
  // A rank-one difference (semidefinite, not definite): in order both ways only within rounding.
  Stiffness<N> rank_one = c;
  rank_one[0][0] += 1e9;
  CHECK(semidefinite_order(c, rank_one));
  CHECK_FALSE(semidefinite_order(rank_one, c));
  // Indefinite: one normal up, another down.
  Stiffness<N> mixed = c;
  mixed[0][0] += 1e9;
  mixed[1][1] -= 1e9;
  CHECK_FALSE(semidefinite_order(c, mixed));
  CHECK_FALSE(semidefinite_order(mixed, c));
  // Below the rounding (1e-6 of the largest entry), a difference is no difference.
  Stiffness<N> near = c;
  near[1][1] -= 1e-7 * 250e9;
  CHECK(semidefinite_order(c, near));
}
