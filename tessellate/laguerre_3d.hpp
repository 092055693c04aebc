// The 3D Laguerre (power) diagram of weighted seeds in a W x H x D box, periodic or
// bounded by the box, through CGAL's regular triangulation (laguerre_3d.cpp is the only
// file of the 3D stage that includes CGAL). Periodicity comes from the 27 images of each
// seed, which works for any box (CGAL's periodic triangulations want a cube); a bounded
// box from each seed's mirror images across the six sides, whose bisectors are the sides.
#pragma once

#include <utility>
#include <vector>

#include "common/vec3.hpp"

namespace grainmesh {

// Volume and centroid of each seed's cell, in floating point: what Lloyd's relaxation
// and the window choice need. A hidden seed (no cell) has volume 0. `vertices` gets the
// diagram's vertices (every cell's corners, once per cell) and `edges` its edges (once
// per face they bound), not reduced into the box.
struct CellMoments {
  std::vector<double> volume;
  std::vector<Vec3> centroid;  // not reduced into the box
  std::vector<Vec3> vertices;
  std::vector<std::pair<Vec3, Vec3>> edges;
};
CellMoments laguerre_moments(const std::vector<Vec3>& seeds, const std::vector<double>& weights, Vec3 box,
                             bool periodic);

// The cells cut exactly into the box: the exact stage. Every vertex is computed in exact
// rational arithmetic and rounded once, so a point reached from two cells, or from two
// periodic images, has the same bits, and a vertex on a side of the box carries the
// side's coordinate (0 or the box's edge) exactly.
struct BoxPiece {
  int seed = 0;
  std::vector<std::vector<int>> faces;  // rings of vertex ids, counter-clockwise seen from outside
};
struct LaguerreCut {
  std::vector<Vec3> vertices;           // each exact point once
  std::vector<BoxPiece> pieces;         // a periodic cell the box cuts gives several
  std::vector<int> cell_faces;          // faces of each seed's uncut cell (0: hidden)
  std::vector<std::vector<int>> neighbours;  // seeds sharing a face with each seed's cell, ascending
};
LaguerreCut laguerre_box_cut(const std::vector<Vec3>& seeds, const std::vector<double>& weights, Vec3 box,
                             bool periodic);

}  // namespace grainmesh
