// The size field of a tessellation's mesh: the phases' sizes, lowered near short edges and
// thin layers and to the boundary and junction sizes, growing away by the gradient.
#pragma once

#include "grains/feature_size.hpp"
#include "grains/grain_mesh_options.hpp"

namespace grainmesh {

// The size field of a tessellation: the phase sizes, lowered near short edges and thin
// layers (when options.feature_size) and to the boundary and junction sizes, growing away
// from them by the gradient. Its base is the largest phase size.
FeatureSize tessellation_size(const Tessellation& t, const GrainMeshOptions& options);

}  // namespace grainmesh
