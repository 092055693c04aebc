// Nested refinement (export/nested_split.hpp) on periodic two-phase cells: four triangles
// (eight tetrahedra) per cell, each grain's area (volume) kept exactly, no inverted child,
// the periodic pairs those a search by position finds (2D) or exact images (3D), and a
// cyclic case of the split cell that checkMesh accepts; the finite-element answer on the
// split mesh lies below the unsplit one's (the spaces are nested: displacement elements
// are too stiff, less so when refined); the two levels solved together (the fine one by
// two-grid conjugate gradients) give the factorised answer.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "analysis/answer.hpp"
#include "analysis/fe_homogenise.hpp"
#include "analysis/voigt.hpp"
#include "common/side_by_side.hpp"
#include "checkmesh.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_case.hpp"
#include "export/nested_split.hpp"
#include "grains/grain_mesh.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "helpers.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/tessellate_3d.hpp"

using namespace grainmesh;

namespace {

// A periodic plane cell of `grains` Lloyd-relaxed grains, meshed at element size `size`.
ExportMesh<2> plane_cell(double width, double height, int grains, std::vector<Phase> phases, unsigned seed,
                         double size) {
  TessellationOptions o;
  o.width = width;
  o.height = height;
  o.grains = grains;
  o.periodic = true;
  o.lloyd_iterations = 3;
  o.phases = std::move(phases);
  Rng rng(seed);
  const Tessellation t = tessellate(o, rng);
  return grain_export_mesh(t, mesh_tessellation(t, {.size = size, .phase_size = {}}));
}

ExportMesh<2> cell_2d() {
  const std::vector<Phase> phases{Phase{"WC", 0.0, true, 700e9, 0.24, {}}, Phase{"Co", 0.2, false, 211e9, 0.31, {}}};
  return plane_cell(3.0, 1.7, 30, phases, 5, 0.15);
}

ExportMesh<3> cell_3d() {
  Tessellation3Options o;
  o.grains = 12;
  o.periodic = true;
  o.lloyd_iterations = 3;
  o.phases = {Phase{"WC", 0.0, true, 700e9, 0.24, {}}, Phase{"Co", 0.2, false, 211e9, 0.31, {}}};
  Rng rng(3);
  const Tessellation3 t = tessellate_3d(o, rng);
  return grain_export_mesh(t, mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 48)}));
}

std::map<int, double> grain_areas(const ExportMesh<2>& m) {
  std::map<int, double> area;
  for (std::size_t c = 0; c < m.mesh.cells(); ++c) {
    const double a = cell_area(m.mesh, c);
    CHECK(a > 0.0);
    area[m.grain[c]] += a;
  }
  return area;
}

std::map<int, double> grain_volumes(const ExportMesh<3>& m) {
  std::map<int, double> volume;
  for (std::size_t c = 0; c < m.mesh.tets.size(); ++c) {
    const auto& [a, b, d, e] = m.mesh.tets[c];
    const auto& p = m.mesh.points;
    const double v = tet_volume(p[a], p[b], p[d], p[e]);
    CHECK(v > 0.0);
    volume[m.grain[c]] += v;
  }
  return volume;
}

template <class Map>
void check_same_measures(const Map& before, const Map& after) {
  REQUIRE(before.size() == after.size());
  for (const auto& [grain, measure] : before) CHECK(after.at(grain) == Approx(measure).epsilon(1e-12));
}

}  // namespace

