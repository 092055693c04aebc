// A 3D cell seen from outside: the sides of a box-shaped tetrahedral mesh that face a
// viewer, projected orthographically into a plane mesh, so that the plane pictures
// (write_mesh_png) draw it with their fills, outlines, fields, legend and scale bar.
#pragma once

#include <vector>

#include "common/vec3.hpp"
#include "mesh/tetmesh.hpp"
#include "mesh/trimesh.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// The viewer's direction (from the cell towards the viewer; unit): in front of the cell
// (-y), to its right (+x) and above it (+z), 35 degrees round and 25 degrees up, so the
// sides x = max, y = min and z = max show.
Vec3 box_view_direction();

struct BoxView {
  TriMesh mesh;               // the visible sides' triangles in the picture plane, counter-clockwise
  std::vector<int> tet;       // the tetrahedron each triangle is a face of
  std::vector<double> shade;  // each triangle's brightness in (0, 1]: its side's, lit from above the viewer
  std::vector<int> side;      // each triangle's side of the box: 2 axis + 1 at the high end, 2 axis at the low
  // Labels for PictureOptions::outline_by: the triangles' `grain` (one per tetrahedron, or region)
  // and their side, so that the box's edges are drawn as the grain boundaries are.
  std::vector<int> outline(const std::vector<int>& grain) const;
};

// The boundary faces of `mesh` (faces whose three corners lie on one side of the points'
// bounding box) that face the viewer, projected: lengths in the picture plane are the
// cell's, so a scale bar measures lengths parallel to it. Throws GeometryError when no
// face shows (an empty mesh, or one that is not a box).
BoxView box_view(const TetMesh& mesh);
// The same for a tessellation's faces on the box, each fanned from its centre into
// triangles whose `tet` is the face's region.
BoxView box_view(const Tessellation3& t);

}  // namespace grainmesh
