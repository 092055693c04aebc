#include "mesh/quality.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grainmesh {

double radius_ratio(Vec2 a, Vec2 b, Vec2 c) {
  const double la = norm(b - c), lb = norm(c - a), lc = norm(a - b);
  const double denom = la * lb * lc;
  if (!(denom > 0.0)) return 0.0;
  // 2 r / R = (b + c - a)(c + a - b)(a + b - c) / (a b c)
  return std::max(0.0, (lb + lc - la) * (lc + la - lb) * (la + lb - lc) / denom);
}

std::vector<double> triangle_quality(const TriMesh& mesh) {
  std::vector<double> q(mesh.triangles.size());
  for (std::size_t t = 0; t < q.size(); ++t) {
    const auto& v = mesh.triangles[t];
    q[t] = radius_ratio(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]]);
  }
  return q;
}

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// Interior angle at vertex p of a triangle with neighbours q and r, in degrees.
double angle_deg(Vec2 p, Vec2 q, Vec2 r) {
  const Vec2 u = q - p, v = r - p;
  return std::atan2(std::abs(cross(u, v)), dot(u, v)) * kDeg;
}

// checkMesh's skewness of the extruded face of edge (a, b); extrusion adds nothing out of
// plane: all centres sit at mid-height.
double face_skewness(Vec2 a, Vec2 b, Vec2 owner, Vec2 d) {
  const Vec2 mid = 0.5 * (a + b);
  return checkmesh_skewness(mid, perp(b - a), owner, d, [&](Vec2 u) { return std::abs(dot(u, a - mid)); });
}

}  // namespace

MeshQuality measure_quality(const TriMesh& mesh) {
  MeshQuality m;
  m.triangles = mesh.triangles.size();
  if (m.triangles == 0) return m;

  const std::vector<double> q = triangle_quality(mesh);
  m.q_min = *std::min_element(q.begin(), q.end());
  double sum = 0.0;
  std::size_t below = 0;
  for (double v : q) {
    sum += v;
    below += v < 0.5;
  }
  m.q_mean = sum / static_cast<double>(q.size());
  m.q_below_half = static_cast<double>(below) / static_cast<double>(q.size());

  m.min_angle_deg = 180.0;
  m.max_angle_deg = 0.0;
  std::vector<Vec2> centroid(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t];
    const Vec2 a = mesh.points[v[0]], b = mesh.points[v[1]], c = mesh.points[v[2]];
    for (double ang : {angle_deg(a, b, c), angle_deg(b, c, a), angle_deg(c, a, b)}) {
      m.min_angle_deg = std::min(m.min_angle_deg, ang);
      m.max_angle_deg = std::max(m.max_angle_deg, ang);
    }
    centroid[t] = (a + b + c) / 3.0;
  }

  double sum_non_orth = 0.0;
  std::size_t internal = 0;
  for (const MeshEdge& e : mesh_edges(mesh)) {
    const Vec2 a = mesh.points[e.a], b = mesh.points[e.b];
    const Vec2 owner = centroid[e.left];
    const Vec2 outward = -perp(b - a);  // right of a -> b: out of the left triangle
    if (e.right >= 0) {
      const Vec2 d = centroid[e.right] - owner;
      const double angle = checkmesh_non_orthogonality_deg(d, outward);
      m.max_non_orthogonality_deg = std::max(m.max_non_orthogonality_deg, angle);
      sum_non_orth += angle;
      ++internal;
      m.max_skewness = std::max(m.max_skewness, face_skewness(a, b, owner, d));
    } else {
      const Vec2 d = checkmesh_boundary_d(0.5 * (a + b), outward, owner);
      m.max_skewness = std::max(m.max_skewness, face_skewness(a, b, owner, d));
    }
  }
  if (internal > 0) m.mean_non_orthogonality_deg = sum_non_orth / static_cast<double>(internal);
  return m;
}

}  // namespace grainmesh
