// A grain mesh as an Abaqus input file (.inp, model data only), which Abaqus, CalculiX and
// meshio read.
#pragma once

#include <filesystem>
#include <string>

#include "export/element_mesh.hpp"

namespace grainmesh {

struct AbaqusOptions {
  bool plane_stress = false;  // 2D: CPS3 elements, else plane strain CPE3
  std::string length_unit;    // what one length unit of the nodes is, for the header ("um")
};

// Writes `m` to `file`: the nodes, the elements (CPE3/CPS3 or C3D4, element set ALL), an
// element set per grain (GRAIN_G) and per phase (PHASE_NAME), a node set per side (LEFT ...
// FRONT), a material per phase (*Elastic E, nu in Pa; *Expansion alpha where not zero)
// with its solid section (2D: unit thickness). A periodic cell gets one reference node
// per axis (node sets RP_X, RP_Y[, RP_Z]; their displacement is the jump across the cell
// along that axis) and one *Equation per tied point and direction: u(point) - u(root) -
// sum of the reference nodes of the axes crossed = 0, each point on a high side tied
// once, straight to its root (periodic_ties). Through a temporary file and a rename.
void write_abaqus(const std::filesystem::path& file, const ElementMesh& m, const AbaqusOptions& options);

}  // namespace grainmesh
