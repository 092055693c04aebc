// Binder mode in 3D: every whole Laguerre cell split into a core (the cell scaled about
// its centre) and one frustum per face (laguerre_3d.hpp's Layering); the frustums are the
// binder, except on the faces chosen as contacts, where both cells' frustums join their
// grains so that the two grains touch across the whole face. Volumes and areas of every
// piece are closed-form in the scale s: a core has s^3 of its cell's volume, a frustum
// (1 - s^3) of its pyramid over the face, an inner face s^2 of the face's area, a side
// (1 - s^2) of the triangle from the centre to its edge. So the scale that leaves the
// binder its fraction, and the contiguity a set of contacts gives, are computed without
// cutting anything.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "common/random.hpp"
#include "common/vec3.hpp"
#include "tessellate/laguerre_3d.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// The smallest core scale: thinner cores than this (binder more than half of a cell's
// volume) are refused.
inline constexpr double kMinCoreScale3 = 0.6;

struct BinderLayout3 {
  double scale = 1.0;
  std::vector<std::vector<char>> contact;  // per seed, per whole face: its frustum is the grain's
  int contacts = 0;                        // touching face pairs
  double contiguity = 0.0;                 // of the grains, from the areas
  // A contiguity target missed by more than kContiguityTolerance: the contiguity with no
  // contact and with the most the binder's fraction allows.
  std::optional<std::pair<double, double>> range;
};

// The centre each cell is scaled about: its seed when the cells are Voronoi cells (the
// layer between two grains is then as thick on both sides of their face), else the cell's
// centroid; in the whole cell's coordinates.
std::vector<Vec3> layer_centres(const std::vector<std::vector<WholeFace>>& whole, const std::vector<Vec3>& seeds,
                                bool voronoi);

// The scale and contacts for a binder of `fraction` of the box's `volume` and, if set, the
// grains' contiguity target: contacts drawn in a seeded order (one per face pair, none
// with a cell's own image), their number by bisection. Throws ConfigError naming the
// fraction when even no contact leaves the cores below kMinCoreScale3.
BinderLayout3 binder_layout_3d(const std::vector<std::vector<WholeFace>>& whole, const std::vector<Vec3>& centres,
                               double volume, double fraction, std::optional<double> contiguity, Rng& rng);

// The grains' phases (all but the matrix), by volume and the arrangement, with the matrix
// grain's (the last) appended.
std::vector<int> binder_phases(const Tessellation3& t, const Tessellation3Options& o, Rng& rng);

}  // namespace grainmesh
