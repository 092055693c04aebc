#include "view/box_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "common/errors.hpp"

namespace grainmesh {
namespace {

Vec3 unit(Vec3 v) { return (1.0 / norm(v)) * v; }

// The side of the box [lo, hi] all of a, b, c lie on (axis * 2 + 0 low, + 1 high), or -1.
int common_side(Vec3 a, Vec3 b, Vec3 c, Vec3 lo, Vec3 hi, double tol) {
  for (int axis = 0; axis < 3; ++axis)
    for (int high = 0; high < 2; ++high) {
      const double at = high ? hi[axis] : lo[axis];
      if (std::abs(a[axis] - at) <= tol && std::abs(b[axis] - at) <= tol && std::abs(c[axis] - at) <= tol)
        return 2 * axis + high;
    }
  return -1;
}

}  // namespace

Vec3 box_view_direction() {
  constexpr double round = 35.0 * std::numbers::pi / 180.0, up = 25.0 * std::numbers::pi / 180.0;
  return {std::cos(up) * std::sin(round), -std::cos(up) * std::cos(round), std::sin(up)};
}

BoxView box_view(const TetMesh& mesh) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Vec3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
  for (const Vec3& p : mesh.points)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  const double tol = 1e-9 * std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 0.0});
  // The picture plane's axes: right, and up (the cell's z leaning towards the viewer).
  const Vec3 view = box_view_direction();
  const Vec3 right = unit(cross(Vec3{0.0, 0.0, 1.0}, view)), up = cross(view, right);
  // Light from above and left of the viewer: the three sides in three brightnesses.
  const Vec3 light = unit(view + Vec3{-0.4, 0.0, 0.9});
  BoxView out;
  std::vector<int> point(mesh.points.size(), -1);
  auto projected = [&](int p) {
    if (point[p] < 0) {
      point[p] = static_cast<int>(out.mesh.points.size());
      out.mesh.points.push_back({dot(mesh.points[p], right), dot(mesh.points[p], up)});
    }
    return point[p];
  };
  static constexpr int kFace[4][4] = {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};  // corners, opposite
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (const auto& f : kFace) {
      int a = mesh.tets[t][f[0]], b = mesh.tets[t][f[1]], c = mesh.tets[t][f[2]];
      const Vec3 &pa = mesh.points[a], &pb = mesh.points[b], &pc = mesh.points[c];
      const int side = common_side(pa, pb, pc, lo, hi, tol);
      if (side < 0) continue;
      Vec3 n{};  // the side's outward normal: one brightness for all its triangles
      n[side / 2] = side % 2 ? 1.0 : -1.0;
      if (!(dot(n, view) > 0.0)) continue;                         // a side facing away
      if (dot(cross(pb - pa, pc - pa), n) < 0.0) std::swap(b, c);  // outward
      out.mesh.triangles.push_back({projected(a), projected(b), projected(c)});
      out.tet.push_back(static_cast<int>(t));
      out.side.push_back(side);
      out.shade.push_back(0.55 + 0.45 * std::max(0.0, dot(n, light)));
    }
  if (out.mesh.triangles.empty()) throw GeometryError("nothing to draw: no side of the cell faces the viewer");
  return out;
}

std::vector<int> BoxView::outline(const std::vector<int>& grain) const {
  std::vector<int> out;
  for (std::size_t k = 0; k < tet.size(); ++k) out.push_back(6 * grain[static_cast<std::size_t>(tet[k])] + side[k]);
  return out;
}

}  // namespace grainmesh
