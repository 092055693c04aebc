#include "analysis/stress_recovery.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace grainmesh {

namespace {

// The normal equations of a weighted least-squares fit D(x) = D_P + G (x - x_P) of one
// cell's displacement gradient G, built from samples (dx, dD) with weights 1 / |dx|^2.
struct GradientFit {
  double a11 = 0, a12 = 0, a22 = 0;
  std::array<double, 2> bx{}, by{};

  void add(Vec2 dx, double ux, double uy) {
    const double w = 1.0 / dot(dx, dx);
    a11 += w * dx.x * dx.x, a12 += w * dx.x * dx.y, a22 += w * dx.y * dx.y;
    bx[0] += w * dx.x * ux, bx[1] += w * dx.y * ux;
    by[0] += w * dx.x * uy, by[1] += w * dx.y * uy;
  }
  // dDx/dx, dDx/dy, dDy/dx, dDy/dy; false when the samples span fewer than two directions.
  bool solve(std::array<double, 4>& g) const {
    const double det = a11 * a22 - a12 * a12;
    if (!(det > 1e-12 * (a11 + a22) * (a11 + a22))) return false;
    g = {(a22 * bx[0] - a12 * bx[1]) / det, (a11 * bx[1] - a12 * bx[0]) / det, (a22 * by[0] - a12 * by[1]) / det,
         (a11 * by[1] - a12 * by[0]) / det};
    return true;
  }
};

}  // namespace

std::vector<StressState> recovered_stress(const CaseFields& fields, const ExportMesh<2>& m, const FoamOptions& o) {
  const CellMesh& mesh = m.mesh;
  const std::size_t cells = mesh.cells();
  const double metres = o.convert_to_meters;
  std::vector<Vec2> centre(cells);
  for (std::size_t t = 0; t < cells; ++t) centre[t] = cell_centroid(mesh, t);
  std::vector<Lame> lames;
  std::vector<double> thermal;  // threeK alpha delta_T of each phase
  for (const FoamPhase& p : m.phases) {
    lames.push_back(lame(p, o.plane_stress));
    thermal.push_back(thermal_stress_per_kelvin(p, o.plane_stress) * o.delta_T);
  }
  auto D = [&](int t) { return fields.displacement[static_cast<std::size_t>(t)]; };
  std::vector<GradientFit> fit(cells);

  // The cells of the same phase that share a corner with each cell.
  std::vector<std::vector<int>> at_vertex(mesh.points.size());
  for (std::size_t t = 0; t < cells; ++t)
    for (int v : mesh.cell(t)) at_vertex[v].push_back(static_cast<int>(t));
  std::vector<int> seen;
  for (std::size_t t = 0; t < cells; ++t) {
    seen.clear();
    for (int v : mesh.cell(t))
      for (int q : at_vertex[v])
        if (q != static_cast<int>(t) && m.phase[q] == m.phase[t] && std::find(seen.begin(), seen.end(), q) == seen.end()) {
          seen.push_back(q);
          fit[t].add((centre[q] - centre[t]) * metres, D(q)[0] - D(t)[0], D(q)[1] - D(t)[1]);
        }
  }
  // Across an interface edge, for both cells: the displacement where the line between the
  // two centres crosses it, at which the flux along that line (stiffness times difference
  // over distance, less the thermal stress along the edge's normal) is the same from both
  // sides; exact for a linear field in one phase.
  for (const MeshEdge& e : mesh_edges(mesh)) {
    const int p = e.left, n = e.right;
    if (n < 0 || m.phase[p] == m.phase[n]) continue;
    const Vec2 along = mesh.points[e.b] - mesh.points[e.a];
    auto distance = [&](Vec2 c) { return std::abs(cross(along, c - mesh.points[e.a])) / norm(along); };
    const double dp = distance(centre[p]), dn = distance(centre[n]);
    const Vec2 crossing = centre[p] + (dp / (dp + dn)) * (centre[n] - centre[p]);
    const double wp = lames[m.phase[p]].gamma() / (dp * metres), wn = lames[m.phase[n]].gamma() / (dn * metres);
    // The unit normal from p to n, and the jump the thermal stresses' difference makes.
    Vec2 normal = Vec2{along.y, -along.x} / norm(along);
    if (dot(normal, centre[n] - centre[p]) < 0.0) normal = -normal;
    const Vec2 push = (thermal[m.phase[p]] - thermal[m.phase[n]]) * normal;
    const double fx = (wp * D(p)[0] + wn * D(n)[0] + push.x) / (wp + wn),
                 fy = (wp * D(p)[1] + wn * D(n)[1] + push.y) / (wp + wn);
    for (const int c : {p, n}) fit[c].add((crossing - centre[c]) * metres, fx - D(c)[0], fy - D(c)[1]);
  }

  std::vector<StressState> out = stress_states(fields, o.plane_stress);  // kept where no fit
  for (std::size_t t = 0; t < cells; ++t) {
    std::array<double, 4> g;
    if (!fit[t].solve(g)) continue;
    const Lame& l = lames[m.phase[t]];
    const double trace = g[0] + g[3], heat = thermal[m.phase[t]];
    out[t] = {.xx = l.lambda * trace + 2 * l.mu * g[0] - heat,
              .yy = l.lambda * trace + 2 * l.mu * g[3] - heat,
              .zz = o.plane_stress ? 0.0 : l.lambda * trace - heat,
              .xy = l.mu * (g[1] + g[2])};
  }
  return out;
}

}  // namespace grainmesh
