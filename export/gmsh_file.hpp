// A grain mesh as a Gmsh MSH 4.1 file (ASCII), the format Gmsh, meshio and the codes built
// on them (FEniCS/DOLFINx, GetFEM, Elmer) read.
#pragma once

#include <filesystem>

#include "export/element_mesh.hpp"

namespace grainmesh {

// Writes `m` to `file`: the nodes classified on the sides they lie on (else in a grain),
// tagged entity by entity as Gmsh numbers them; one elementary entity per grain (surfaces in 2D, volumes in 3D,
// tag = its index among the grains + 1; elements tagged as their index in `m` + 1), one
// per side of the cell (curves in 2D, surfaces in 3D, tags 1.. in side order) carrying
// the side's facets; physical groups per phase (named after it, tags 1..), per grain
// ("grain_G", tags after the phases') and per side ("left" ... "front"), a grain's entity
// in its phase's group first; for a periodic cell, one $Periodic link per axis (the high
// side's entity to the low side's, with the translation) listing each periodic pair once.
// Through a temporary file and a rename; IoError when it cannot be written.
void write_gmsh(const std::filesystem::path& file, const ElementMesh& m);

}  // namespace grainmesh
