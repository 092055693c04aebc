// The invariants of a cut 2D tessellation.
#pragma once

#include "tessellate/tessellation.hpp"

namespace grainmesh {

// Invariants a bug could break: areas, ring orientation and simplicity, edge sides,
// partner positions. Throws GeometryError naming the first violation.
void validate(const Tessellation& t);

}  // namespace grainmesh