TEST_CASE("nested refinement splits a periodic plane cell in four, grains and pairs kept", "[export][nested]") {
  const ExportMesh<2> m = cell_2d();
  const ExportMesh<2> s = split_nested(m);
  REQUIRE(s.mesh.cells() == 4 * m.mesh.cells());
  validate(s.mesh);
  check_same_measures(grain_areas(m), grain_areas(s));
  for (std::size_t c = 0; c < s.mesh.cells(); ++c) CHECK(s.phase[c] == m.phase[c / 4]);
  // The pairs are exactly those of the points on the sides.
  PeriodicPairs found = pair_by_position(s.mesh.points, s.cell), made = s.pairs;
  for (int axis = 0; axis < 2; ++axis) {
    std::sort(found.axis[axis].begin(), found.axis[axis].end());
    std::sort(made.axis[axis].begin(), made.axis[axis].end());
    CHECK(made.axis[axis] == found.axis[axis]);
    CHECK(made.axis[axis].size() == 2 * m.pairs.axis[axis].size() - 1);  // a midpoint between each two
  }
  test::ScratchDir dir("nested_split");
  write_foam_case(dir.path(), s, {.cyclic = true});
  test::check_mesh_ok(dir.path(), s.phases, s.phase);
}

TEST_CASE("nested refinement splits a periodic solid cell in eight, grains and pairs kept", "[export][nested]") {
  const ExportMesh<3> m = cell_3d();
  const ExportMesh<3> s = split_nested(m);
  REQUIRE(s.mesh.tets.size() == 8 * m.mesh.tets.size());
  check_same_measures(grain_volumes(m), grain_volumes(s));
  const Vec3 size = s.cell.size();
  for (int axis = 0; axis < 3; ++axis) {
    REQUIRE(s.pairs.axis[axis].size() > m.pairs.axis[axis].size());
    for (const auto& [low, high] : s.pairs.axis[axis]) {
      const Vec3 a = s.mesh.points[low], b = s.mesh.points[high];
      const std::array<double, 3> pa{a.x, a.y, a.z}, pb{b.x, b.y, b.z}, extent{size.x, size.y, size.z};
      for (int k = 0; k < 3; ++k) {
        if (k == axis) CHECK(pb[k] - pa[k] == Approx(extent[k]).epsilon(1e-12));
        else CHECK(pb[k] == pa[k]);  // bit for bit
      }
    }
  }
}

TEST_CASE("the finite elements on a nested refinement lie below the unsplit mesh's", "[export][nested][fe]") {
  const ExportMesh<2> m = cell_2d();
  const FeHomogenised<3> coarse = fe_homogenise(m, false, false), fine = fe_homogenise(split_nested(m), false, false);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(fine.stiffness[i][i] < coarse.stiffness[i][i]);
    CHECK(fine.stiffness[i][i] > 0.999 * coarse.stiffness[i][i]);
  }
}

namespace {

// How far the cycles' answer may lie from the factor's: they stop at a residual of 1e-4 of
// each load's norm (fe_homogenise.cpp), which on the 3D example left the stiffness within
// 5e-9 and the expansion within 9e-9 of the answer at 1e-6; on this test's 3D cell the
// coarse level's expansion by its linear elements came within 1.1e-7 of its factor's.
constexpr double kCycles = 3e-7;

// Each entry of `a` within `tolerance` of `b`'s, relative to b's largest entry.
template <class Tensor>
void check_close(const Tensor& a, const Tensor& b, double tolerance) {
  double scale = 0.0;
  for (const auto& row : b)
    for (const double v : row) scale = std::max(scale, std::abs(v));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < a.size(); ++j) CHECK(std::abs(a[i][j] - b[i][j]) <= tolerance * scale);
}

template <class Fe>
void check_expansion_close(const Fe& a, const Fe& b) {
  REQUIRE(a.expansion);
  REQUIRE(b.expansion);
  for (std::size_t i = 0; i < a.expansion->size(); ++i)
    CHECK((*a.expansion)[i] == Approx((*b.expansion)[i]).margin(kCycles * std::abs((*b.expansion)[0])));
}

