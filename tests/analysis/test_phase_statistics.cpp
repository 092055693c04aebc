// Area-weighted distributions and the stress measures, against values worked by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "analysis/phase_statistics.hpp"
#include "analysis/stress_measures.hpp"

using namespace grainmesh;

TEST_CASE("area-weighted distributions: mean, spread and percentiles by area", "[analysis][statistics]") {
  // Values 1, 2, 3, 10 on areas 0.5, 0.3, 0.195, 0.005: half the area at 1, 80 % at or
  // below 2, 99.5 % at or below 3, the largest 10.
  const Distribution d = distribution({10, 2, 1, 3}, {0.005, 0.3, 0.5, 0.195});
  const double mean = 0.5 * 1 + 0.3 * 2 + 0.195 * 3 + 0.005 * 10;
  CHECK(d.mean == Approx(mean).epsilon(1e-14));
  const double variance = 0.5 * std::pow(1 - mean, 2) + 0.3 * std::pow(2 - mean, 2) + 0.195 * std::pow(3 - mean, 2) +
                          0.005 * std::pow(10 - mean, 2);
  CHECK(d.std == Approx(std::sqrt(variance)).epsilon(1e-12));
  CHECK(d.p50 == 1.0);
  CHECK(d.p90 == 3.0);
  CHECK(d.p99 == 3.0);
  CHECK(d.max == 10.0);
  // Scaling every area changes nothing.
  const Distribution scaled = distribution({10, 2, 1, 3}, {1, 60, 100, 39});
  CHECK(scaled.mean == Approx(d.mean).epsilon(1e-14));
  CHECK(scaled.p90 == d.p90);
}

TEST_CASE("von Mises, the largest principal and the hydrostatic stress of known states", "[analysis][statistics]") {
  // Uniaxial: von Mises is the stress itself.
  CHECK(von_mises({.xx = 5, .yy = 0, .zz = 0, .xy = 0}) == Approx(5));
  // Pure shear tau: von Mises sqrt(3) tau, principal stresses +-tau.
  CHECK(von_mises({.xx = 0, .yy = 0, .zz = 0, .xy = 2}) == Approx(2 * std::sqrt(3.0)));
  CHECK(largest_principal({.xx = 0, .yy = 0, .zz = 0, .xy = 2}) == Approx(2));
  // Hydrostatic: no von Mises stress; the out-of-plane stress can be the largest.
  CHECK(von_mises({.xx = -3, .yy = -3, .zz = -3, .xy = 0}) == Approx(0).margin(1e-12));
  CHECK(hydrostatic({.xx = 1, .yy = 2, .zz = 6, .xy = 7}) == Approx(3));
  CHECK(largest_principal({.xx = 1, .yy = 2, .zz = 6, .xy = 0}) == Approx(6));
  // In plane: (xx + yy) / 2 + sqrt(((xx - yy) / 2)^2 + xy^2).
  CHECK(largest_principal({.xx = 4, .yy = -2, .zz = 0, .xy = 4}) == Approx(1 + 5));
}

TEST_CASE("von Mises histograms give each phase's share of its area per bin", "[analysis][statistics]") {
  // Two unit squares of two triangles each: phase 0 at von Mises 1 and 3 (half its area
  // each), phase 1 all at 3.
  const CellMesh mesh = cell_mesh(TriMesh{{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}}, {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}}});
  const std::vector<StressState> stress{{.xx = 1}, {.xx = 3}, {.xx = 3}, {.xx = 3}};
  const auto h = von_mises_histograms(stress, mesh, {0, 0, 1, 1}, 2, 4);
  REQUIRE(h.size() == 2);
  REQUIRE(h[0].size() == 4);
  // Bins of width 0.5 from 1 to 3: centres 1.25, 1.75, 2.25, 2.75; 3 falls in the last.
  CHECK(h[0][0].x == Approx(1.25));
  CHECK(h[0][0].y == Approx(0.5));
  CHECK(h[0][3].y == Approx(0.5));
  CHECK(h[1][3].y == Approx(1.0));
  double sum = 0.0;
  for (const Vec2& b : h[1]) sum += b.y;
  CHECK(sum == Approx(1.0));
}

