// The keys a 2D and a 3D tessellation share, read from a config: the diagram's settings and
// the phases. Each throws ConfigError naming the key at fault.
#pragma once

#include <vector>

#include "pipelines/config.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

// The diagram's keys shared by 2D and 3D: tessellation.lloyd_iterations, .size_cv,
// .min_edge (default `min_edge`) and .arrangement.
struct DiagramSettings {
  int lloyd_iterations = 0;
  double size_cv = 0.0;
  double min_edge = 0.0;
  Arrangement arrangement = Arrangement::random;
};
DiagramSettings read_diagram_settings(const Config& c, double min_edge);
// The [phase.NAME] sections: fractions (one may be rest), E, nu, alpha.
std::vector<Phase> read_phases(const Config& c);

}  // namespace grainmesh
