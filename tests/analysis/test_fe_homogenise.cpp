// The finite-element reference against exact answers, in 2D and 3D: one material (its own
// stiffness and free expansion), laminates whose layers the mesh follows (Backus's
// stiffness, Levin's exact expansion with it), both to 1e-9; a stiff inclusion converging
// as quadratic elements should under nested refinement; and the periodic ties refused
// where the mesh does not hold them.
#include <dlfcn.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

#include "analysis/bounds.hpp"
#include "analysis/fe_homogenise.hpp"
#include "analysis/thermal.hpp"
#include "common/errors.hpp"
#include "pipelines/laminate.hpp"

using namespace grainmesh;

namespace {

const FoamPhase kHard{"hard", 700e9, 0.24, 5.2e-6}, kSoft{"soft", 210e9, 0.31, 13.8e-6};

// An n x n periodic grid of squares on [0, 2] x [0, 1], each cut into two triangles; a
// cell's phase by `phase_at` of its centroid.
template <class PhaseAt>
ExportMesh<2> grid_2d(int n, PhaseAt phase_at) {
  ExportMesh<2> m;
  m.phases = {kHard, kSoft};
  m.cell.lo = {0, 0};
  m.cell.hi = {2, 1};
  m.periodic = true;
  auto id = [n](int i, int j) { return i + (n + 1) * j; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.mesh.points.push_back({2.0 * i / n, 1.0 * j / n});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      for (const std::array<int, 3> t : {std::array<int, 3>{id(i, j), id(i + 1, j), id(i + 1, j + 1)},
                                         std::array<int, 3>{id(i, j), id(i + 1, j + 1), id(i, j + 1)}}) {
        m.mesh.add_cell(t);
        const Vec2 c = (1.0 / 3.0) * (m.mesh.points[t[0]] + m.mesh.points[t[1]] + m.mesh.points[t[2]]);
        m.phase.push_back(phase_at(c.x, c.y));
        m.grain.push_back(m.phase.back());
      }
  for (int j = 0; j <= n; ++j) m.pairs.axis[0].emplace_back(id(0, j), id(n, j));
  for (int i = 0; i <= n; ++i) m.pairs.axis[1].emplace_back(id(i, 0), id(i, n));
  return m;
}

// An n^3 periodic grid of cubes on [0, 1]^3, each cut into six tetrahedra along its
// diagonal (Kuhn's: the same cut in every cube, so opposite sides match); phase by centroid.
template <class PhaseAt>
ExportMesh<3> grid_3d(int n, PhaseAt phase_at) {
  ExportMesh<3> m;
  m.phases = {kHard, kSoft};
  m.cell = {{0, 0, 0}, {1, 1, 1}};
  m.periodic = true;
  auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.mesh.points.push_back({1.0 * i / n, 1.0 * j / n, 1.0 * k / n});
  std::array<int, 3> axes{0, 1, 2};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        std::sort(axes.begin(), axes.end());
        do {
          std::array<int, 3> at{i, j, k};
          std::array<int, 4> tet{};
          tet[0] = id(at[0], at[1], at[2]);
          for (int s = 0; s < 3; ++s) {
            ++at[static_cast<std::size_t>(axes[static_cast<std::size_t>(s)])];
            tet[static_cast<std::size_t>(s + 1)] = id(at[0], at[1], at[2]);
          }
          const auto& p = m.mesh.points;
          if (tet_volume(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]) < 0) std::swap(tet[2], tet[3]);
          m.mesh.tets.push_back(tet);
          const Vec3 c = tet_centroid(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]);
          m.phase.push_back(phase_at(c.x, c.y, c.z));
          m.grain.push_back(m.phase.back());
        } while (std::next_permutation(axes.begin(), axes.end()));
      }
  for (int b = 0; b <= n; ++b)
    for (int a = 0; a <= n; ++a) {
      m.pairs.axis[0].emplace_back(id(0, a, b), id(n, a, b));
      m.pairs.axis[1].emplace_back(id(a, 0, b), id(a, n, b));
      m.pairs.axis[2].emplace_back(id(a, b, 0), id(a, b, n));
    }
  return m;
}

test::Material material(const FoamPhase& p) { return {p.youngs_modulus, p.poisson_ratio, p.alpha}; }

template <std::size_t N>
void check_stiffness(const Stiffness<N>& got, const Stiffness<N>& exact) {
  const double scale = largest_entry(exact);
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) {
      INFO("C" << i + 1 << j + 1);
      CHECK(std::abs(got[i][j] - exact[i][j]) < 1e-9 * scale);
    }
}

template <std::size_t N>
void check_expansion(const std::array<double, N>& got, const std::array<double, N>& exact) {
  const double scale = std::max(std::abs(exact[0]), std::abs(exact[1]));
  for (std::size_t k = 0; k < N; ++k) CHECK(std::abs(got[k] - exact[k]) < 1e-9 * scale);
}

}  // namespace

TEST_CASE("the FE reference on one material: its own stiffness and free expansion, 2D and 3D", "[analysis][fe]") {
  for (const bool plane_stress : {false, true}) {
    const FeHomogenised<3> h = fe_homogenise(grid_2d(4, [](double, double) { return 0; }), plane_stress, true);
    check_stiffness<3>(h.stiffness, isotropic_stiffness<3>(kHard, plane_stress));
    const double b = free_expansion(kHard, plane_stress);
    check_expansion<3>(*h.expansion, {b, b, 0.0});
  }
  const FeHomogenised<6> h = fe_homogenise(grid_3d(2, [](double, double, double) { return 1; }), true);
  check_stiffness<6>(h.stiffness, isotropic_stiffness<6>(kSoft));
  check_expansion<6>(*h.expansion, {kSoft.alpha, kSoft.alpha, kSoft.alpha, 0, 0, 0});
}

