// Improvement of a region's tetrahedra with its surface kept: topological flips (edge
// removal, which includes the 3-2 and 4-4 flips, and the 2-3 face flip) and smoothing of
// the inner points, each step taken only when it raises the smallest quality (the radius
// ratio, or a sharp dihedral angle's sine: improve_tets.cpp) of the tetrahedra it replaces
// or moves.
#pragma once

#include <array>
#include <vector>

#include "common/vec3.hpp"

namespace grainmesh {

struct TetImprovement {
  int edge_removals = 0;
  int face_flips = 0;
  int insertions = 0;
  int moves = 0;
};

// `tets` positively oriented, filling a region whose boundary triangles are faces of one
// tetrahedron each; points with index < first_free (the surface ones) stay bit for bit and
// so do the boundary triangles (flips only replace tetrahedra around an inner edge or
// face). Works in index order, so the result depends on the input alone.
TetImprovement improve_tets(std::vector<Vec3>& points, std::vector<std::array<int, 4>>& tets, int first_free,
                            int passes);

}  // namespace grainmesh
