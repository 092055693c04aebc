// Nested refinement of a simplicial export mesh: every triangle split in four, every
// tetrahedron in eight, at its edges' midpoints — the same geometry, grains and phases at
// every level, so that a solve's answers on the levels converge as Richardson assumes and
// a finite-element space on a level holds the one before (nested). The periodic pairs
// carry over: an edge on a low side and its image split at points that are images too.
#pragma once

#include "export/export_mesh.hpp"

namespace grainmesh {

// `m` with each cell split (2D: into its four corner and middle triangles; 3D: the four
// corner tetrahedra and the inner octahedron cut along its shortest diagonal into four),
// each child of its parent's grain and phase; the points: m's, then one per edge. Throws
// GeometryError when a 2D cell is no triangle or a low side's edge has no image edge.
ExportMesh<2> split_nested(const ExportMesh<2>& m);
ExportMesh<3> split_nested(const ExportMesh<3>& m);

}  // namespace grainmesh
