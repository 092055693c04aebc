#include <algorithm>
#include <cmath>
#include <set>

#include <catch2/catch.hpp>

#include "common/errors.hpp"
#include "common/random.hpp"
#include "grains/grain_mesh.hpp"
#include "mesh/dual_mesh.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellate.hpp"

using namespace grainmesh;

namespace {

Tessellation cells(bool periodic, int grains, std::uint64_t seed, double binder = 0.0) {
  TessellationOptions o;
  o.width = 3.0;
  o.height = 1.7;
  o.grains = grains;
  o.periodic = periodic;
  o.lloyd_iterations = 3;
  o.phases = {Phase{"WC", 0.0, true, 800e9, 0.1, {}}, Phase{"Co", 0.2, false, 300e9, 0.1, {}}};
  if (binder > 0.0) {
    o.phases[1].fraction = binder;
    o.phase_mode = PhaseMode::binder;
    o.matrix_phase = 1;
  }
  Rng rng(seed);
  return tessellate(o, rng);
}

// Every invariant of a dual split by grain: one grain per cell, each grain's cells add up
// to its area, cells no more than `max_ratio` of the triangles, pairs exact.
void check_dual(const Tessellation& t, const GrainMesh& m, double max_ratio) {
  const DualMesh d = dual_mesh(m.mesh, m.grain, m.pairs);
  REQUIRE_NOTHROW(validate(d.mesh));
  REQUIRE(d.node.size() == d.mesh.cells());
  REQUIRE(d.triangle.size() == d.mesh.cells());
  std::vector<double> area(t.grains.size(), 0.0);
  for (std::size_t c = 0; c < d.mesh.cells(); ++c) area[m.grain[d.triangle[c]]] += cell_area(d.mesh, c);
  double worst = 0.0;
  for (std::size_t g = 0; g < t.grains.size(); ++g)
    worst = std::max(worst, std::abs(area[g] - t.grains[g].area) / t.grains[g].area);
  CHECK(worst <= 1e-9);
  INFO(d.mesh.cells() << " cells from " << m.mesh.triangles.size() << " triangles");
  CHECK(static_cast<double>(d.mesh.cells()) <= max_ratio * static_cast<double>(m.mesh.triangles.size()));
  // Every triangle of the conforming mesh (splits add some) takes its circumcentre, so
  // every face between the cells of two nodes lies on the bisector of the edge joining
  // them: at right angles to it.
  CHECK(d.circumcentres >= m.mesh.triangles.size());
  CHECK(d.centroids == 0);
  std::size_t faces = 0, skew = 0;
  for (const MeshEdge& e : mesh_edges(d.mesh)) {
    if (e.right < 0) continue;
    const int v = d.node[e.left], w = d.node[e.right];
    const int n = static_cast<int>(m.mesh.points.size());
    if (v == w || v >= n || w >= n) continue;  // a cut along a grain boundary; a split edge's midpoint
    const Vec2 face = d.mesh.points[e.b] - d.mesh.points[e.a], joining = m.mesh.points[w] - m.mesh.points[v];
    ++faces;
    skew += std::abs(dot(face, joining)) > 1e-9 * std::sqrt(norm2(face) * norm2(joining));
  }
  CHECK(faces > d.mesh.cells());
  CHECK(skew == 0);
  if (t.periodic) {
    // The carried pairs are exactly the pairs by position of the dual's side points.
    const PeriodicPairs by_position = pair_by_position(d.mesh.points, Box{{0.0, 0.0}, {t.width, t.height}});
    for (const auto* side : {&d.pairs.axis[0], &d.pairs.axis[1]}) {
      const auto& want = side == &d.pairs.axis[0] ? by_position.axis[0] : by_position.axis[1];
      CHECK(std::set<std::pair<int, int>>(side->begin(), side->end()) ==
            std::set<std::pair<int, int>>(want.begin(), want.end()));
    }
  } else {
    CHECK(d.pairs.axis[0].empty());
    CHECK(d.pairs.axis[1].empty());
  }
}

}  // namespace

