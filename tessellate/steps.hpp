// The steps tessellate() chains, each on plain data so tests can call one alone.
#pragma once

#include <numbers>
#include <vector>

#include "common/random.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/torus.hpp"

namespace grainmesh {

// --- regularise.cpp ------------------------------------------------------------------

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

// --- window.cpp ----------------------------------------------------------------------

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

// --- cut.cpp -------------------------------------------------------------------------

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

// --- phases.cpp ----------------------------------------------------------------------

// A phase for each grain, so that the summed `areas` of the grains of each phase with a
// fraction approach fraction x total_area (greedy in the arrangement's order, then best
// single swaps); the rest phase (or, without one, the last phase) takes the remaining
// grains. `phases` indexes into `all`.
std::vector<int> assign_phases(const std::vector<double>& areas, const std::vector<std::vector<int>>& neighbours,
                               const std::vector<Phase>& all, const std::vector<int>& phases, double total_area,
                               Arrangement arrangement, Rng& rng);

// --- contiguity.cpp ------------------------------------------------------------------

// Each grain's neighbours and the length of boundary it shares with each (summed over
// their edges; a grain's boundary with itself left out).
using SharedBoundaries = std::vector<std::vector<std::pair<int, double>>>;

// The contiguity 2 L_aa / (2 L_aa + L_ab) of `phase` under `label` (0 without boundary).
double labelled_contiguity(const std::vector<int>& label, const SharedBoundaries& shared, int phase);

// Moves the contiguity of `phase` toward `target` by trading labels: a grain of the phase
// and a like-sized grain of another phase swap theirs, the phase's summed area staying
// within `slack` of `target_area` (or within where it started, when further). Greedy:
// each of the phase's grains in an order drawn from `rng` takes the trade that brings the
// contiguity nearest the target, sweep after sweep until within 0.002 or no trade helps.
// Returns the contiguity reached.
double arrange_contiguity(std::vector<int>& label, const std::vector<double>& areas, const SharedBoundaries& shared,
                          int phase, double target, double target_area, double slack, Rng& rng);

// The convex set of points of a convex-ish polygon at distance >= t inside every edge's
// line (the inward offset). Empty when nothing is left.
std::vector<Vec2> shrink_polygon(const std::vector<Vec2>& ring, double t);

// --- tessellation.cpp ----------------------------------------------------------------

// Crossings of the cell's sides shallower than this are squared off.
inline constexpr double kMinSideAngle = 32.0 * std::numbers::pi / 180.0;

// The best `count` cell origins on the torus: x first, then y for each x, keeping clear
// of where the x side crosses boundaries and of the x side itself.
std::vector<Vec2> window_candidates(const std::vector<Segment>& segs, const std::vector<Vec2>& points, double W,
                                    double H, double scale, int count);

// The part of a polygon inside [0, W] x [0, H] (Sutherland-Hodgman), for areas only.
std::vector<Vec2> clip_to_cell(std::vector<Vec2> poly, double W, double H);

// The area fraction phase p is to have: its own, or for the rest phase what the others leave.
double target_fraction(const std::vector<Phase>& phases, int p);

// Lognormal radii of median 1 with coefficient of variation `cv`, one per seed: the
// Laguerre sizes of both the 2D and the 3D stage (Box-Muller, two draws per radius).
std::vector<double> lognormal_radii(int n, double cv, Rng& rng);

// --- binder.cpp ----------------------------------------------------------------------

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
