// A planar graph of grains before it is cut into the cell: on the torus (periodic) or in
// the plane. Vertices are stored once, reduced into [0, W) x [0, H); a cell's ring refers
// to a vertex together with the lattice shift that puts that copy next to the cell's
// other corners, so rings are unwrapped polygons that may reach outside the box.
#pragma once

#include <cstdint>
#include <vector>

#include "common/geometry.hpp"
#include "common/ring.hpp"

namespace grainmesh {

// A cell corner: vertex v translated by (i W, j H).
struct Corner {
  int v = 0;
  int i = 0;
  int j = 0;

  friend bool operator==(const Corner&, const Corner&) = default;
};

struct TorusGraph {
  double width = 1.0;     // W, length unit of the caller
  double height = 1.0;    // H
  bool periodic = true;   // false: plain plane, every shift is 0
  std::vector<Vec2> vertices;              // #V reduced positions
  std::vector<Vec2> seeds;                 // #C generator points, reduced
  std::vector<double> weights;             // #C power weights (radius squared), 0 for Voronoi
  std::vector<std::vector<Corner>> rings;  // #C counter-clockwise corners; empty = no cell

  // The position of a corner. Always evaluated by this one expression, so the same corner
  // reached from two cells gives the same bits.
  Vec2 point(const Corner& c) const {
    return {vertices[c.v].x + c.i * width, vertices[c.v].y + c.j * height};
  }
  // The unwrapped polygon of cell c.
  std::vector<Vec2> polygon(int c) const;
  // Number of cells that are not empty.
  int live_cells() const;
};

// Reduces p into [0, W) x [0, H); `shift` receives k with p = reduced + (k.i W, k.j H).
Vec2 reduce_periodic(Vec2 p, double width, double height, Corner* shift = nullptr);

// The power diagram (Laguerre tessellation; Voronoi when all weights are 0) of the seeds,
// periodic in the W x H cell or, when !periodic, in the plane around it. Cells whose seed
// is hidden by heavier neighbours have empty rings. Vertices closer than `merge_distance`
// (cocircular seeds) are merged. Uses CGAL's regular triangulation with exact predicates.
TorusGraph power_diagram(const std::vector<Vec2>& seeds, const std::vector<double>& weights, double width,
                         double height, bool periodic, double merge_distance);

}  // namespace grainmesh