TEST_CASE("the FE reference leaves a point no element uses without unknowns", "[analysis][fe]") {
  // A mesher may leave a point unused (TetGen did, on a 3D cell): it has no stiffness.
  ExportMesh<3> m = grid_3d(2, [](double, double, double) { return 0; });
  const FeHomogenised<6> before = fe_homogenise(m, false);
  m.mesh.points.push_back({0.3, 0.4, 0.5});
  const FeHomogenised<6> after = fe_homogenise(m, false);
  CHECK(after.unknowns == before.unknowns);
  check_stiffness<6>(after.stiffness, isotropic_stiffness<6>(kHard));
}

TEST_CASE("the FE reference on laminates the mesh follows: Backus's stiffness and Levin's expansion, exact",
          "[analysis][fe]") {
  // Layers normal to x, the soft one 30 % of the cell.
  const double f = 0.3;
  {
    const FeHomogenised<3> h = fe_homogenise(grid_2d(10, [&](double x, double) { return x < 2 * f ? 1 : 0; }), false, true);
    const auto [c11, c22, c12, c66] = test::laminate(material(kHard), material(kSoft), f);
    const Stiffness<3> exact{{{c11, c12, 0}, {c12, c22, 0}, {0, 0, c66}}};
    check_stiffness<3>(h.stiffness, exact);
    check_expansion<3>(*h.expansion, *levin_expansion<3>({kHard, kSoft}, exact));
  }
  {
    // Two of six slabs soft.
    const double f3 = 1.0 / 3.0;
    const FeHomogenised<6> h = fe_homogenise(grid_3d(6, [&](double x, double, double) { return x < f3 ? 1 : 0; }), true);
    const Stiffness<6> exact = test::laminate_3d(material(kHard), material(kSoft), f3);
    check_stiffness<6>(h.stiffness, exact);
    check_expansion<6>(*h.expansion, *levin_expansion<6>({kHard, kSoft}, exact));
  }
}

TEST_CASE("the FE reference converges on a stiff inclusion as quadratic elements should", "[analysis][fe]") {
  // A soft square inclusion in the hard cell: its corners make the solution singular, so
  // the energy converges at a rate below the smooth one's h^4; the differences between
  // nested levels shrink steadily, by more than the linear elements' h^2 would.
  auto inclusion = [](double x, double y) { return x > 0.5 && x < 1.5 && y > 0.25 && y < 0.75 ? 1 : 0; };
  std::vector<double> c11;
  for (const int n : {8, 16, 32}) c11.push_back(fe_homogenise(grid_2d(n, inclusion), false, false).stiffness[0][0]);
  const double d1 = std::abs(c11[1] - c11[0]), d2 = std::abs(c11[2] - c11[1]);
  INFO("C11 " << c11[0] << " " << c11[1] << " " << c11[2]);
  CHECK(d2 < 0.5 * d1);
  CHECK(d2 < 1e-3 * c11[2]);
}

TEST_CASE("the FE reference refuses a cell it cannot tie or solve", "[analysis][fe]") {
  ExportMesh<2> m = grid_2d(4, [](double, double) { return 0; });
  ExportMesh<2> open = m;
  open.periodic = false;
  CHECK_THROWS_WITH(fe_homogenise(open, false, false), Catch::Contains("not periodic"));
  ExportMesh<2> inverted = m;
  std::swap(inverted.mesh.corners[1], inverted.mesh.corners[2]);
  CHECK_THROWS_WITH(fe_homogenise(inverted, false, false), Catch::Contains("element 0 is inverted"));
}

TEST_CASE("the FE reference refuses a factor larger than the memory it may take, naming the key", "[analysis][fe]") {
  const ExportMesh<2> m = grid_2d(32, [](double, double) { return 0; });
  // A 32 x 32 grid's factor takes a few MiB: refused under 1 MiB, solved under 1 GiB.
  CHECK_THROWS_AS(fe_homogenise(m, false, false, {.memory_mib = 1.0}), ConfigError);
  CHECK_THROWS_WITH(fe_homogenise(m, false, false, {.memory_mib = 1.0}),
                    Catch::StartsWith("homogenise.solver = fe: the finite elements on this mesh") &&
                        Catch::Contains("more than the 1 MiB available") && Catch::Contains("homogenise.solver = openfoam"));
  CHECK_THROWS_WITH(fe_homogenise(m, false, false, {.memory_mib = 1.0, .reference = true}),
                    Catch::StartsWith("homogenise.reference = fe: ") && Catch::Contains("homogenise.reference = none"));
  CHECK_NOTHROW(fe_homogenise(m, false, false, {.memory_mib = 1024.0}));
  const ExportMesh<3> cube = grid_3d(4, [](double, double, double) { return 0; });
  CHECK_THROWS_AS(fe_homogenise(cube, false, {.memory_mib = 0.01}), ConfigError);
}

// scripts/install-deps.sh makes OpenBLAS the BLAS: the limit must reach it.
TEST_CASE("the finite elements' BLAS threads are limited (OpenBLAS's)", "[analysis][fe]") {
  using GetThreads = int (*)();
  const auto get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  REQUIRE(get);
  const int before = get();
  limit_fe_threads(2);
  CHECK(get() == 2);
  limit_fe_threads(1);
  CHECK(get() == 1);
  limit_fe_threads(before);
}