TEST_CASE("the dual of two triangles: the corners' Voronoi cells, or each label's own", "[dual]") {
  const TriMesh square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}}};
  // One label: the two circumcentres are the square's centre (one point), the cells the
  // four quarter squares.
  const DualMesh one = dual_mesh(square, {0, 0});
  CHECK(one.circumcentres == 2);
  CHECK(one.splits == 0);
  REQUIRE(one.mesh.cells() == 4);
  for (std::size_t c = 0; c < 4; ++c) {
    CHECK(one.mesh.cell(c).size() == 4);
    CHECK(cell_area(one.mesh, c) == Approx(0.25).epsilon(1e-15));
  }
  // Two labels: the diagonal bounds both, and each right angle faces it, so it is split
  // (and so on, for a few rounds: right isosceles halves stay right isosceles); each
  // label's cells still cover exactly its half.
  const DualMesh two = dual_mesh(square, {0, 1});
  CHECK(two.splits > 0);
  double half[2] = {0.0, 0.0};
  for (std::size_t c = 0; c < two.mesh.cells(); ++c) half[two.triangle[c]] += cell_area(two.mesh, c);
  CHECK(half[0] == Approx(0.5).epsilon(1e-15));
  CHECK(half[1] == Approx(0.5).epsilon(1e-15));
  CHECK_THROWS_WITH(dual_mesh(square, {0}), Catch::Contains("1 labels for 2 triangles"));
}

TEST_CASE("an edge bounding a label that an obtuse triangle faces is split at its midpoint", "[dual]") {
  // A square with a node just above the middle of its bottom side: the triangle on that
  // side is obtuse, its circumcentre far below the side. The side is split at its
  // midpoint, and every triangle takes its circumcentre again.
  const TriMesh square{{{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0.3}}, {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}};
  const DualMesh d = dual_mesh(square, {0, 0, 0, 0});
  CHECK(d.splits == 1);
  CHECK(d.centroids == 0);
  double total = 0.0;
  for (std::size_t c = 0; c < d.mesh.cells(); ++c) total += cell_area(d.mesh, c);
  CHECK(total == Approx(4.0).epsilon(1e-15));
  // Node 5, the bottom side's midpoint, got a cell of its own.
  CHECK(std::count(d.node.begin(), d.node.end(), 5) == 1);
}

TEST_CASE("an interior node of acute triangles gets its Voronoi cell", "[dual]") {
  // A regular hexagon around the origin: six equilateral triangles.
  TriMesh hex;
  hex.points.push_back({0, 0});
  for (int k = 0; k < 6; ++k) hex.points.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3)});
  for (int k = 0; k < 6; ++k) hex.triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
  const DualMesh d = dual_mesh(hex, std::vector<int>(6, 0));
  CHECK(d.circumcentres == 6);
  REQUIRE(d.node[0] == 0);
  // The centre's cell: the hexagon of the circumcentres (the spokes' midpoints left out),
  // of side 1/sqrt(3): area sqrt(3)/2.
  CHECK(d.mesh.cell(0).size() == 6);
  CHECK(cell_area(d.mesh, 0) == Approx(std::sqrt(3.0) / 2.0).epsilon(1e-14));
  double total = 0.0;
  for (std::size_t c = 0; c < d.mesh.cells(); ++c) total += cell_area(d.mesh, c);
  CHECK(total == Approx(1.5 * std::sqrt(3.0)).epsilon(1e-14));
}

TEST_CASE("dual cells of grain meshes keep every grain exact and their periodic pairs", "[dual][grains]") {
  for (bool periodic : {true, false})
    for (std::uint64_t seed : {1, 2}) {
      INFO("periodic " << periodic << " seed " << seed);
      const Tessellation t = cells(periodic, 40, seed);
      // About 90 triangles per grain: a node has about two triangles, and a node on a
      // grain boundary one cell per grain (0.66 to 0.68 measured).
      check_dual(t, mesh_tessellation(t, {.size = 0.06, .phase_size = {}}), 0.7);
    }
  // About 330 triangles per grain: fewer of the nodes lie on grain boundaries (0.59).
  const Tessellation fine = cells(true, 40, 1);
  check_dual(fine, mesh_tessellation(fine, {.size = 0.03, .phase_size = {}}), 0.6);
  const Tessellation binder = cells(true, 30, 3, 0.12);
  check_dual(binder, mesh_tessellation(binder, {.size = 0.05, .phase_size = {}}), 0.7);
}
