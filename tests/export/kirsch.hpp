// Kirsch's plate with a hole: the quarter plate of OpenFOAM's plateHole tutorial (20 x 20,
// a hole of radius 0.5, 10 kPa pulling along x) meshed by the domain stage, and the exact
// stress of an infinite plate the tests and bench_dual hold its solution to.
#pragma once

#include <cmath>
#include <string>

#include "export/export_mesh.hpp"
#include "pipelines/config.hpp"
#include "pipelines/domain_command.hpp"

namespace grainmesh::test {

inline constexpr double kHoleRadius = 0.5, kPlateTraction = 1e4;

// Kirsch: sigma_xx at p (from the hole's centre) of an infinite plate under
// kPlateTraction along x with a hole of radius kHoleRadius.
inline double kirsch_sigma_xx(Vec2 p) {
  const double R = kHoleRadius, T = kPlateTraction;
  const double rr = norm(p), th = std::atan2(p.y, p.x), a = R * R / (rr * rr);
  return T * (1 - a * (1.5 * std::cos(2 * th) + std::cos(4 * th)) + 1.5 * a * a * std::cos(4 * th));
}

// The quarter plate (symmetry on the left and bottom), graded from h0 at the hole (growing
// by 0.15 h0 per h0 up to 16 h0), as one steel phase in triangles. No point is fixed, as
// in OpenFOAM's tutorial: the mesher finds the corners where the hole meets the symmetry
// lines at the h0 used here (not at every h0: at 0.018343 it misses the top one).
inline ExportMesh<2> plate_with_hole(double h0 = 0.025) {
  const std::string h = std::to_string(h0);
  const Config c = Config::from_text(
      "[domain]\nshape = difference(polygon(0 0, 10 0, 10 10, 0 10), circle(0, 0, 0.5))\n"
      "[size]\nh0 = " + h + "\nfunction = min(1 + 0.15*(sqrt(x^2+y^2) - 0.5)/" + h + ", 16)\n",
      "plate_hole.ini");
  const DistMeshResult r = mesh_domain(read_domain_job(c));
  ExportMesh<2> e;
  e.mesh = cell_mesh(r.mesh);
  e.phase.assign(r.mesh.triangles.size(), 0);
  e.grain = e.phase;
  e.phases = {{"steel", 2e11, 0.3}};
  for (const Vec2 p : r.mesh.points) e.cell.extend(p);
  return e;
}

}  // namespace grainmesh::test
