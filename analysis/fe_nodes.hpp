// The nodes of a simplicial mesh's quadratic (Lagrange) elements and their unknowns on a
// periodic cell, for the finite-element reference (fe_homogenise.hpp): the mesh's points,
// then one node per edge; each node tied to its periodic images (a midside node with the
// image of its edge), the class of the first element's first corner held (a translation is
// free), a point no element uses left without unknowns, and the
// unknowns numbered in a fill-reducing order for the sparse Cholesky factor (CHOLMOD,
// inside fe_nodes.cpp only).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "export/export_mesh.hpp"

namespace grainmesh {

// A simplex of D dimensions with quadratic Lagrange shape functions: its D + 1 corners,
// then one node per edge (i, j), i < j, in kEdges' order.
template <int D>
struct Simplex {
  static constexpr int kCorners = D + 1;
  static constexpr int kEdges = D * (D + 1) / 2;
  static constexpr int kNodes = kCorners + kEdges;
  static constexpr std::array<std::array<int, 2>, kEdges> edges() {
    std::array<std::array<int, 2>, kEdges> e{};
    int k = 0;
    for (int i = 0; i < kCorners; ++i)
      for (int j = i + 1; j < kCorners; ++j) e[static_cast<std::size_t>(k++)] = {i, j};
    return e;
  }
};

// The mesh's points, elements and an element's corners (2D: a cell that is no triangle
// is a GeometryError).
const std::vector<Vec2>& mesh_points(const ExportMesh<2>& m);
const std::vector<Vec3>& mesh_points(const ExportMesh<3>& m);
std::size_t element_count(const ExportMesh<2>& m);
std::size_t element_count(const ExportMesh<3>& m);
std::array<int, 3> element_corners(const ExportMesh<2>& m, std::size_t c);
std::array<int, 4> element_corners(const ExportMesh<3>& m, std::size_t c);

template <int D>
struct FeNodes {
  std::vector<std::array<int, Simplex<D>::kNodes>> element;  // per element its nodes, corners then edges
  std::size_t count = 0;                                      // nodes: the points, then the edges'
  std::vector<int> first;      // per node its unknowns' first index (D in a row), -1 held or unused
  std::size_t unknowns = 0;    // D per class of tied nodes, the held one excepted
};

// The nodes and unknowns of periodic cell `m`. Throws GeometryError when it is not
// periodic, has a cell that is no triangle (2D), or an edge on a low side without its image.
FeNodes<2> fe_nodes(const ExportMesh<2>& m);
FeNodes<3> fe_nodes(const ExportMesh<3>& m);

// The same for `fine`, a nested split of `coarse` (fine element 2^D c + k inside coarse
// element c), its unknowns numbered after the coarse level's (whose nodes are its corners)
// rather than by an ordering of its own (on the 1,000-grain cell's fine level 0.5 s
// saved); still a nested-dissection order, should the fine level be factorised.
FeNodes<2> fe_nodes(const ExportMesh<2>& fine, const ExportMesh<2>& coarse, const FeNodes<2>& coarse_nodes);
FeNodes<3> fe_nodes(const ExportMesh<3>& fine, const ExportMesh<3>& coarse, const FeNodes<3>& coarse_nodes);

// The graph of the unknown nodes (first[node] / D) that share an element, column by
// column: its lower triangle, diagonal included, rows sorted in each column. Made from each
// node's elements (counted, then listed) with a mark per row seen: a third of the time of
// sorting the element pairs (the 1,000-grain cell's fine level).
struct NodeGraph {
  std::vector<int> outer, inner;  // column j's rows: inner[outer[j] .. outer[j + 1])
};

template <int D>
NodeGraph node_graph(const FeNodes<D>& n);

}  // namespace grainmesh
