// The finite-element view of a grain mesh that the Gmsh and Abaqus files are written from:
// its side facets (on the side, facing out) and its periodic ties (each high-side point
// once, straight to the point on no high side), on hand-made plane and solid cells.
#include <algorithm>
#include <array>
#include <vector>

#include <catch2/catch.hpp>

#include "common/errors.hpp"
#include "export/element_mesh.hpp"
#include "mesh/tetmesh.hpp"

namespace gm = grainmesh;

namespace {

// The unit square as a 3 x 3 grid of points (p = i + 3 j), two triangles per square; the
// left column grain 0 (phase 0), the right grain 1 (phase 1); periodic.
gm::ElementMesh square() {
  gm::ExportMesh<2> e;
  gm::TriMesh tri;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) tri.points.push_back({0.5 * i, 0.5 * j});
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = i + 3 * j, b = a + 1, c = a + 4, d = a + 3;
      tri.triangles.push_back({a, b, c});
      tri.triangles.push_back({a, c, d});
      for (int k = 0; k < 2; ++k) {
        e.grain.push_back(i);
        e.phase.push_back(i);
      }
    }
  e.mesh = gm::cell_mesh(tri);
  e.phases = {{"WC", 700e9, 0.2}, {"Co", 200e9, 0.3}};
  e.cell = gm::Box{{0.0, 0.0}, {1.0, 1.0}};
  e.periodic = true;
  e.pairs = gm::pair_by_position(tri.points, e.cell);
  return gm::element_mesh(e);
}

// The unit cube's corners (p = x + 2 y + 4 z) as its six Kuhn tetrahedra round the
// diagonal 0-7, positive; periodic, each corner paired across each axis it is low on.
gm::ElementMesh cube() {
  gm::ExportMesh<3> e;
  for (int p = 0; p < 8; ++p) e.mesh.points.push_back({double(p & 1), double((p >> 1) & 1), double((p >> 2) & 1)});
  std::array<int, 3> axes{0, 1, 2};
  do {
    std::array<int, 4> t{0, 1 << axes[0], (1 << axes[0]) | (1 << axes[1]), 7};
    const auto& P = e.mesh.points;
    if (gm::tet_volume(P[t[0]], P[t[1]], P[t[2]], P[t[3]]) < 0) std::swap(t[2], t[3]);
    e.mesh.tets.push_back(t);
    e.grain.push_back(3);
    e.phase.push_back(0);
  } while (std::next_permutation(axes.begin(), axes.end()));
  e.phases = {{"WC", 700e9, 0.2}};
  e.cell = gm::Box3{{0, 0, 0}, {1, 1, 1}};
  e.periodic = true;
  for (int axis = 0; axis < 3; ++axis)
    for (int p = 0; p < 8; ++p)
      if (!(p & (1 << axis))) e.pairs.axis[axis].push_back({p, p | (1 << axis)});
  return gm::element_mesh(e);
}

// Whether facet f of element `el` faces out of it: its right-hand normal (2D: the edge's
// right) points away from the element's other corners.
bool faces_out(const gm::ElementMesh& m, const std::array<int, 3>& f, const std::array<int, 4>& el) {
  const gm::Vec3 a = m.points[f[0]], b = m.points[f[1]];
  for (int k = 0; k < m.corners(); ++k) {
    const int q = el[k];
    if (q == f[0] || q == f[1] || q == f[2]) continue;
    const gm::Vec3 w = m.points[q];
    if (m.dimensions == 2) return (b.x - a.x) * (w.y - a.y) - (b.y - a.y) * (w.x - a.x) > 0;  // w on the left
    return gm::tet_volume(a, b, m.points[f[2]], w) < 0;  // w behind a b c's right-hand normal
  }
  return false;
}

// The element holding all of facet f's corners.
std::array<int, 4> element_of(const gm::ElementMesh& m, const std::array<int, 3>& f) {
  for (const auto& el : m.elements) {
    int found = 0;
    for (int k = 0; k < m.dimensions; ++k) found += std::count(el.begin(), el.begin() + m.corners(), f[k]) > 0;
    if (found == m.dimensions) return el;
  }
  return {-1, -1, -1, -1};
}

void check_sides(const gm::ElementMesh& m, std::size_t facets_per_side) {
  const auto facets = gm::side_facets(m);
  REQUIRE(facets.size() == static_cast<std::size_t>(m.sides()));
  for (int s = 0; s < m.sides(); ++s) {
    INFO("side " << gm::side_name(m, s));
    CHECK(facets[s].size() == facets_per_side);
    const int axis = s / 2;
    const double at = s % 2 == 0 ? m.cell.lo[axis] : m.cell.hi[axis];
    for (const auto& f : facets[s]) {
      for (int k = 0; k < m.dimensions; ++k) CHECK(m.points[f[k]][axis] == at);
      if (m.dimensions == 2) CHECK(f[2] == -1);
      CHECK(faces_out(m, f, element_of(m, f)));
    }
  }
}

}  // namespace

TEST_CASE("A plane cell's side facets lie on their side and face out and each high-side point is tied once to its root",
          "[export][element_mesh]") {
  const gm::ElementMesh m = square();
  CHECK(m.elements.size() == 8);
  check_sides(m, 2);
  const auto points = gm::side_points(m);
  CHECK(points[0] == std::vector<int>{0, 3, 6});  // left
  CHECK(points[3] == std::vector<int>{6, 7, 8});  // top
  const std::vector<gm::PeriodicTie> ties = gm::periodic_ties(m);
  REQUIRE(ties.size() == 5);  // right 2, 5, 8 and top 6, 7
  struct Want { int point, root; bool x, y; };
  const std::vector<Want> want{{2, 0, true, false}, {5, 3, true, false}, {6, 0, false, true},
                               {7, 1, false, true}, {8, 0, true, true}};
  for (std::size_t k = 0; k < ties.size(); ++k) {
    INFO("tie of point " << ties[k].point);
    CHECK(ties[k].point == want[k].point);
    CHECK(ties[k].root == want[k].root);
    CHECK(ties[k].across == std::array<bool, 3>{want[k].x, want[k].y, false});
  }
  CHECK(gm::grains_of(m) == std::vector<int>{0, 1});
}

TEST_CASE("A solid cell's side facets face out and its high corner, edges and faces go straight to its low corner",
          "[export][element_mesh]") {
  const gm::ElementMesh m = cube();
  check_sides(m, 2);
  const std::vector<gm::PeriodicTie> ties = gm::periodic_ties(m);
  REQUIRE(ties.size() == 7);
  for (int p = 1; p < 8; ++p) {
    INFO("corner " << p);
    CHECK(ties[p - 1].point == p);
    CHECK(ties[p - 1].root == 0);
    CHECK(ties[p - 1].across == std::array<bool, 3>{(p & 1) != 0, (p & 2) != 0, (p & 4) != 0});
  }
}

TEST_CASE("Periodic pairs that give a point two images across one axis are refused", "[export][element_mesh]") {
  gm::ElementMesh m = square();
  m.pairs.axis[0].push_back({3, 8});  // 8's image across x is 6
  CHECK_THROWS_AS(gm::periodic_ties(m), gm::GeometryError);
}

TEST_CASE("A mesh of polygons is refused as finite elements", "[export][element_mesh]") {
  gm::ExportMesh<2> e;
  e.mesh.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  e.mesh.add_cell(std::vector<int>{0, 1, 2, 3});
  e.grain = e.phase = {0};
  CHECK_THROWS_AS(gm::element_mesh(e), gm::GeometryError);
}
