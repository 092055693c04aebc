// Makes a labelled triangle mesh fit for Voronoi cells: Delaunay inside each label, and no
// edge that bounds a label (a label boundary or the mesh's boundary) encroached, so that
// each triangle's circumcentre lies in its own label and the dual's faces meet the mesh
// edges at right angles right up to the boundaries (the admissibility condition of the
// Voronoi box method). The dual mesh works on this copy.
#pragma once

#include <cstddef>
#include <vector>

#include "common/periodic_pairs.hpp"
#include "mesh/trimesh.hpp"

namespace grainmesh {

// A triangle encroaches an edge of its that bounds its label when its angle opposite that
// edge exceeds this: at 90 degrees its circumcentre reaches the edge, and near 90 the dual
// face from the edge's midpoint to the circumcentre is very short.
inline constexpr double kEncroachDegrees = 85.0;

struct ConformingMesh {
  TriMesh mesh;
  std::vector<int> label;   // #T
  std::vector<int> origin;  // #T: the input triangle it was cut from or flipped with (same label)
  PeriodicPairs pairs;      // the input's, extended to the split side edges' midpoints
  std::size_t splits = 0;   // edges split at their midpoints (a periodic side edge and its image: two)
  std::size_t flips = 0;
  std::size_t encroaching = 0;  // triangles still encroaching an edge after the last round
};

// Splits every encroached edge at its midpoint (a periodic side edge together with its
// image, whose midpoints are paired), then flips the edges inside each label that are not
// locally Delaunay; repeated for a few rounds, since a split can leave a shorter edge
// encroached near a sharp corner. Label boundaries and sides keep their exact geometry,
// so each label's area is unchanged. Throws GeometryError for labels not one per triangle.
ConformingMesh conforming_delaunay(const TriMesh& mesh, const std::vector<int>& label, const PeriodicPairs& pairs);

}  // namespace grainmesh
