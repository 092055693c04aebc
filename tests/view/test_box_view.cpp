#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "common/errors.hpp"
#include "mesh/trimesh.hpp"
#include "view/box_view.hpp"

using namespace grainmesh;

namespace {

// The box [0, W] x [0, H] x [0, D] in n x n x n bricks, each split into six tetrahedra
// along its main diagonal (Kuhn's split).
TetMesh brick_mesh(double W, double H, double D, int n) {
  TetMesh m;
  auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.points.push_back({W * i / n, H * j / n, D * k / n});
  static constexpr std::array<std::array<int, 3>, 6> kOrders{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& order : kOrders) {
          std::array<int, 3> at{i, j, k};
          std::array<int, 4> tet{id(i, j, k), 0, 0, 0};
          for (int s = 0; s < 3; ++s) {
            ++at[static_cast<std::size_t>(order[static_cast<std::size_t>(s)])];
            tet[static_cast<std::size_t>(s) + 1] = id(at[0], at[1], at[2]);
          }
          m.tets.push_back(tet);
        }
  return m;
}

}  // namespace

TEST_CASE("a 3D view shows the three sides facing the viewer, each projected by its cosine", "[view]") {
  const double W = 2.0, H = 1.0, D = 0.5;
  const TetMesh m = brick_mesh(W, H, D, 3);
  const BoxView view = box_view(m);
  // Three sides of 9 bricks' faces, two triangles each.
  REQUIRE(view.mesh.triangles.size() == 3 * 9 * 2);
  REQUIRE(view.tet.size() == view.mesh.triangles.size());
  // Counter-clockwise and one manifold sheet (mesh_edges throws otherwise): the picture
  // plane is covered once, by the sides' areas times their normals' cosines to the viewer.
  for (int t = 0; t < static_cast<int>(view.mesh.triangles.size()); ++t) CHECK(triangle_area(view.mesh, t) > 0.0);
  CHECK_NOTHROW(mesh_edges(view.mesh));
  const Vec3 v = box_view_direction();
  CHECK(v.x > 0.0);
  CHECK(v.y < 0.0);
  CHECK(v.z > 0.0);
  CHECK(mesh_area(view.mesh) == Approx(H * D * v.x - W * D * v.y + W * H * v.z).epsilon(1e-12));
  // Each side one brightness, three apart.
  std::vector<double> shades = view.shade;
  std::sort(shades.begin(), shades.end());
  shades.erase(std::unique(shades.begin(), shades.end()), shades.end());
  CHECK(shades.size() == 3);
  for (const double s : shades) CHECK((s > 0.5 && s <= 1.0));
  // The sides x = W, y = 0 and z = D, the brighter the more they face the light above.
  std::set<int> sides(view.side.begin(), view.side.end());
  CHECK(sides == std::set<int>{1, 2, 5});
  // One grain: the outline labels part the sides alone, so the box's edges are drawn.
  const std::vector<int> one_grain(m.tets.size(), 0);
  CHECK(view.outline(one_grain) == view.side);
  CHECK_THROWS_AS(box_view(TetMesh{}), GeometryError);
}

TEST_CASE("a 3D tessellation's view: its box faces fanned from their centres, corners in a row giving no flat triangle",
          "[view]") {
  // One region filling the box W x H x D; the top face and the front face (y = 0) share
  // the edge z = D, y = 0, split at its middle by a vertex of both.
  const double W = 2.0, H = 1.0, D = 0.5;
  Tessellation3 t;
  t.width = W, t.height = H, t.depth = D;
  for (int k = 0; k < 8; ++k) t.vertices.push_back({k & 1 ? W : 0.0, k & 2 ? H : 0.0, k & 4 ? D : 0.0});
  t.vertices.push_back({0.5 * W, 0.0, D});  // 8: the middle of the edge from 4 to 5
  // Rings turning counter-clockwise seen from outside (right-hand normal outward: back 0, front -1).
  const std::vector<std::vector<int>> rings{{0, 2, 3, 1}, {4, 8, 5, 7, 6}, {0, 1, 5, 8, 4},
                                            {2, 6, 7, 3}, {0, 4, 6, 2},    {1, 3, 7, 5}};
  Region3 region;
  for (std::size_t f = 0; f < rings.size(); ++f) {
    t.faces.push_back(Face3{rings[f], 0, -1});
    region.faces.push_back(static_cast<int>(f));
  }
  t.regions.push_back(region);
  const BoxView view = box_view(t);
  // The top (5 corners), front (5) and right (4) sides, each corner's triangle from the centre.
  REQUIRE(view.mesh.triangles.size() == 5 + 5 + 4);
  for (int k = 0; k < static_cast<int>(view.mesh.triangles.size()); ++k) CHECK(triangle_area(view.mesh, k) > 0.0);
  CHECK_NOTHROW(mesh_edges(view.mesh));
  const Vec3 v = box_view_direction();
  CHECK(mesh_area(view.mesh) == Approx(H * D * v.x - W * D * v.y + W * H * v.z).epsilon(1e-12));
  for (const int r : view.tet) CHECK(r == 0);
}
