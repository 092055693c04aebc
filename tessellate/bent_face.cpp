#include "tessellate/bent_face.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace grainmesh {

int side_mask(Vec3 p, Vec3 box) {
  int m = 0;
  for (int a = 0; a < 3; ++a) {
    if (p[a] == 0.0) m |= 1 << (2 * a);
    if (p[a] == box[a]) m |= 1 << (2 * a + 1);
  }
  return m;
}

namespace {

// The smallest angle is the largest cosine's: one arc cosine, not three (it was the
// 3D tessellation's costliest call at 1,000 grains).
double smallest_angle(Vec3 a, Vec3 b, Vec3 c) {
  auto cosine = [](Vec3 u, Vec3 v) { return std::clamp(dot(u, v) / (norm(u) * norm(v)), -1.0, 1.0); };
  return std::acos(std::max({cosine(b - a, c - a), cosine(a - b, c - b), cosine(a - c, b - c)}));
}

// The ring's centroid and unit Newell normal; a zero normal for a degenerate ring.
std::pair<Vec3, Vec3> centre_and_normal(const std::vector<Vec3>& p, const std::vector<int>& ring) {
  const int n = static_cast<int>(ring.size());
  Vec3 c{}, normal{};
  for (int v : ring) c += p[v];
  c = c / static_cast<double>(n);
  for (int k = 0; k < n; ++k) normal += cross(p[ring[k]] - c, p[ring[(k + 1) % n]] - c);
  const double len = norm(normal);
  return {c, len > 0.0 ? normal / len : Vec3{}};
}

// A triangle of a split turns with the face (and is not flat): its normal within
// acos(cosine) of the face's.
bool turns_with(Vec3 a, Vec3 b, Vec3 d, Vec3 normal, double cosine = 1e-3) {
  const Vec3 m = cross(b - a, d - a);
  return dot(m, normal) > cosine * norm(m);
}

}  // namespace

double smallest_angle(const std::vector<Vec3>& p, const std::vector<std::array<int, 3>>& triangles) {
  double least = std::numbers::pi;
  for (const auto& [a, b, c] : triangles) least = std::min(least, smallest_angle(p[a], p[b], p[c]));
  return least;
}

CentreFan centre_fan(const std::vector<Vec3>& p, const std::vector<int>& ring) {
  const auto [c, normal] = centre_and_normal(p, ring);
  CentreFan fan{.valid = norm(normal) > 0.0, .centre = c, .smallest_angle = std::numbers::pi};
  for (std::size_t k = 0; k < ring.size() && fan.valid; ++k) {
    const Vec3 a = p[ring[k]], b = p[ring[(k + 1) % ring.size()]];
    fan.valid = turns_with(c, a, b, normal);
    fan.smallest_angle = std::min(fan.smallest_angle, smallest_angle(c, a, b));
  }
  return fan;
}

FaceShape face_shape(const std::vector<Vec3>& p, const std::vector<int>& ring, double flat, Vec3 box) {
  FaceShape shape;
  const int n = static_cast<int>(ring.size());
  const auto [c, normal] = centre_and_normal(p, ring);
  if (!(norm(normal) > 0.0)) return {.planar = false, .valid = false, .triangles = {}};
  double off = 0.0;
  for (int v : ring) off = std::max(off, std::abs(dot(p[v] - c, normal)));
  if (n == 3 || off <= flat) return shape;
  shape.planar = false;
  // best[i][j]: the best smallest angle of the polygon ring[i..j] closed by the chord j-i.
  constexpr double kNone = -1.0;
  std::vector<std::vector<double>> best(n, std::vector<double>(n, kNone));
  std::vector<std::vector<int>> apex(n, std::vector<int>(n, -1));
  for (int i = 0; i + 1 < n; ++i) best[i][i + 1] = std::numbers::pi;
  for (int span = 2; span < n; ++span)
    for (int i = 0; i + span < n; ++i) {
      const int j = i + span;
      // A diagonal between two points on one side of the box lies in that side, where the
      // box face is: not a chord of a face inside.
      auto chord_ok = [&](int x, int y) { return y - x == 1 || (x == 0 && y == n - 1) || (side_mask(p[ring[x]], box) & side_mask(p[ring[y]], box)) == 0; };
      for (int k = i + 1; k < j; ++k) {
        if (!chord_ok(i, k) || !chord_ok(k, j) || !chord_ok(i, j)) continue;
        const Vec3 a = p[ring[i]], b = p[ring[k]], d = p[ring[j]];
        if (!turns_with(a, b, d, normal)) continue;
        const double q = std::min({best[i][k], best[k][j], smallest_angle(a, b, d)});
        if (best[i][k] >= 0.0 && best[k][j] >= 0.0 && q > best[i][j]) {
          best[i][j] = q;
          apex[i][j] = k;
        }
      }
    }
  if (best[0][n - 1] <= 0.0) return {.planar = false, .valid = false, .triangles = {}};
  std::vector<std::pair<int, int>> todo{{0, n - 1}};
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    if (j - i < 2) continue;
    const int k = apex[i][j];
    shape.triangles.push_back({ring[i], ring[k], ring[j]});
    todo.emplace_back(i, k);
    todo.emplace_back(k, j);
  }
  return shape;
}

}  // namespace grainmesh
