// The polyMesh of a 3D mesh's median dual split at grain boundaries (export.cells =
// polygons).
#pragma once

#include "export/export_mesh.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh_3d.hpp"

namespace grainmesh {

// The median dual of the tetrahedra split at grain boundaries (export.cells = polygons):
// one cell for each mesh point and grain around it (for each set of the point's
// tetrahedra of one grain joined through faces), the union of its tetrahedra's corner
// pieces (each tetrahedron cut through points on its edges, faces and inside: the means
// of their corners, a point on a phase interface weighted so that its cells' centres on
// the two sides lie at distances in the ratio sqrt(gamma_soft / gamma_hard), where the
// compact form's face force across the interface is exact for a laminate; elsewhere the
// midpoints and centroids). A face between the cells of an edge's two ends runs round the
// edge; a face between two cells of one point lies in the grain boundary (a quarter of a
// triangle, plane, so each grain keeps its volume exactly), as does a face on a side of
// the box; each is one polygon (its ring of corners, and the point or edge point it fans
// from when the ring is open; with options.plane_faces a face round an edge is split into
// its plane triangles, edge midpoint, face centroid and tetrahedron centroid). Internal
// faces in OpenFOAM's order, boundary faces patch
// by patch as build_polymesh (cyclic sides' faces the images of their partners'),
// zones by add_zones; cells in the order of their points.
// Mended where checkMesh would fail (options.mend_checks; its checks as
// foam_mesh_check.hpp computes them): a point whose faces between two of its own cells
// fail gets them folded into one (fanned from the point, or the ring round it where they
// close round it, as at a grain's tip poking into the binder: its cone then changes sides,
// so the grains' volumes move a little there, 6e-5 of the binder's on the binder example);
// cells whose faces still fail are joined with neighbours of their grain, or of their
// phase (join_cells.hpp); at most four builds after the first. What was mended, and what
// still fails (left for checkMesh to report as well), in the result's `mending`. Throws as
// build_polymesh, and GeometryError where the
// dual's faces would not be simple (a grain boundary not manifold at a point).
FoamMesh3 build_dual_polymesh_3d(const ExportMesh<3>& m, const FoamOptions& options);

}  // namespace grainmesh
