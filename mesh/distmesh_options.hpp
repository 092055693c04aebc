// What DistMesh is given and gives back: its options (the thesis' constants and our own),
// the problem (domain, sizes, interface, fixed points), its statistics and result.
#pragma once


#include <cstddef>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "common/deadline.hpp"
#include "common/geometry.hpp"
#include "common/random.hpp"
#include "mesh/delaunay.hpp"
#include "domain/distance.hpp"
#include "domain/size_function.hpp"
#include "mesh/trimesh.hpp"

namespace grainmesh {

// Algorithm constants. Lengths are relative to h0.
struct DistMeshOptions {
  double fscale = 1.2;             // bars want to be fscale x their size (eq. 2.9)
  double dt = 0.2;                 // pseudo time step of forward Euler (eq. 2.12)
  double ttol = 0.1;               // retriangulate once a point moved more than ttol h0
  double dptol = 1e-3;             // converged when every interior move is below dptol h0
  double geps = 1e-3;              // d < -geps h0 is inside, d > geps h0 outside
  int max_iterations = 5000;       // hard bound on force iterations
  int density_control_every = 30;  // drop points on bars shorter than half their size
                                   // every this many iterations; 0 = never
  // Beyond the thesis (each can be switched off to get its plain Algorithm 1):
  bool boundary_seeding = true;    // start with points on the boundary, spaced by size
  bool split_long_edges = true;    // density control also splits long boundary and
                                   // interface edges
  int optimize_sweeps = 50;        // local quality optimisation sweeps at the very end
  double optimize_below = 0.99;    // ... of the points with a triangle of q below this
  // The run's wall-clock guard, asked every force iteration and in every long loop of
  // seeding and finishing: TimeLimitError once it passes. Default: none.
  Deadline deadline{};
};

// The most points a size function may ask the engine to seed (about twice as many
// triangles): beyond it the size is a mistake (a jump of many orders of magnitude, a
// unit slip), and the error says so instead of exhausting memory.
inline constexpr double kMaxMeshPoints = 50e6;

struct DistMeshProblem {
  DistanceFunction domain;                    // d < 0 inside the domain
  SizeFunction size = constant_size(1.0);     // relative edge length, h > 0 in the domain
  double h0 = 0.0;                            // edge length where h is least
  Box bbox;                                   // where the initial lattice is spread
  std::vector<Vec2> fixed{};                  // mesh nodes that never move (corners)
  std::optional<DistanceFunction> interface{};  // internal boundary dI = 0 the mesh follows
  // Segments between fixed points (pairs of indices into `fixed`) that must be mesh
  // edges. When given, they are closed rings and the fixed points are the whole boundary
  // (the mesh stage's shared seeds): the mesh is a constrained Delaunay triangulation
  // whose inside is told by the rings, no point is seeded on or projected onto the
  // boundary, points that leave the domain are pulled back inside to half their size
  // from the boundary, and after the iterations poor triangles get Steiner points or lose
  // crowding points. Every fixed point is kept, in order.
  std::vector<std::array<int, 2>> constraints{};
  // The size function gives absolute lengths (not scaled so that its least value is h0);
  // h0 is then the finest lattice spacing and must not exceed the size anywhere.
  bool absolute_size = false;
  // Curved boundaries (of the domain and the interface) get edges of at most
  // curvature_angle radians, R curvature_angle long, growing by curvature_gradient per
  // unit distance away from them. 0 = no limit.
  double curvature_angle = 0.0;
  double curvature_gradient = 0.1;
  // > 0 (relative sizes only): the size grows at most this much per unit distance, so a
  // size function that jumps is graded first (mesh/size_grading.hpp). 0 = as given.
  double size_gradient = 0.0;
};

struct DistMeshStats {
  int iterations = 0;
  int retriangulations = 0;
  int rebuilds = 0;                 // of them, built anew (the rest repaired by flips)
  std::size_t flips = 0;            // edge flips of the repairs
  std::size_t inserted = 0;         // points added to a live triangulation by a walk
  double seeding_seconds = 0.0;       // the parts of `seconds`: seeding, triangulating,
  double triangulation_seconds = 0.0;  // ... and the finish after the force iterations
  double finish_seconds = 0.0;
  bool converged = false;           // false: the iteration limit stopped it
  std::string stop_reason;
  double lattice_spacing = 0.0;     // h0, or finer where curved boundaries ask for it
  bool size_graded = false;         // the size function was steeper than size_gradient
  std::size_t initial_points = 0;   // after rejection, fixed points included
  std::size_t density_removed = 0;  // points removed by density control
  std::size_t density_added = 0;    // points added on long boundary and interface edges
  int interface_repairs = 0;        // final passes needed to clear straddling triangles
  std::size_t interface_straddling = 0;  // triangles still crossing dI = 0 (0 unless broken)
  double seconds = 0.0;
};

struct DistMeshResult {
  TriMesh mesh;
  std::vector<int> phase;  // #T: 1 where the triangle lies inside the interface (dI < 0), else 0
  DistMeshStats stats;
};

}  // namespace grainmesh
