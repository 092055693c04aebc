// Binder mode: grains shrunk inside their torus cells until the matrix between them has
// its target fraction.
#pragma once

#include <vector>

#include "common/geometry.hpp"
#include "common/random.hpp"
#include "tessellate/cut.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/torus.hpp"

namespace grainmesh {

// The convex set of points of a convex-ish polygon at distance >= t inside every edge's
// line (the inward offset). Empty when nothing is left.
std::vector<Vec2> shrink_polygon(const std::vector<Vec2>& ring, double t);

// Binder mode: the grains are the torus cells `cells` of `g` shrunk by the one offset
// that leaves the matrix its target fraction (found by bisection; layers thinner than
// kMinBinderLayer of the grain spacing refused, naming the fraction that would do), the
// window placed clear of their corners, shallow side crossings squared off, and the
// grains labelled with the phases `hard`. The seeds of `g` are moved into the window.
struct BinderGrains {
  std::vector<CutPolygon> polygons;
  std::vector<int> grain_cell;  // torus cell of each grain (swallowed cells have none)
  int matrix_grain = -1;        // the grain the matrix becomes: after the others
};
BinderGrains binder_grains(TorusGraph& g, const std::vector<int>& cells, const TessellationOptions& o, double scale,
                           const std::vector<int>& hard, TessellationStats& st, Rng& rng);

}  // namespace grainmesh
