// Tetrahedral meshes: the 3D mesh stage's output, and their quality measures.
#pragma once

#include <array>
#include <vector>

#include "common/vec3.hpp"

namespace grainmesh {

struct TetMesh {
  std::vector<Vec3> points;
  std::vector<std::array<int, 4>> tets;  // positively oriented: tet_volume > 0
};

// Signed volume of tetrahedron abcd: > 0 when d lies on the side abc's right-hand normal
// points to (abc turning clockwise seen from outside the tetrahedron).
double tet_volume(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
// Its centroid, the corners' mean (OpenFOAM's cell centre of a tetrahedron too).
inline Vec3 tet_centroid(Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return 0.25 * (a + b + c + d); }
// Radius ratio 3 r_in / r_circ: 1 for the regular tetrahedron, 0 for a flat one (also one
// flat only to rounding: volume below 1e-12 of the longest edge's cube).
double radius_ratio(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
// The six dihedral angles (radians), at edges ab, ac, ad, bc, bd, cd.
std::array<double, 6> dihedral_angles(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
// The smallest sine of the six, over the regular tetrahedron's (2 sqrt(2) / 3): 1 for the
// regular tetrahedron, near 0 for one with an angle near 0 or 180 degrees. Without
// trigonometry: the sine at edge e is 3 V |e| / (2 A1 A2), A1 and A2 the faces meeting there.
double dihedral_sine_ratio(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
// Both, their faces' areas and the volume found once (the mesh improvement's every step).
struct TetShape {
  double radius_ratio = 0.0;
  double dihedral_sine_ratio = 0.0;
};
TetShape tet_shape(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

// The regular tetrahedron: its volume from its edge (h^3 / (6 sqrt 2)) and its edge from
// its volume. How a wanted element size becomes a volume bound, and tetrahedra per grain
// an element size.
double regular_tet_volume(double edge);
double regular_tet_edge(double volume);

// What report.json's `mesh` holds for a tetrahedral mesh.
struct TetQuality {
  double q_min = 0.0;               // radius ratio
  double q_mean = 0.0;
  double min_dihedral_deg = 0.0;
  double max_dihedral_deg = 0.0;
  double share_dihedral_below_10 = 0.0;  // of all tetrahedra, those with an angle below 10 degrees
};
TetQuality measure_quality(const TetMesh& mesh);

}  // namespace grainmesh
