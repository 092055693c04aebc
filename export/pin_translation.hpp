// A fully periodic cell fixes no translation: its displacement equation is singular, and
// OpenFOAM's linear solvers can blow up on the rounding noise of a component whose
// solution is zero (GAMG on a one-material cell: a residual of 1e26). Stock OpenFOAM's
// way to fix a displacement is a fixedValue patch, so one face pair of the left/right
// cyclic pair becomes two plain patches, pin_left and pin_right, whose displacement the
// case fixes at the imposed mean strain's (export/foam_case.cpp).
//
// Why the answer does not change: the two pinned faces replace one cyclic face pair, so
// they fix the translation (three unknowns) and drop the balance of that one pair (three
// equations). Every cell's forces add up to zero at convergence, internal and cyclic
// faces cancel in the sum over the cell, so the forces through the two pinned faces are
// equal and opposite: the balance the cyclic pair held is met anyway, and the solution
// is the periodic one up to its translation. (One material: exactly the affine field.)
#pragma once

#include <string>
#include <vector>

#include "export/polymesh.hpp"

namespace grainmesh {

// The pinned faces' patch names; pin_left's face pairs with pin_right's as a cyclic one.
inline constexpr const char* kPinPatchLow = "pin_left";
inline constexpr const char* kPinPatchHigh = "pin_right";
// Whether patch `p` is one of them.
bool is_pin_patch(const PolyMesh::Patch& p);
// The pin patch on the cyclic side `side` ("left" or "right"), or empty for other sides.
std::string pin_patch_of(const std::string& side);

// Moves one face pair of the cyclic patches left/right (face k of each: they pair) into
// the patches pin_left and pin_right, each right after its side's patch: a pair whose two
// cells are of one phase and have no neighbour of another (inside a phase, where the
// field is smooth), the first such from the middle of the side; any pair when there is
// none. Sets each pin patch's `at` to where its displacement is fixed (the foot of the
// perpendicular from its cell's centre to the face: see pin_translation.cpp), mesh units
// from `origin`. Does nothing to a mesh without a cyclic left/right pair or with a
// single face on it. `phase` is per cell.
void pin_translation(PolyMesh& pm, const std::vector<int>& phase, Vec3 origin);

}  // namespace grainmesh
