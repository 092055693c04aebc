// The tessellation stage: periodic Voronoi/Laguerre grains with phase labels, cut into a
// W x H cell as a planar graph the mesh stage meshes region by region.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/cell_side.hpp"
#include "common/deadline.hpp"
#include "common/periodic_pairs.hpp"
#include "common/geometry.hpp"
#include "common/random.hpp"

namespace grainmesh {

// A named phase with its elastic constants.
struct Phase {
  std::string name;
  double fraction = 0.0;      // target area fraction in (0, 1]; ignored when rest
  bool rest = false;          // takes whatever the other phases leave
  double youngs_modulus = 0;  // E, Pa (or the caller's stress unit)
  double poisson_ratio = 0;   // nu
  std::optional<double> alpha;  // linear thermal expansion, 1/K (needed by a thermal load only)
};

enum class PhaseMode { grain, binder };
enum class Arrangement { random, dispersed, clustered };

struct TessellationOptions {
  double width = 1.0;            // W, the caller's length unit
  double height = 1.0;           // H
  bool periodic = true;
  int grains = 100;              // N seeds
  std::vector<Vec2> seeds;       // given generator points in the cell (N of them); empty = drawn
  int lloyd_iterations = 0;      // centroidal relaxation steps
  double size_cv = 0.0;          // coefficient of variation of the Laguerre radii; 0 = Voronoi
  double min_edge = 0.1;         // edges shorter than this x mean grain diameter are merged; 0 = off
  PhaseMode phase_mode = PhaseMode::grain;
  Arrangement arrangement = Arrangement::random;
  std::vector<Phase> phases;     // at least one
  int matrix_phase = -1;         // binder mode: index into phases
  // The contiguity phase `contiguity_phase` is to have (descriptors.hpp). Grain mode:
  // reached by trading the labels of like-sized grains after the fractions are met; binder
  // mode (one grain phase): by the interfaces left without binder (binder_contacts.hpp);
  // none: as the arrangement gives it, or no grain touching another in binder mode.
  std::optional<double> contiguity;
  int contiguity_phase = -1;
  Deadline deadline{};           // the run's wall-clock guard, asked every Lloyd step
};

// An edge between two vertices; `left` and `right` are the regions on either side of
// v0 -> v1 (-1 = outside the cell).
struct TessEdge {
  int v0 = 0;
  int v1 = 0;
  int left = -1;
  int right = -1;
};

// A region: one grain piece, or a connected part of the matrix in binder mode. Every ring
// is counter-clockwise; rings[0] is the outer boundary, the others are holes cut out.
struct Region {
  int grain = 0;
  int phase = 0;
  std::vector<std::vector<int>> rings;  // vertex ids
};

struct Grain {
  int id = 0;
  int phase = 0;
  Vec2 seed{};                 // generator point, in the cell
  double area = 0.0;           // summed over its pieces
  std::vector<int> neighbours; // grain ids sharing an edge, ascending
  bool matrix = false;         // binder mode: the matrix, one grain for all its regions
};

struct PhaseStats {
  double target_fraction = 0.0;
  double achieved_fraction = 0.0;
  int grains = 0;
  // The WC-Co descriptors (descriptors.hpp): NaN where the phase has no boundary, the
  // mean free path infinite where no other phase touches it.
  double contiguity = 0.0;
  double intercept_length = 0.0;
  double mean_free_path = 0.0;
};

// How near a contiguity target is met, where it can be.
inline constexpr double kContiguityTolerance = 0.02;

struct TessellationStats {
  int grains = 0;                   // not counting the matrix
  int removed_grains = 0;           // hidden Laguerre cells and cells regularisation merged away
  double area_mean = 0.0, area_std = 0.0;
  double diameter_mean = 0.0, diameter_std = 0.0;  // equivalent-circle diameters
  double neighbours_mean = 0.0;     // on the torus (in the plane when not periodic)
  double edges_per_grain_mean = 0.0;
  double edge_threshold = 0.0;      // regularisation length
  double shortest_edge = 0.0;       // in the cut cell
  double shortest_torus_edge = 0.0; // before cutting
  double sharpest_corner_deg = 0.0; // over every region corner, cell-side crossings included
  int collapsed_edges = 0;
  int side_jogs = 0;                // shallow cell-side crossings replaced by a square step
  int pushed_vertices = 0;          // junctions moved off a cell side
  double binder_offset = 0.0;       // t of binder mode
  Vec2 window_origin{};             // where the cell was placed on the torus
  // A contiguity target missed by more than kContiguityTolerance: the lowest and highest
  // contiguity the label trades (binder mode: the contacts) reach from the same start
  // (none when met).
  std::optional<std::pair<double, double>> contiguity_range;
  std::vector<PhaseStats> phases;
};

struct Tessellation {
  double width = 1.0;
  double height = 1.0;
  bool periodic = true;
  std::vector<Phase> phases;
  std::vector<Grain> grains;
  std::vector<Vec2> vertices;
  std::vector<TessEdge> edges;
  std::vector<Region> regions;
  // Periodic partners: each vertex on the left (bottom) side and the vertex on the right
  // (top) side at exactly the position plus W (H); empty when not periodic.
  PeriodicPairs partners;
  TessellationStats stats;
};

// The side of the cell [0, W] x [0, H] the segment ab runs along, else kNoSide. Exact:
// points on a side carry its coordinate.
CellSide cell_side(const Tessellation& t, Vec2 a, Vec2 b);

// The positions of a ring of vertex ids, in its order.
std::vector<Vec2> ring_points(const std::vector<Vec2>& vertices, const std::vector<int>& ring);

// Area of a region (outer minus holes).
double region_area(const Tessellation& t, const Region& r);

}  // namespace grainmesh
