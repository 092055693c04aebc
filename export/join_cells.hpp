// Which cells of a polyMesh to join so that checkMesh's failures go away: a builder whose
// cells are unions of smaller pieces (the 3D dual's tetrahedron corners) joins them and
// builds again.
#pragma once

#include <vector>

#include "common/vec3.hpp"
#include "export/polymesh.hpp"

namespace grainmesh {

// Each cell's number after joining (#cells; joined cells numbered in the order of their
// lowest old number), or empty when no join helps. For each cell and face checkMesh would
// fail (foam_mesh_check.hpp), one of its cells (the smaller first) is joined with the
// neighbour of its grain (across an internal face, never a cyclic one) for which the
// failures on the two cells' faces drop the most, judged with the joined cell's centre at
// the two centres' mean by volume; no join where none drops them. A cell whose faces'
// verdicts a join has changed waits for the next round (build, then call again). `grain`
// is per cell; `centre` and `volume` are foam_cell_geometry's.
std::vector<int> joined_cells(const PolyMesh& pm, const std::vector<int>& grain, const std::vector<int>& phase,
                              const std::vector<Vec3>& centre, const std::vector<double>& volume);

}  // namespace grainmesh