// A coarse level too costly to factorise (forced here: no operations allowed) is solved by
// conjugate gradients on its linear elements' cycle, and the fine level's cycle nests it:
// both levels' answers are still their factors' to the cycles' precision.
template <int D, class Solve>
void check_linear_coarse_level(const ExportMesh<D>& coarse, const FeHomogenised<voigt_size(D)>& fine_direct,
                               Solve solve) {
  INFO("the coarse level by its linear elements");
  FeOptions o;
  o.coarse_factor_flops = 0.0;
  const auto nested = solve(o);
  const auto coarse_direct = [&] {
    if constexpr (D == 2)
      return fe_homogenise(coarse, false, true);
    else
      return fe_homogenise(coarse, true);
  }();
  CHECK(nested.coarse.iterations > 0);
  CHECK(nested.coarse.iterations < 50);
  CHECK(nested.fine.iterations > 0);
  CHECK(nested.fine.iterations < 60);
  check_close(nested.coarse.stiffness, coarse_direct.stiffness, kCycles);
  check_expansion_close(nested.coarse, coarse_direct);
  check_close(nested.fine.stiffness, fine_direct.stiffness, kCycles);
  check_expansion_close(nested.fine, fine_direct);
}

}  // namespace

TEST_CASE("the nested levels' fine solve by two-grid conjugate gradients is the factorised one", "[export][nested][fe]") {
  SECTION("2D, heated") {
    ExportMesh<2> m = cell_2d();
    m.phases[0].alpha = 5.2e-6;
    m.phases[1].alpha = 13.8e-6;
    const ExportMesh<2> fine = split_nested(m);
    const FeNested<3> nested = fe_homogenise_nested(m, fine, false, true);
    const FeHomogenised<3> direct = fe_homogenise(fine, false, true);
    CHECK(nested.fine.iterations > 0);
    CHECK(nested.fine.iterations < 30);
    CHECK(nested.fine.unknowns == direct.unknowns);
    check_close(nested.fine.stiffness, direct.stiffness, kCycles);
    check_expansion_close(nested.fine, direct);
    check_close(nested.coarse.stiffness, fe_homogenise(m, false, true).stiffness, 1e-12);
    CHECK_THROWS_AS(fe_homogenise_nested(m, m, false, false), GeometryError);
    // On one thread (sweep --jobs 2 or more) the loads' groups are solved one after the
    // other and the coarse factor before the fine level's assembly: the same answer to the
    // bit (the groups do not depend on the threads, the factor is made on one BLAS thread).
    limit_fe_threads(1);
    const FeNested<3> one = fe_homogenise_nested(m, fine, false, true);
    limit_fe_threads(cores());
    CHECK(one.coarse.stiffness == nested.coarse.stiffness);
    CHECK(one.fine.stiffness == nested.fine.stiffness);
    CHECK(*one.fine.expansion == *nested.fine.expansion);
    CHECK(one.fine.iterations == nested.fine.iterations);
    check_linear_coarse_level(m, direct, [&](const FeOptions& o) { return fe_homogenise_nested(m, fine, false, true, o); });
  }
  SECTION("3D, heated") {
    ExportMesh<3> m = cell_3d();
    m.phases[0].alpha = 5.2e-6;
    m.phases[1].alpha = 13.8e-6;
    const ExportMesh<3> fine = split_nested(m);
    const FeNested<6> nested = fe_homogenise_nested(m, fine, true);
    const FeHomogenised<6> direct = fe_homogenise(fine, true);
    CHECK(nested.fine.iterations > 0);
    CHECK(nested.fine.iterations < 50);
    check_close(nested.fine.stiffness, direct.stiffness, kCycles);
    check_expansion_close(nested.fine, direct);
    check_linear_coarse_level(m, direct, [&](const FeOptions& o) { return fe_homogenise_nested(m, fine, true, o); });
  }
}

