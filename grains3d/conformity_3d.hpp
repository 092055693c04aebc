// What makes a 3D grain mesh right, checked against its tessellation.
#pragma once

#include <vector>

#include "grains3d/grain_mesh_3d.hpp"
#include "grains3d/surface_mesh.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// The 3D conformity checker: every tetrahedron positive; every triangle of the mesh
// shared by two tetrahedra, or by one on the box; the tessellation's faces made of
// triangles with a tetrahedron of each region on their sides; each grain's tetrahedra
// filling what its surface triangles enclose (1e-9 relative), and that its polyhedron's
// volume within kBentFaceVolume (surface_mesh.hpp); paired points images across the box (1e-12 of it).
// Throws GeometryError naming the first violation.
void check_conformity(const Tessellation3& t, const GrainMesh3& m);

// The volume each grain's surface triangles (m.faces) enclose.
std::vector<double> surface_volumes(const Tessellation3& t, const GrainMesh3& m);

// The largest relative difference between that and a grain's polyhedron's volume.
double grain_volume_change_max(const Tessellation3& t, const GrainMesh3& m);

}  // namespace grainmesh
