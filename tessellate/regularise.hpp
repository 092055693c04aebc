// Regularising a 2D torus graph: short edges collapsed, and the edge walks the steps of
// tessellate() share (each edge once, an edge's twin, the cells around a vertex).
#pragma once

#include <vector>

#include "tessellate/torus.hpp"

namespace grainmesh {

// Merges the end vertices of edges shorter than `threshold`, shortest first, into their
// midpoint, as long as every ring it touches stays simple and counter-clockwise. A
// three-sided cell that loses an edge disappears. Returns the number of edges collapsed;
// `removed_cells` receives the cells that vanished.
int collapse_short_edges(TorusGraph& g, double threshold, int* removed_cells);

// The direction in which an edge between corners a and b is stored and computed: from
// the smaller vertex id, or, for an edge to its own image, towards the positive shift.
inline bool canonical_direction(const Corner& a, const Corner& b) {
  if (a.v != b.v) return a.v < b.v;
  return b.i - a.i > 0 || (b.i == a.i && b.j - a.j > 0);
}

// Each edge once: the cell and ring position where it runs in canonical direction.
struct EdgeRef {
  int cell = 0;
  int at = 0;  // edge from rings[cell][at] to the next corner
};
std::vector<EdgeRef> unique_edges(const TorusGraph& g);

// The cell whose ring holds the twin of edge `e` (v then u, same relative shift), and
// where; {-1, -1} on the boundary of a plane (non-periodic) diagram.
EdgeRef twin_edge(const TorusGraph& g, const std::vector<std::vector<int>>& vertex_cells, EdgeRef e);
// Cells around each vertex.
std::vector<std::vector<int>> vertex_cells(const TorusGraph& g);

}  // namespace grainmesh
