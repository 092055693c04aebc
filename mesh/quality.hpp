// Quality measures for triangle meshes: shape measures of the triangles, and the
// finite-volume measures OpenFOAM's checkMesh reports for the mesh extruded one cell
// thick (prisms), so a mesh can be judged before it is exported.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "common/geometry.hpp"
#include "mesh/trimesh.hpp"

namespace grainmesh {

// Radius ratio q = 2 r_in / r_circ: 1 for an equilateral triangle, 0 for a degenerate one.
double radius_ratio(Vec2 a, Vec2 b, Vec2 c);

// checkMesh's skewness of a face, 2D (an extruded edge) or 3D alike: with its centre and
// area vector (any multiple of its normal will do), the owner's centre and d towards the
// neighbour's (on a boundary: the normal part of owner -> face centre), the distance from
// the face centre to where the line from the owner along d pierces the face's plane, over
// the larger of 0.2 |d| and the face's extent that way: extent(u) is its corners' largest
// |u . (corner - centre)| for the unit vector u.
template <class V, class Extent>
double checkmesh_skewness(V centre, V area, V owner, V d, Extent&& extent) {
  const V cpf = centre - owner;
  const double across = dot(area, d);
  const V sv = cpf - (dot(area, cpf) / (across == 0.0 ? 1e-300 : across)) * d;
  const double length = norm(sv);
  if (length == 0.0) return 0.0;
  return length / std::max(0.2 * norm(d), extent(sv / length));
}

// checkMesh's non-orthogonality of an internal (or coupled) face, 2D or 3D alike: the angle
// in degrees between d, owner -> neighbour centre, and the face's area vector.
template <class V>
double checkmesh_non_orthogonality_deg(V d, V area) {
  const double cosine = std::clamp(dot(d, area) / (norm(d) * norm(area)), -1.0, 1.0);
  return std::acos(cosine) * (180.0 / std::numbers::pi);
}

// checkMesh's d on a boundary face, for its skewness: the normal part of owner -> centre.
template <class V>
V checkmesh_boundary_d(V centre, V area, V owner) {
  const V n = area / norm(area);
  return dot(n, centre - owner) * n;
}

// q of every triangle (#T).
std::vector<double> triangle_quality(const TriMesh& mesh);

struct MeshQuality {
  std::size_t triangles = 0;
  double q_min = 0.0, q_mean = 0.0;
  double q_below_half = 0.0;   // share of triangles with q < 0.5, in [0, 1]
  double min_angle_deg = 0.0, max_angle_deg = 0.0;
  // checkMesh's face non-orthogonality: angle between the owner->neighbour centre vector
  // and the face normal, over internal faces (0 when there are none); the max is
  // checkMesh's, the mean the mean angle (checkMesh's "average" is the angle of the mean
  // cosine, a little larger).
  double max_non_orthogonality_deg = 0.0, mean_non_orthogonality_deg = 0.0;
  // checkMesh's face skewness over internal and boundary faces of the extruded mesh.
  double max_skewness = 0.0;
};

// Measures a non-empty mesh. Uses mesh_edges(), so throws on non-manifold input.
MeshQuality measure_quality(const TriMesh& mesh);

}  // namespace grainmesh
