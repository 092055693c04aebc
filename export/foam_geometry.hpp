// Face and cell geometry as OpenFOAM computes it from a polyMesh's points (area vectors,
// centres, volumes), for 2D and 3D polyMeshes alike.
#pragma once

#include <vector>

#include "common/vec3.hpp"
#include "export/polymesh.hpp"

namespace grainmesh {

// A polyMesh face's area vector (normal by its points' turning, right hand) and centre
// as OpenFOAM computes them: a triangle's own; a polygon's from the triangles about its
// points' mean, centres weighted by area (mesh units; a 2D mesh's faces as extruded).
struct FoamFace {
  Vec3 area, centre;
};
FoamFace foam_face(const PolyMesh& pm, int face);
// Each cell's centre (mesh units) and volume (mesh units cubed) as OpenFOAM computes them:
// pyramids from the mean of the cell's face centres to its faces.
void foam_cell_geometry(const PolyMesh& pm, std::vector<Vec3>& centre, std::vector<double>& volume);

}  // namespace grainmesh
