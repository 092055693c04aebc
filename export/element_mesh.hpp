// A grain mesh as linear finite elements, one contract for plane and solid cells, for the
// writers of other solvers' mesh files (gmsh_file.hpp, abaqus_file.hpp): its nodes, its
// elements with a grain and a phase each, the facets on each side of the cell, and the
// periodic ties that make a periodic boundary condition.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "common/vec3.hpp"
#include "export/export_mesh.hpp"

namespace grainmesh {

struct ElementMesh {
  int dimensions = 2;
  std::vector<Vec3> points;                  // #P, z = 0 in 2D
  std::vector<std::array<int, 4>> elements;  // #E point ids: triangles (the first 3, counter-clockwise) or
                                             // positive tetrahedra
  std::vector<int> grain;                    // #E
  std::vector<int> phase;                    // #E, index into phases
  std::vector<FoamPhase> phases;
  Box3 cell;                                 // the sides: s = 2 axis + (0 low, 1 high)
  bool periodic = false;
  PeriodicPairs pairs;                       // per axis (low side point, high side point)

  int corners() const { return dimensions + 1; }
  int sides() const { return 2 * dimensions; }
};

// The elements of a plane export mesh of triangles (GeometryError for polygonal cells:
// the polygons' triangles are what a finite-element code takes) or of a solid one.
ElementMesh element_mesh(const ExportMesh<2>& m);
ElementMesh element_mesh(const ExportMesh<3>& m);

// The name of side s (left, right, bottom, top, back, front).
const char* side_name(const ElementMesh& m, int s);

// The facets on each side of the cell: per side, the corners of the element facets lying
// on it (edges in 2D, the third corner -1; triangles in 3D), in the order of the elements.
std::vector<std::vector<std::array<int, 3>>> side_facets(const ElementMesh& m);

// The points on each side of the cell (exactly on it, as the mesh puts them), ascending.
std::vector<std::vector<int>> side_points(const ElementMesh& m);

// A periodic cell's point on a high side tied to its image on the low sides: u(point) =
// u(root) + the jump across each axis in `across`. The root lies on no high side; a point
// on a high edge or corner is tied straight to the root (never through another tied
// point), so each tied point appears in one tie only.
struct PeriodicTie {
  int point = -1;
  int root = -1;
  std::array<bool, 3> across{};
};
// One tie per point on a high side, ascending by point; none for a cell that is not
// periodic. GeometryError when a pair list ties a point to two roots.
std::vector<PeriodicTie> periodic_ties(const ElementMesh& m);

// The grains the elements carry, ascending.
std::vector<int> grains_of(const ElementMesh& m);

}  // namespace grainmesh
