#include "view/box_view.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "common/errors.hpp"

namespace grainmesh {
namespace {

Vec3 unit(Vec3 v) { return (1.0 / norm(v)) * v; }

// The bounding box of points, and a tolerance for "on a side" of 1e-9 of its size.
struct Bounds {
  Vec3 lo, hi;
  double tol = 0.0;
  explicit Bounds(const std::vector<Vec3>& points) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    lo = {kInf, kInf, kInf}, hi = {-kInf, -kInf, -kInf};
    for (const Vec3& p : points)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    tol = 1e-9 * std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 0.0});
  }
  // The side all of `corners` lie on (axis * 2 + 0 low, + 1 high), or -1.
  template <typename Points>
  int common_side(const Points& corners) const {
    for (int axis = 0; axis < 3; ++axis)
      for (int high = 0; high < 2; ++high) {
        const double at = high ? hi[axis] : lo[axis];
        bool on = true;
        for (const Vec3& p : corners) on = on && std::abs(p[axis] - at) <= tol;
        if (on) return 2 * axis + high;
      }
    return -1;
  }
};

// The view under construction: triangles on the box's sides, kept and projected when their
// side faces the viewer.
class ViewBuilder {
 public:
  explicit ViewBuilder(const std::vector<Vec3>& points) : points_(points), projected_(points.size(), -1) {
    view_ = box_view_direction();
    right_ = unit(cross(Vec3{0.0, 0.0, 1.0}, view_));  // the picture plane's axes: right, and up
    up_ = cross(view_, right_);
    light_ = unit(view_ + Vec3{-0.4, 0.0, 0.9});  // from above and left of the viewer
  }
  // Whether side `side` faces the viewer.
  bool shows(int side) const { return dot(normal(side), view_) > 0.0; }
  // Triangle a b c (ids into the points) on side `side`, from `source`; turned outward.
  void add(int a, int b, int c, int side, int source) {
    const Vec3 n = normal(side);
    const Vec3 pa = position(a), pb = position(b), pc = position(c);
    if (dot(cross(pb - pa, pc - pa), n) < 0.0) std::swap(b, c);
    out_.mesh.triangles.push_back({projected(a), projected(b), projected(c)});
    out_.tet.push_back(source);
    out_.side.push_back(side);
    out_.shade.push_back(0.55 + 0.45 * std::max(0.0, dot(n, light_)));
  }
  // A point of the view's own (not one of the points'); its id for add().
  int extra(Vec3 p) {
    extra_.push_back(p);
    projected_.push_back(-1);
    return static_cast<int>(points_.size() + extra_.size() - 1);
  }
  BoxView take() {
    if (out_.mesh.triangles.empty()) throw GeometryError("nothing to draw: no side of the cell faces the viewer");
    return std::move(out_);
  }

 private:
  static Vec3 normal(int side) {
    Vec3 n{};
    n[side / 2] = side % 2 ? 1.0 : -1.0;
    return n;
  }
  Vec3 position(int id) const {
    return id < static_cast<int>(points_.size()) ? points_[static_cast<std::size_t>(id)]
                                                 : extra_[static_cast<std::size_t>(id) - points_.size()];
  }
  int projected(int id) {
    int& at = projected_[static_cast<std::size_t>(id)];
    if (at < 0) {
      at = static_cast<int>(out_.mesh.points.size());
      const Vec3 p = position(id);
      out_.mesh.points.push_back({dot(p, right_), dot(p, up_)});
    }
    return at;
  }

  const std::vector<Vec3>& points_;
  std::vector<Vec3> extra_;
  std::vector<int> projected_;
  Vec3 view_, right_, up_, light_;
  BoxView out_;
};

}  // namespace

Vec3 box_view_direction() {
  constexpr double round = 35.0 * std::numbers::pi / 180.0, up = 25.0 * std::numbers::pi / 180.0;
  return {std::cos(up) * std::sin(round), -std::cos(up) * std::cos(round), std::sin(up)};
}

BoxView box_view(const TetMesh& mesh) {
  const Bounds bounds(mesh.points);
  ViewBuilder view(mesh.points);
  static constexpr int kFace[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (const auto& f : kFace) {
      const int a = mesh.tets[t][f[0]], b = mesh.tets[t][f[1]], c = mesh.tets[t][f[2]];
      const int side = bounds.common_side(std::array{mesh.points[a], mesh.points[b], mesh.points[c]});
      if (side >= 0 && view.shows(side)) view.add(a, b, c, side, static_cast<int>(t));
    }
  return view.take();
}

BoxView box_view(const Tessellation3& t) {
  const Bounds bounds(t.vertices);
  ViewBuilder view(t.vertices);
  for (const Face3& f : t.faces) {
    if ((f.back >= 0) == (f.front >= 0) || f.ring.size() < 3) continue;  // inside, or not a polygon
    std::vector<Vec3> corners;
    Vec3 centre{};
    for (const int v : f.ring) corners.push_back(t.vertices[static_cast<std::size_t>(v)]), centre += corners.back();
    const int side = bounds.common_side(corners);
    if (side < 0 || !view.shows(side)) continue;
    // Fanned from its centre: a convex face's corners in a row along a side give no flat triangle.
    const int mid = view.extra((1.0 / static_cast<double>(corners.size())) * centre);
    for (std::size_t k = 0; k < f.ring.size(); ++k)
      view.add(mid, f.ring[k], f.ring[(k + 1) % f.ring.size()], side, std::max(f.back, f.front));
  }
  return view.take();
}

std::vector<int> BoxView::outline(const std::vector<int>& grain) const {
  std::vector<int> out;
  for (std::size_t k = 0; k < tet.size(); ++k) out.push_back(6 * grain[static_cast<std::size_t>(tet[k])] + side[k]);
  return out;
}

}  // namespace grainmesh
