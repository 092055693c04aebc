// Which cells of a polyMesh to join so that checkMesh's failures go away: a builder whose
// cells are unions of smaller pieces (the 3D dual's tetrahedron corners) joins them and
// builds again.
#pragma once

#include <vector>

#include "common/vec3.hpp"
#include "export/foam_mesh_check.hpp"
#include "export/polymesh.hpp"
#include "export/polymesh_3d.hpp"

namespace grainmesh {

// Each cell's number after joining (#cells; joined cells numbered in the order of their
// lowest old number), or empty when no join helps. For each failing face of `failures`
// (FoamMeshCheck's on this mesh), its smaller cell is joined with one or all of its
// neighbours of its grain (across internal faces, never a cyclic one), and the other cell
// likewise or not at all, whichever most reduces the failures on the cells' faces; of
// their phase where nothing inside the grains helps; a failing cell is joined the same
// way. The joins are judged on this mesh, one after another: a joined cell's volume is
// its parts' sum and its centre their mean by volume, its faces theirs but those between
// them; the faces of a new cell that fail go back on the list. The builder builds again
// and calls again (the rebuilt faces bend a little differently). `grain` and `phase` are
// per cell; `centre` and `volume` foam_cell_geometry's.
std::vector<int> joined_cells(const PolyMesh& pm, const std::vector<int>& grain, const std::vector<int>& phase,
                              const std::vector<Vec3>& centre, const std::vector<double>& volume,
                              const FoamCheckFailures& failures);

// The 3D dual's cells before a build (`cells`: grain, phase, corner_cell) joined as
// `number` (joined_cells's on the built dual `built`) has them: a cell joined across
// grains of one phase takes its largest part's grain.
void join_cells(const std::vector<int>& number, const FoamMesh3& built, FoamMesh3& cells);

}  // namespace grainmesh
