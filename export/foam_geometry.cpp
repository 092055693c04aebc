// OpenFOAM's geometry of a polyMesh (primitiveMesh's face centres and areas, cell
// centres and volumes), so that what grainmesh computes from a case's fields uses the
// centres and volumes the solver used.
#include "export/foam_geometry.hpp"

#include <algorithm>

#include "export/polymesh.hpp"

namespace grainmesh {

FoamFace foam_face(const PolyMesh& pm, int f) {
  const int first = pm.face_start[f], n = pm.face_start[f + 1] - first;
  // A 2D mesh's points are extruded: its points at z = 0, then at z = thickness.
  const int n2 = static_cast<int>(pm.points2d.size());
  auto point = [&](int k) {
    const int p = pm.face_points[first + k % n];
    if (pm.points2d.empty()) return pm.points3d[p];
    const Vec2 q = pm.points2d[p % n2];
    return Vec3{q.x, q.y, p < n2 ? 0.0 : pm.thickness};
  };
  if (n == 3) return {0.5 * cross(point(1) - point(0), point(2) - point(0)), (point(0) + point(1) + point(2)) / 3.0};
  Vec3 mean;
  for (int k = 0; k < n; ++k) mean += point(k);
  mean = mean / n;
  Vec3 S, sum_c;
  double sum_a = 0.0;
  for (int k = 0; k < n; ++k) {
    const Vec3 t = cross(point(k + 1) - point(k), mean - point(k));
    const double a = norm(t);
    S += 0.5 * t;
    sum_c += a * (point(k) + point(k + 1) + mean);
    sum_a += a;
  }
  return {S, sum_c / (3.0 * sum_a)};
}

void foam_cell_geometry(const PolyMesh& pm, std::vector<Vec3>& centre, std::vector<double>& volume) {
  const std::size_t cells = static_cast<std::size_t>(pm.cells);
  std::vector<FoamFace> face(static_cast<std::size_t>(pm.faces()));
  for (int f = 0; f < pm.faces(); ++f) face[f] = foam_face(pm, f);
  // The estimate: the mean of the cell's face centres.
  std::vector<Vec3> estimate(cells);
  std::vector<int> faces_of(cells, 0);
  auto each_side = [&](auto&& visit) {
    for (int f = 0; f < pm.faces(); ++f) {
      visit(f, pm.owner[f], false);
      if (f < pm.internal_faces()) visit(f, pm.neighbour[f], true);
    }
  };
  each_side([&](int f, int c, bool) {
    estimate[c] += face[f].centre;
    ++faces_of[c];
  });
  for (std::size_t c = 0; c < cells; ++c) estimate[c] = estimate[c] / std::max(faces_of[c], 1);
  // Each face's pyramid to the estimate: three times its volume, its centroid.
  centre.assign(cells, Vec3{});
  volume.assign(cells, 0.0);
  each_side([&](int f, int c, bool neighbour) {
    const double v3 = dot(face[f].area, face[f].centre - estimate[c]) * (neighbour ? -1.0 : 1.0);
    centre[c] += v3 * (0.75 * face[f].centre + 0.25 * estimate[c]);
    volume[c] += v3;
  });
  for (std::size_t c = 0; c < cells; ++c) {
    centre[c] = centre[c] / volume[c];
    volume[c] /= 3.0;
  }
}

}  // namespace grainmesh
