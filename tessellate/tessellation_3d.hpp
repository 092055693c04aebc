// The 3D tessellation stage: periodic Voronoi/Laguerre grains with phase labels in a
// W x H x D box, cut into the box as convex polyhedral regions with shared faces and
// exact periodic partners.
#pragma once

#include <array>
#include <cmath>
#include <utility>
#include <optional>
#include <utility>
#include <vector>

#include "common/deadline.hpp"
#include "common/periodic_pairs.hpp"
#include "common/random.hpp"
#include "common/vec3.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

struct Tessellation3Options {
  double width = 1.0;            // W, the caller's length unit
  double height = 1.0;           // H
  double depth = 1.0;            // D
  bool periodic = true;
  int grains = 100;              // N seeds
  std::vector<Vec3> seeds;       // given generator points in the box (N of them); empty = drawn
  int lloyd_iterations = 0;      // centroidal relaxation steps
  double size_cv = 0.0;          // coefficient of variation of the Laguerre radii; 0 = Voronoi
  double min_edge = 0.1;         // edges shorter than this x mean grain diameter are collapsed; 0 = off
  Arrangement arrangement = Arrangement::random;
  std::vector<Phase> phases;     // at least one; fractions are volume fractions
  // The contiguity `contiguity_phase` is to have, from face areas (grain mode's label
  // trades, as in 2D: contiguity.hpp); none: as the arrangement gives it.
  std::optional<double> contiguity;
  int contiguity_phase = -1;
  // Binder mode (binder_3d.hpp): the grains' cores in a matrix of phase `matrix_phase`; the
  // contiguity target (of the one grain phase) is met by the faces left without binder.
  PhaseMode phase_mode = PhaseMode::grain;
  int matrix_phase = -1;
  Deadline deadline{};           // asked every Lloyd step
};

// A planar convex polygon between two regions. The ring's right-hand normal points from
// `back` into `front`; front = -1 for a face on the box (the ring then turns
// counter-clockwise seen from outside).
struct Face3 {
  std::vector<int> ring;  // vertex ids
  int back = -1;
  int front = -1;
};

// One convex piece of a grain inside the box (a periodic grain the box cuts has several).
struct Region3 {
  int grain = 0;
  int phase = 0;
  std::vector<int> faces;  // face ids
  double volume = 0.0;
};

struct Grain3 {
  int id = 0;
  int phase = 0;
  Vec3 seed{};                  // generator point, in the box
  double volume = 0.0;          // summed over its pieces
  int faces = 0;                // faces of the whole (uncut) polyhedron
  std::vector<int> neighbours;  // grain ids sharing a face, ascending (on the torus when periodic)
  bool matrix = false;          // binder mode: the matrix, one grain for all its regions (the last)
};

struct Tessellation3Stats {
  // A contiguity target missed by more than kContiguityTolerance: the lowest and highest
  // contiguity the label trades reach from the same start (none when met).
  std::optional<std::pair<double, double>> contiguity_range;
  int grains = 0;                    // with a cell (hidden Laguerre cells and the matrix do not count)
  double binder_scale = 0.0;         // binder mode: the cores' scale of their cells (0: grain mode)
  int binder_contacts = 0;           // binder mode: faces two grains touch across
  double binder_layer = 0.0;         // binder mode: its mean thickness, 2 x its volume / its area with the grains
  int removed_grains = 0;            // hidden Laguerre cells
  double volume_mean = 0.0, volume_std = 0.0;
  double diameter_mean = 0.0, diameter_std = 0.0;  // equivalent-sphere diameters
  double faces_per_grain_mean = 0.0;
  double neighbours_mean = 0.0;
  double shortest_edge = 0.0;        // over the cut regions' edges
  double smallest_face = 0.0;        // area, over the cut regions' faces
  double sharpest_dihedral_deg = 0.0;  // interior angle between two faces of a region
  // Regularisation: edges below edge_threshold collapsed; the extremes before it.
  double edge_threshold = 0.0;
  int collapsed_edges = 0;
  int removed_regions = 0;           // slivers the box cut off a grain, flattened and removed
  double shortest_edge_before = 0.0;
  double sharpest_dihedral_before_deg = 0.0;
  Vec3 window_origin{};              // where the box was placed on the torus
  std::vector<PhaseStats> phases;    // fractions by volume; contiguity from face areas
};

struct Tessellation3 {
  double width = 1.0;
  double height = 1.0;
  double depth = 1.0;
  bool periodic = true;
  std::vector<Phase> phases;
  std::vector<Grain3> grains;
  std::vector<Vec3> vertices;
  std::vector<Face3> faces;
  std::vector<Region3> regions;
  PeriodicPairs partners;  // empty when not periodic
  Tessellation3Stats stats;

  Vec3 size() const { return {width, height, depth}; }
};

// The interior dihedral angle (radians, in (0, 2 pi)) of a solid at an edge through
// `on_edge` between faces A and B with outward unit normals n_a and n_b, `off_b` a point of
// B off the edge: pi minus the normals' angle where B bends in behind A's plane, pi plus
// it where the solid is reflex there (a fold reads near 2 pi, not as flat).
inline double interior_dihedral(Vec3 n_a, Vec3 n_b, Vec3 off_b, Vec3 on_edge) {
  const double c = dot(n_a, n_b);
  const double between = std::acos(c < -1.0 ? -1.0 : (c > 1.0 ? 1.0 : c));
  constexpr double pi = 3.14159265358979323846;
  return dot(n_a, off_b - on_edge) <= 0.0 ? pi - between : pi + between;
}

// The side of the box every vertex of `ring` lies on, as {axis, 0 low or 1 high}; axis -1
// when there is none. Exact: vertices on a side carry its coordinate.
std::pair<int, int> box_side(const Tessellation3& t, const std::vector<int>& ring);

// Volume of a region (its faces as stored) and area of a face.
double region_volume(const Tessellation3& t, const Region3& r);
double face_area(const Tessellation3& t, const Face3& f);

// Newell's normal of a ring of vertex ids, of length twice its area.
Vec3 ring_normal(const std::vector<Vec3>& p, const std::vector<int>& ring);

}  // namespace grainmesh