TEST_CASE("a general 3D state's largest principal stress and von Mises stress against its known eigenvalues",
          "[analysis][statistics]") {
  // R diag(5, 2, -1) R^T with R a rotation by 30 degrees about z, then by 45 about x: the
  // eigenvalues 5, 2, -1 in any axes; von Mises sqrt(((5 - 2)^2 + (2 + 1)^2 + (-1 - 5)^2) / 2).
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6), q = std::sqrt(0.5);
  const double R[3][3] = {{c, -s, 0}, {q * s, q * c, -q}, {q * s, q * c, q}};
  const double d[3] = {5, 2, -1};
  double A[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) A[i][j] += R[i][k] * d[k] * R[j][k];
  const StressTensor t{A[0][0], A[1][1], A[2][2], A[1][2], A[0][2], A[0][1]};
  REQUIRE(std::abs(t[3]) > 0.1);
  CHECK(largest_principal(t) == Approx(5).epsilon(1e-12));
  CHECK(von_mises(t) == Approx(std::sqrt((9.0 + 9.0 + 36.0) / 2)).epsilon(1e-12));
  CHECK(hydrostatic(t) == Approx(2).epsilon(1e-12));
  // Hydrostatic: every direction principal.
  CHECK(largest_principal(StressTensor{-3, -3, -3, 0, 0, 0}) == -3);
  // A 2D state as a tensor: the same measures.
  const StressState plane{.xx = 4, .yy = -2, .zz = 1, .xy = 4};
  CHECK(largest_principal(stress_tensor(plane)) == largest_principal(plane));
  CHECK(von_mises(stress_tensor(plane)) == Approx(von_mises(plane)).epsilon(1e-15));
}

TEST_CASE("phase means and partition from balanced stresses, with zz, the weights and the distributions the cells' own",
          "[analysis][statistics]") {
  // Two unit squares of two triangles: phase 0 on the left, phase 1 on the right, each
  // half the area.
  const CellMesh mesh = cell_mesh(TriMesh{{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}}, {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}}});
  std::vector<double> area;
  for (std::size_t k = 0; k < 4; ++k) area.push_back(cell_area(mesh, k));
  const std::vector<StressState> cells{{.xx = 1, .yy = 0, .zz = 5, .xy = 0}, {.xx = 3, .yy = 0, .zz = 7, .xy = 0},
                                       {.xx = 4, .yy = 1, .zz = 2, .xy = 0}, {.xx = 4, .yy = 1, .zz = 2, .xy = 0}};
  const std::vector<StressState> virial{{.xx = 2, .yy = -1, .zz = 0, .xy = 1}, {.xx = 4, .yy = -3, .zz = 0, .xy = 1},
                                        {.xx = 6, .yy = 2, .zz = 0, .xy = 0}, {.xx = 6, .yy = 2, .zz = 0, .xy = 0}};
  const std::vector<StressTensor> own = stress_tensors(cells), balanced = stress_tensors(cells, &virial);
  const std::vector<int> phase{0, 0, 1, 1};
  const auto plain = phase_stresses(own, area, phase, 2, 0);
  const auto with = phase_stresses(own, area, phase, 2, 0, &balanced);
  CHECK(plain[0].mean[0] == Approx(2.0));
  CHECK(plain[0].volume_fraction == Approx(0.5));
  CHECK(with[0].mean[0] == Approx(3.0));
  CHECK(with[0].mean[1] == Approx(-2.0));
  CHECK(with[0].mean[5] == Approx(1.0));
  CHECK(with[0].mean[2] == Approx(6.0));  // zz: the cells' own (the 2D virial has none)
  // The partition: the phase's balanced mean xx over the cell's, (3 + 6) / 2.
  CHECK(*with[0].partition == Approx(3.0 / 4.5));
  CHECK(*with[1].partition == Approx(6.0 / 4.5));
  CHECK(with[0].von_mises.mean == Approx(plain[0].von_mises.mean));
  // Loaded in xy (Voigt index 5): the balanced xy means, 1 and 0, over the cell's 0.5.
  CHECK(*phase_stresses(own, area, phase, 2, 5, &balanced)[0].partition == Approx(2.0));
  // No loaded component: no partition.
  CHECK_FALSE(phase_stresses(own, area, phase, 2, -1, &balanced)[0].partition);
  // Weights of a 3D cell: volumes, phase 1 three times phase 0's.
  const auto weighted = phase_stresses(own, {1, 1, 3, 3}, phase, 2, 0);
  CHECK(weighted[1].volume_fraction == Approx(0.75));
  CHECK(weighted[0].hydrostatic.mean == Approx((2.0 + 10.0 / 3) / 2).epsilon(1e-12));
}
