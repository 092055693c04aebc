// The keys a 2D and a 3D tessellation share, read from a config: the diagram's settings and
// the phases. Each throws ConfigError naming the key at fault.
#pragma once

#include <string>
#include <vector>

#include "common/vec3.hpp"
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
// The grain count of a cell of `dimensions` (2 or 3) with extent `box` (its depth unused in
// 2D): from tessellation.grains (default 100), .grain_size (the mean equivalent-circle or
// -sphere diameter) or .seeds ("x y, x y, ..." or "x y z, x y z, ...", each inside the
// box; then the seeds too). At most ten million grains in 2D, a million in 3D.
struct GrainCount {
  int grains = 0;
  std::vector<Vec3> seeds;  // given ones; z = 0 in 2D
};
GrainCount read_grain_count(const Config& c, Vec3 box, int dimensions);
// The [phase.NAME] sections: fractions (one may be rest), E, nu, alpha.
std::vector<Phase> read_phases(const Config& c);
// The keys that would draw grains (tessellation.grains, .seeds, ...) refused, when the
// grains come `from` a file.
void refuse_drawing_keys(const Config& c, const std::string& from);

}  // namespace grainmesh
