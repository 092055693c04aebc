// What a config asks of the tessellation stage, read and checked (the tessellation
// keys, tessellate_config_keys()), and the stage run on it: a plane cell's job and a solid
// one's (their keys' meanings differ: binder mode and contiguity in 2D so far, the
// section's height in 3D).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pipelines/config.hpp"
#include "pipelines/phase_checks.hpp"
#include "pipelines/report.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

struct TessellateJob {
  TessellationOptions options;
  std::uint64_t seed = 1;
  int picture_width = 1200;  // pixels
  ConfigOrigin origin;       // names the key at fault in errors found while tessellating
};

struct Tessellate3Job {
  Tessellation3Options options;
  std::uint64_t seed = 1;
  int picture_width = 1200;  // pixels
  double section = 0.5;      // the section's height, as a fraction of the depth
  ConfigOrigin origin;       // names the key at fault in errors found while tessellating
};

// Reads and checks a tessellation config. Throws ConfigError naming the key.
TessellateJob read_tessellate_job(const Config& config);
// The same for a 3D cell (domain.depth set; the 2D-only keys refused by name).
Tessellate3Job read_tessellate_3d_job(const Config& config);

// Tessellates with randomness from the job's seed alone; a contiguity target out of reach
// refused (ConfigError naming the key).
Tessellation run_tessellate_job(const TessellateJob& job);
// Tessellates a 3D cell (randomness from job.seed only). A phase with no grain fails
// naming its fraction key; a fraction missed by more than 0.01 becomes a warning.
Tessellation3 run_tessellate_job(const Tessellate3Job& job, Warnings& warnings);

}  // namespace grainmesh
