// The dual's phase interfaces (polymesh_dual_3d.cpp): which points lie on one, and how a
// point on one weighs in the means that place the dual's corners about it.
#pragma once

#include <vector>

#include "export/export_mesh.hpp"
#include "export/foam_material.hpp"

namespace grainmesh {

// #points: 1 where tetrahedra of two phases meet at the point, counting a periodic
// point's images'.
std::vector<char> interface_points(const ExportMesh<3>& m);

// Per phase: an interface point's weight in the means of the corners around it in that
// phase, so that its cell there reaches the fraction sqrt(gamma_p / gamma_max) / 2 of its
// edges into the phase (a half in the stiffest).
std::vector<double> interface_weights(const std::vector<FoamPhase>& phases);

}  // namespace grainmesh