namespace {

// The fine level's error estimate (fe_levels, from the coarse level and the fine) against
// the fine level's measured error: its difference from the next level, a third (the error
// of a displacement method only shrinks under nested refinement, so this is the part of
// it that the levels show). Every stiffness entry, K, G and the expansion are covered;
// the diagonals, K and G (energies) fall from level to level and by a factor of at least
// 1 + 1 / kFeLevelFactor per halving, the estimate's assumption.
template <std::size_t N>
void check_estimate_covers(const FeHomogenised<N>& coarse, const FeHomogenised<N>& fine, const FeHomogenised<N>& next) {
  const FeLevels<N> l = fe_levels(fine, coarse, "test");
  const Stiffness<N>& a0 = coarse.stiffness;
  const Stiffness<N>& a1 = fine.stiffness;
  const Stiffness<N>& a2 = next.stiffness;
  const double largest = largest_entry(a2);
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) {
      CAPTURE(i, j, a0[i][j], a1[i][j], a2[i][j]);
      const double scale = std::abs(a2[i][j]) >= 0.01 * largest ? std::abs(a2[i][j]) : largest;
      CHECK(std::abs(a1[i][j] - a2[i][j]) / scale <= l.estimate.stiffness[i][j]);
    }
  auto check_energy = [](double e0, double e1, double e2, double estimate) {
    CAPTURE(e0, e1, e2, estimate);
    CHECK(e0 > e1);
    CHECK(e1 > e2);
    CHECK((e0 - e1) / (e1 - e2) >= 1.0 + 1.0 / kFeLevelFactor);
    CHECK(e1 / e2 - 1.0 <= estimate);
  };
  for (std::size_t i = 0; i < N; ++i) check_energy(a0[i][i], a1[i][i], a2[i][i], l.estimate.stiffness[i][i]);
  check_energy(bulk_modulus(a0), bulk_modulus(a1), bulk_modulus(a2), l.estimate.bulk_modulus);
  check_energy(shear_modulus(a0), shear_modulus(a1), shear_modulus(a2), l.estimate.shear_modulus);
  REQUIRE(l.estimate.expansion);
  const auto& x1 = *fine.expansion;
  const auto& x2 = *next.expansion;
  const double scale = std::max({std::abs(x2[0]), std::abs(x2[1]), std::abs(x2[voigt_dimensions<N>() - 1])});
  for (std::size_t k = 0; k < N; ++k) {
    CAPTURE(k, x1[k], x2[k]);
    CHECK(std::abs(x1[k] - x2[k]) / scale <= (*l.estimate.expansion)[k]);
  }
}

std::vector<Phase> wc_co(double co_modulus) {
  return {Phase{"WC", 0.0, true, 700e9, 0.24, {}}, Phase{"Co", 0.25, false, co_modulus, 0.31, {}}};
}

template <class Mesh>
Mesh heated(Mesh m) {
  m.phases[0].alpha = 5.2e-6;
  m.phases[1].alpha = 13.8e-6;
  return m;
}

}  // namespace

TEST_CASE("the finite elements' error estimate covers their error measured on the next nested level",
          "[export][nested][fe]") {
  SECTION("2D, contrasts 3.3 and 20") {
    for (const double co_modulus : {211e9, 35e9}) {
      CAPTURE(co_modulus);
      const ExportMesh<2> m = heated(plane_cell(1.5, 1.2, 12, wc_co(co_modulus), 7, 0.15));
      const ExportMesh<2> s1 = split_nested(m);
      const FeNested<3> levels = fe_homogenise_nested(m, s1, false, true);
      check_estimate_covers(levels.coarse, levels.fine, fe_homogenise_nested(s1, split_nested(s1), false, true).fine);
    }
  }
  SECTION("3D") {
    // A cell whose C12 and C13 changed less from the coarse level to the fine than from the
    // fine to the next: their own changes alone estimated them below their error.
    Tessellation3Options o;
    o.grains = 6;
    o.periodic = true;
    o.lloyd_iterations = 3;
    o.phases = wc_co(211e9);
    Rng rng(3);
    const Tessellation3 t = tessellate_3d(o, rng);
    const ExportMesh<3> m =
        heated(grain_export_mesh(t, mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, 24)})));
    const ExportMesh<3> s1 = split_nested(m);
    const FeNested<6> levels = fe_homogenise_nested(m, s1, true);
    const FeNested<6> next = fe_homogenise_nested(s1, split_nested(s1), true);
    check_estimate_covers(levels.coarse, levels.fine, next.fine);
  }
}
