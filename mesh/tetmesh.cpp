#include "mesh/tetmesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grainmesh {

double tet_volume(Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return dot(d - a, cross(b - a, c - a)) / 6.0; }

namespace {

// Six times the volume (unsigned) and twice the areas of the faces opposite a, b, c and d:
// what the radius ratio and the dihedral sines share.
struct Faces {
  double six_v, fa, fb, fc, fd;
};
Faces faces(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  return {std::abs(dot(w, cross(u, v))), norm(cross(c - b, d - b)), norm(cross(v, w)), norm(cross(u, w)),
          norm(cross(u, v))};
}

double radius_ratio(Vec3 a, Vec3 b, Vec3 c, Vec3 d, const Faces& f) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double area = f.fd + f.fc + f.fb + f.fa;  // x 2
  // Flat to rounding (a volume below 1e-12 of the longest edge's cube): 0, not the ratio of
  // two rounding errors (four points on a circle gave infinity).
  const double longest = std::sqrt(std::max({dot(u, u), dot(v, v), dot(w, w), dot(c - b, c - b), dot(d - b, d - b),
                                             dot(d - c, d - c)}));
  if (!(f.six_v > 6e-12 * longest * longest * longest)) return 0.0;
  const double r_in = f.six_v / area;  // 3 V / (sum of face areas), with both factors of 2 cancelling
  // Circumcentre relative to a: (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 u . (v x w)).
  const Vec3 num = dot(u, u) * cross(v, w) + dot(v, v) * cross(w, u) + dot(w, w) * cross(u, v);
  const double r_circ = norm(num) / (2.0 * f.six_v);
  return 3.0 * r_in / r_circ;
}

double dihedral_sine_ratio(Vec3 a, Vec3 b, Vec3 c, Vec3 d, const Faces& f) {
  if (!(f.fa > 0.0 && f.fb > 0.0 && f.fc > 0.0 && f.fd > 0.0)) return 0.0;
  // Edge ij lies on the two faces opposite the other two corners.
  const double lowest = std::min({norm(b - a) / (f.fc * f.fd), norm(c - a) / (f.fb * f.fd), norm(d - a) / (f.fb * f.fc),
                                  norm(c - b) / (f.fa * f.fd), norm(d - b) / (f.fa * f.fc), norm(d - c) / (f.fa * f.fb)});
  // 3 V |e| / (2 A1 A2) with V = six_v / 6 and A = f / 2: six_v |e| / (f1 f2).
  constexpr double regular = 2.0 * std::numbers::sqrt2 / 3.0;
  return f.six_v * lowest / regular;
}

}  // namespace

double radius_ratio(Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return radius_ratio(a, b, c, d, faces(a, b, c, d)); }

double dihedral_sine_ratio(Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return dihedral_sine_ratio(a, b, c, d, faces(a, b, c, d)); }

TetShape tet_shape(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const Faces f = faces(a, b, c, d);
  return {radius_ratio(a, b, c, d, f), dihedral_sine_ratio(a, b, c, d, f)};
}

std::array<double, 6> dihedral_angles(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const std::array<Vec3, 4> p{a, b, c, d};
  constexpr int edge[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  std::array<double, 6> out{};
  for (int k = 0; k < 6; ++k) {
    // The angle between the two faces at edge ij: between k and l projected across it.
    const Vec3 o = p[edge[k][0]], e = p[edge[k][1]] - o;
    const double e2 = dot(e, e);
    Vec3 s = p[edge[k][2]] - o, t = p[edge[k][3]] - o;
    s = s - (dot(s, e) / e2) * e;
    t = t - (dot(t, e) / e2) * e;
    out[k] = std::acos(std::clamp(dot(s, t) / (norm(s) * norm(t)), -1.0, 1.0));
  }
  return out;
}

double regular_tet_volume(double edge) { return edge * edge * edge / (6.0 * std::sqrt(2.0)); }
double regular_tet_edge(double volume) { return std::cbrt(6.0 * std::sqrt(2.0) * volume); }

TetQuality measure_quality(const TetMesh& mesh) {
  TetQuality q;
  if (mesh.tets.empty()) return q;
  q.q_min = 1.0;
  q.min_dihedral_deg = 180.0;
  double sum = 0.0;
  std::size_t below = 0;
  constexpr double kDeg = 180.0 / std::numbers::pi;
  for (const auto& t : mesh.tets) {
    const Vec3 a = mesh.points[t[0]], b = mesh.points[t[1]], c = mesh.points[t[2]], d = mesh.points[t[3]];
    const double r = radius_ratio(a, b, c, d);
    q.q_min = std::min(q.q_min, r);
    sum += r;
    const auto angles = dihedral_angles(a, b, c, d);
    const double lo = *std::min_element(angles.begin(), angles.end()) * kDeg;
    q.min_dihedral_deg = std::min(q.min_dihedral_deg, lo);
    q.max_dihedral_deg = std::max(q.max_dihedral_deg, *std::max_element(angles.begin(), angles.end()) * kDeg);
    below += lo < 10.0;
  }
  q.q_mean = sum / static_cast<double>(mesh.tets.size());
  q.share_dihedral_below_10 = static_cast<double>(below) / static_cast<double>(mesh.tets.size());
  return q;
}

}  // namespace grainmesh
