// Cutting grain polygons (and their periodic images) by the cell into the regions of a
// tessellation, shared edges computed once so that both sides get the same bits.
#pragma once

#include <vector>

#include "tessellate/tessellation.hpp"
#include "tessellate/torus.hpp"

namespace grainmesh {

// A corner given as base + (i W, j H), so the same corner reached twice has the same bits.
struct CutCorner {
  Vec2 base;
  int i = 0;
  int j = 0;
};
// The straight edge through which cut points are computed: endpoints p, q in the frame
// shifted by (i W, j H). Shared edges of two polygons must carry the same p, q, i, j.
struct CutEdge {
  Vec2 p, q;
  int i = 0;
  int j = 0;
};
struct CutPolygon {
  int grain = 0;
  int phase = 0;
  std::vector<CutCorner> corners;  // counter-clockwise
  std::vector<CutEdge> edges;      // edges[k] runs from corners[k] to corners[k + 1]
};

// Cuts the polygons (and, when periodic, their lattice images) by the cell [0, W] x [0, H]
// into regions; builds vertices, edges with their sides and, when periodic, the partner
// maps. With `matrix_grain` >= 0 the rest of the cell becomes matrix regions of that
// grain and `matrix_phase`.
void cut_into_cell(const std::vector<CutPolygon>& polygons, Tessellation& t, int matrix_grain, int matrix_phase);

// The canonical cut polygons of the cells of a graph (grain mode): polygon k for cell
// cells[k], shared edges carrying one canonical frame.
std::vector<CutPolygon> cell_polygons(const TorusGraph& g, const std::vector<int>& cells);

}  // namespace grainmesh
