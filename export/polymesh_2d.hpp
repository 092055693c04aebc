// The polyMesh of a 2D mesh: its cells (triangles or polygons) extruded one cell thick into
// prisms, the cell's sides as patches or cyclic pairs, the pinned pair of a periodic case,
// zones by add_zones.
#pragma once

#include "export/export_mesh.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh.hpp"

namespace grainmesh {

// Builds the polyMesh. Throws ConfigError naming a patch the load needs that has no face
// (right, left, bottom, and top unless uniaxial), GeometryError when a cyclic side's faces
// do not pair, or a boundary edge lies on no side while the mesh is to be cyclic.
PolyMesh build_polymesh(const ExportMesh<2>& m, const FoamOptions& options);

}  // namespace grainmesh
