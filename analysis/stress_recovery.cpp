#include "analysis/stress_recovery.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "analysis/phase_statistics.hpp"

namespace grainmesh {

std::vector<StressState> recovered_stress(const CaseFields& fields, const ExportMesh& m, const FoamOptions& o) {
  const TriMesh& mesh = m.mesh;
  const std::size_t cells = mesh.triangles.size();
  std::vector<StressState> out = stress_states(fields, o.plane_stress);  // the fallback
  std::vector<std::vector<int>> at_vertex(mesh.points.size());
  std::map<std::pair<int, int>, std::array<int, 2>> at_edge;
  for (std::size_t t = 0; t < cells; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      at_vertex[a].push_back(static_cast<int>(t));
      auto [it, fresh] = at_edge.try_emplace(std::minmax(a, b), std::array<int, 2>{static_cast<int>(t), -1});
      if (!fresh) it->second[1] = static_cast<int>(t);
    }
  std::vector<Vec2> centre(cells);
  for (std::size_t t = 0; t < cells; ++t) centre[t] = triangle_centroid(mesh, static_cast<int>(t));
  std::vector<Lame> lames;
  for (const FoamPhase& p : m.phases) lames.push_back(lame(p, o.plane_stress));
  const double metres = o.convert_to_meters;
  std::vector<int> seen;  // the own-phase cells around the current one

  for (std::size_t t = 0; t < cells; ++t) {
    const int phase = m.phase[t];
    const double* Dp = fields.displacement[t];
    // Normal equations of the weighted fit D(x) = D_P + G (x - x_P), weights 1 / |dx|^2.
    double a11 = 0, a12 = 0, a22 = 0;
    std::array<double, 2> bx{}, by{};
    auto use = [&](Vec2 dx, double ux, double uy, double weight) {
      const double w = weight / dot(dx, dx);
      a11 += w * dx.x * dx.x, a12 += w * dx.x * dx.y, a22 += w * dx.y * dx.y;
      bx[0] += w * dx.x * ux, bx[1] += w * dx.y * ux;
      by[0] += w * dx.x * uy, by[1] += w * dx.y * uy;
    };
    seen.clear();
    for (int v : mesh.triangles[t])
      for (int q : at_vertex[v]) {
        if (q == static_cast<int>(t) || m.phase[q] != phase) continue;
        if (std::find(seen.begin(), seen.end(), q) != seen.end()) continue;
        seen.push_back(q);
        const double* Dq = fields.displacement[q];
        use((centre[q] - centre[t]) * metres, Dq[0] - Dp[0], Dq[1] - Dp[1], 1.0);
      }
    // Across an interface edge: the displacement where the line between the two cells'
    // centres crosses it, at which the flux along that line (stiffness times difference
    // over distance) is the same from both sides; exact for a linear field in one phase.
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      const auto& pair = at_edge.at(std::minmax(a, b));
      const int n = pair[0] == static_cast<int>(t) ? pair[1] : pair[0];
      if (n < 0 || m.phase[n] == phase) continue;
      const Vec2 along = mesh.points[b] - mesh.points[a];
      auto distance = [&](Vec2 c) { return std::abs(cross(along, c - mesh.points[a])) / norm(along); };
      const double dp = distance(centre[t]), dn = distance(centre[n]);
      const Vec2 crossing = centre[t] + (dp / (dp + dn)) * (centre[n] - centre[t]);
      const double wp = lames[phase].gamma() / dp, wn = lames[m.phase[n]].gamma() / dn;
      const double* Dn = fields.displacement[n];
      const double fx = (wp * Dp[0] + wn * Dn[0]) / (wp + wn), fy = (wp * Dp[1] + wn * Dn[1]) / (wp + wn);
      use((crossing - centre[t]) * metres, fx - Dp[0], fy - Dp[1], 1.0);
    }
    const double det = a11 * a22 - a12 * a12;
    if (!(det > 1e-12 * (a11 + a22) * (a11 + a22))) continue;  // keeps the solver's stress
    const double gxx = (a22 * bx[0] - a12 * bx[1]) / det, gxy = (a11 * bx[1] - a12 * bx[0]) / det;
    const double gyx = (a22 * by[0] - a12 * by[1]) / det, gyy = (a11 * by[1] - a12 * by[0]) / det;
    const Lame& l = lames[phase];
    const double trace = gxx + gyy;
    out[t] = {.xx = l.lambda * trace + 2 * l.mu * gxx,
              .yy = l.lambda * trace + 2 * l.mu * gyy,
              .zz = o.plane_stress ? 0.0 : l.lambda * trace,
              .xy = l.mu * (gxy + gyx)};
  }
  return out;
}

}  // namespace grainmesh
