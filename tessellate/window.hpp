// Placing the cell's window on the torus: line offsets clear of the boundaries' vertices
// and shallow crossings, vertices pushed off the cell's lines, shallow crossings squared
// off, and the part of a polygon inside the cell.
#pragma once

#include <numbers>
#include <vector>

#include "common/geometry.hpp"
#include "tessellate/torus.hpp"

namespace grainmesh {

// Crossings of the cell's sides shallower than this are squared off.
inline constexpr double kMinSideAngle = 32.0 * std::numbers::pi / 180.0;

// A segment of a grain boundary, anywhere in the plane (periodic images implied).
struct Segment {
  Vec2 a, b;
};

// The `count` best offsets in [0, period), best first, of the cell's lines normal to
// `axis` (0: lines x = c, 1: lines y = c): crossings steep, away from the points and
// apart from each other and from the positions `along` the line where the other axis'
// line already is. `scale` is the length below which a feature counts as short.
std::vector<double> best_line_offsets(const std::vector<Segment>& segments, const std::vector<Vec2>& points, int axis,
                                      double period, double other_period, bool other_periodic, double scale,
                                      const std::vector<double>& along, int count);

// Where the segments cross the line coord(axis) = c (and its periodic images), reduced.
std::vector<Vec2> line_crossings(const std::vector<Segment>& segments, int axis, double c, double width,
                                 double height);

// Moves each vertex closer than `distance` to a cell line (x = k W, y = k H; the cell's
// own sides when not periodic) straight away from it to that distance, when the cells
// around it stay simple, no corner of theirs becomes sharper than `min_angle` and no edge
// at the vertex shorter than `min_edge` (or than it was). Returns the vertices moved.
int push_vertices_off_lines(TorusGraph& g, double distance, double min_angle, double min_edge);

// Moves every vertex, seed and corner of a periodic graph by -origin.
void translate_graph(TorusGraph& g, Vec2 origin);

// Replaces each crossing of a cell line (x = k W, y = k H; only the cell's own sides when
// not periodic) shallower than `min_angle` by a square step of half-width <= `step`, so
// the line is crossed at right angles. Returns the number of steps made.
int square_shallow_crossings(TorusGraph& g, double min_angle, double step);
// The same for one polygon of its own (a binder-mode grain), in place.
int square_shallow_crossings(std::vector<Vec2>& polygon, double width, double height, bool periodic,
                             double min_angle, double step);

// The best `count` cell origins on the torus: x first, then y for each x, keeping clear
// of where the x side crosses boundaries and of the x side itself.
std::vector<Vec2> window_candidates(const std::vector<Segment>& segs, const std::vector<Vec2>& points, double W,
                                    double H, double scale, int count);

// The part of a polygon inside [0, W] x [0, H] (Sutherland-Hodgman), for areas only.
std::vector<Vec2> clip_to_cell(std::vector<Vec2> poly, double W, double H);

}  // namespace grainmesh
