// The dual of a triangle mesh (the thesis' §4.2 perspective): one polygonal cell per mesh
// node, bounded by a centre of each of its triangles and the midpoints of its edges, split
// where the triangles around the node change label, so that every cell lies in one label
// (grain or phase) and each label's cells cover exactly its triangles.
#pragma once

#include <cstddef>
#include <vector>

#include "common/periodic_pairs.hpp"
#include "mesh/cell_mesh.hpp"
#include "mesh/trimesh.hpp"

namespace grainmesh {

// A triangle's centre is its circumcentre (the Voronoi vertex: dual faces then cross the
// mesh edges at right angles) when that lies inside it with each barycentric coordinate at
// least this; otherwise (obtuse or right triangles, near-right ones) its centroid.
inline constexpr double kCircumcentreMargin = 0.05;

struct DualMesh {
  CellMesh mesh;
  std::vector<int> node;      // #C: the triangle mesh's node each cell surrounds
  std::vector<int> triangle;  // #C: a triangle of the cell, to carry per-triangle attributes (grain, phase)
  // The triangle mesh's periodic pairs carried to the dual's points on the sides (nodes
  // and edge midpoints); empty when the triangle mesh has none.
  PeriodicPairs pairs;
  std::size_t circumcentres = 0;  // triangles whose circumcentre is a corner,
  std::size_t centroids = 0;      // ... and whose centroid is instead
};

// Cells never cross an edge between triangles of different `label` (#T) nor the mesh's
// boundary: a node there gets one cell for each run of equal labels around it (half- and
// quarter-cells on a cell's sides and corners). A cell's corners: the node itself where
// its cell is split or on the boundary, the midpoints of its edges and its triangles'
// centres; a midpoint between two circumcentres of one label is left out (it lies on the
// segment joining them), so such a pair of cells shares one straight face. Cells in the
// order of their nodes. Throws GeometryError for a triangle mesh that is not valid or not
// manifold at a node, or labels not one per triangle.
DualMesh dual_mesh(const TriMesh& mesh, const std::vector<int>& label, const PeriodicPairs& pairs = {});

}  // namespace grainmesh
