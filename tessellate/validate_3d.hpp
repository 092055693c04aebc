// The invariants of a cut 3D tessellation.
#pragma once

#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// Invariants a bug could break: region volumes sum to W H D, every face between two
// regions or on the box, each region closed and outward oriented, partners exact.
// Throws GeometryError naming the first violation.
void validate(const Tessellation3& t);

}  // namespace grainmesh
