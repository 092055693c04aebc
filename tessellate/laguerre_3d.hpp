// The 3D Laguerre (power) diagram of weighted seeds in a W x H x D box, periodic or
// bounded by the box, through CGAL's regular triangulation (laguerre_3d.cpp is the only
// file of the 3D stage that includes CGAL). Periodicity comes from the 27 images of each
// seed, which works for any box (CGAL's periodic triangulations want a cube); a bounded
// box from each seed's mirror images across the six sides, whose bisectors are the sides.
#pragma once

#include <array>
#include <functional>
#include <optional>
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

// Each seed's whole cell in floating point: its faces' rings of points, counter-clockwise
// seen from outside, about the seed itself (periodic: reaching out of the box, not
// reduced into it); no faces when the seed is hidden. What a tessellation file of whole
// cells (Neper's periodic ones) holds.
std::vector<std::vector<std::vector<Vec3>>> laguerre_cells(const std::vector<Vec3>& seeds,
                                                           const std::vector<double>& weights, Vec3 box, bool periodic);

// The cells cut exactly into the box: the exact stage. Every vertex is computed in exact
// rational arithmetic and rounded once, so a point reached from two cells, or from two
// periodic images, has the same bits, and a vertex on a side of the box carries the
// side's coordinate (0 or the box's edge) exactly.
struct BoxPiece {
  int seed = 0;
  int face = -1;  // layered: the frustum on this face of the seed's whole cell; -1 the cell (or its core)
  std::vector<std::vector<int>> faces;  // rings of vertex ids, counter-clockwise seen from outside
};
// A face of a seed's whole (uncut) cell: its ring in floating point, counter-clockwise seen
// from outside, and the seed across it with that seed's face index matching it (-1 for a
// side of a bounded box, which the seed's mirror image makes).
struct WholeFace {
  std::vector<Vec3> ring;
  int across = -1;
  int across_face = -1;
};
struct LaguerreCut {
  std::vector<Vec3> vertices;                // each exact point once
  std::vector<BoxPiece> pieces;              // a periodic cell the box cuts gives several
  std::vector<int> cell_faces;               // faces of each seed's uncut cell (0: hidden)
  std::vector<std::vector<int>> neighbours;  // seeds sharing a face with each seed's cell, ascending
  std::vector<std::vector<WholeFace>> whole; // each seed's whole cell (laguerre_box_cut only)
};
// Binder mode's layers: each whole cell split, before the box cuts it, into its core (the
// cell scaled by `scale` about the seed's centre) and one frustum per face, between the
// face and the core's copy of it (each frustum convex; neighbouring frustums share their
// faces exactly, as the cells do).
struct Layering {
  std::vector<Vec3> centres;  // per seed, inside its cell
  double scale = 1.0;         // in (0, 1)
};
// The layers to split the cells into, chosen from the whole cells (none: cut them whole).
using LayeringOf = std::function<std::optional<Layering>(const std::vector<std::vector<WholeFace>>& whole)>;
LaguerreCut laguerre_box_cut(const std::vector<Vec3>& seeds, const std::vector<double>& weights, Vec3 box,
                             bool periodic, const LayeringOf& layering = {});

// A corner of a periodic cell given whole (a Neper file's): the point bases[base] moved by
// `shift` periods along each axis, computed exactly, so each image of one point is that
// point moved by whole periods with no rounding between them.
struct LatticeCorner {
  int base = 0;
  std::array<int, 3> shift{0, 0, 0};
};
// Convex cells given whole, each its faces' rings of corners (counter-clockwise seen from
// outside), cut exactly into the periodic box as laguerre_box_cut cuts its own: piece
// seed = the cell's index; cell_faces and neighbours are left empty.
LaguerreCut periodic_box_cut(const std::vector<Vec3>& bases,
                             const std::vector<std::vector<std::vector<LatticeCorner>>>& cells, Vec3 box);

}  // namespace grainmesh
