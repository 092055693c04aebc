// One edge of a mesh of cells (triangles or polygons) and the cells on its two sides.
#pragma once

namespace grainmesh {

// One edge of a mesh. `left` is the triangle in which the edge runs a -> b
// counter-clockwise; `right` is the triangle on the other side, or -1 on the boundary
// (so the boundary's outward normal points to the right of a -> b).
struct MeshEdge {
  int a = -1, b = -1;
  int left = -1, right = -1;
};

}  // namespace grainmesh
