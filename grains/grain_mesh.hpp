// The mesh stage on a tessellation: every edge seeded once, every region meshed by the
// DistMesh engine with its seeded boundary fixed, the pieces merged into one conforming
// mesh with a grain and a phase per triangle and, when periodic, paired side nodes.
#pragma once

#include "grains/grain_mesh_options.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

// Meshes every region (in parallel; the result does not depend on the thread count) and
// merges them. Throws GeometryError when a region cannot be meshed.
GrainMesh mesh_tessellation(const Tessellation& t, const GrainMeshOptions& options);

}  // namespace grainmesh
