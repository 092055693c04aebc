// The surfaces of a 3D tessellation meshed once: every edge seeded once (its seeds shared
// by all faces around it), every face triangulated once (its triangles shared by the two
// regions on its sides), and each face on a high side of the box the exact copy of its
// partner on the low side.
#pragma once

#include <array>
#include <vector>

#include "common/vec3.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

struct SurfaceMesh {
  // Points: the tessellation's vertices (same ids), then the edge seeds, then the faces'
  // interior points.
  std::vector<Vec3> points;
  // #F: each face's triangles, turning as its ring does (right-hand normal from the
  // face's back region into its front).
  std::vector<std::vector<std::array<int, 3>>> faces;
  PeriodicPairs pairs;  // surface points on the box's sides with their images; empty when bounded
};

// A bent face (split into planar pieces by the regularisation) is meshed as one surface
// whose triangles cross its pieces' diagonals, off them by a little of its bend; a grain's
// bent faces together move its volume by at most this share of it (those that would move
// it further, and those whose triangles would lay an edge in a side of the box, are meshed
// piece by piece). Planar faces are met exactly.
inline constexpr double kBentFaceVolume = 5e-3;

// Triangles of edge length about `h` (the tessellation's unit) on every face: edges cut
// into equal pieces nearest h, faces filled with a triangular lattice of spacing h kept
// 0.6 h from their boundary, triangulated (constrained Delaunay) and smoothed; a bent
// face's pieces as one surface where kBentFaceVolume allows. Throws
// GeometryError for a face that cannot be triangulated.
SurfaceMesh mesh_surfaces(const Tessellation3& t, double h);

}  // namespace grainmesh
