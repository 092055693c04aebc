// The dual of a triangle mesh (the thesis' §4.2 perspective): one polygonal cell per mesh
// node, its Voronoi cell, cut where the triangles around the node change label, so that
// every cell lies in one label (grain or phase) and each label's cells cover exactly its
// triangles.
#pragma once

#include <cstddef>
#include <vector>

#include "common/periodic_pairs.hpp"
#include "mesh/cell_mesh.hpp"
#include "mesh/trimesh.hpp"

namespace grainmesh {

struct DualMesh {
  CellMesh mesh;
  // #C: the node each cell surrounds, of the conforming mesh (conforming_delaunay.hpp:
  // the input's nodes keep their ids, the midpoints of split edges follow).
  std::vector<int> node;
  std::vector<int> triangle;  // #C: an input triangle of the cell's label, to carry attributes that follow the label
  // The triangle mesh's periodic pairs carried to the dual's points on the sides (nodes
  // and edge midpoints); empty when the triangle mesh has none.
  PeriodicPairs pairs;
  std::size_t circumcentres = 0;  // triangles of the conforming mesh whose circumcentre is a corner,
  std::size_t centroids = 0;      // ... and whose centroid is instead
  std::size_t splits = 0, flips = 0;  // what made the mesh conforming (see ConformingMesh)
};

// First makes the mesh conforming (conforming_delaunay.hpp): Delaunay in each label, no
// edge bounding a label encroached. A cell's corners are then its triangles'
// circumcentres, and where it meets edges bounding its label, the edges' midpoints and
// the node itself (not where the two edges continue each other straight through the node:
// then the cut is one face): its faces to neighbour cells lie on the bisectors of the mesh
// edges.
// A triangle still encroaching an edge bounding its label, or whose circumcentre lies
// beyond an edge towards such a triangle, or one of a cell that would not be a simple
// polygon, takes its centroid instead, and the midpoints of its edges become corners too.
// Cells never cross an edge between triangles of different `label` (#T) nor the mesh's
// boundary: a node there gets one cell for each run of equal labels around it (half- and
// quarter-cells on a cell's sides and corners). Cells in the order of their nodes. Throws
// GeometryError for a triangle mesh that is not valid or not manifold at a node, or
// labels not one per triangle.
DualMesh dual_mesh(const TriMesh& mesh, const std::vector<int>& label, const PeriodicPairs& pairs = {});

}  // namespace grainmesh
