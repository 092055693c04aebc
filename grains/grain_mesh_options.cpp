#include "grains/grain_mesh_options.hpp"

namespace grainmesh {

double region_size(const GrainMeshOptions& o, int phase) {
  if (phase >= 0 && static_cast<std::size_t>(phase) < o.phase_size.size() && o.phase_size[phase] > 0.0)
    return o.phase_size[phase];
  return o.size;
}

}  // namespace grainmesh
