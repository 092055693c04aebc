// What a config asks of the tessellation stage, read and checked (the tessellation
// keys, tessellate_config_keys()), and the stage run on it: a plane cell's job and a solid
// one's (their keys' meanings differ: binder mode and contiguity in 2D so far, the
// section's height in 3D).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "pipelines/config.hpp"
#include "pipelines/image_input.hpp"
#include "pipelines/phase_checks.hpp"
#include "pipelines/report.hpp"
#include "tessellate/neper_tess.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// A cell's tessellation job, per dimension D (2: plane, 3: solid).
template <int D>
struct TessellateJob;

// tessellation.neper: a Neper tessellation read instead of one drawn (the cell is its
// domain, periodic when the file is; the phases from its cell groups through
// tessellation.neper_phases, else by our rules).
struct NeperInput {
  std::filesystem::path file;  // empty: none
  NeperTess tess;
  std::vector<LabelPhase> group_phases;  // empty: phases by our rules
};

template <>
struct TessellateJob<2> {
  TessellationOptions options;
  std::uint64_t seed = 1;
  int picture_width = 1200;  // pixels
  ConfigOrigin origin;       // names the key at fault in errors found while tessellating
  NeperInput neper;
  ImageInput image;
};

template <>
struct TessellateJob<3> {
  Tessellation3Options options;
  std::uint64_t seed = 1;
  int picture_width = 1200;  // pixels
  double section = 0.5;      // the section's height, as a fraction of the depth
  ConfigOrigin origin;       // names the key at fault in errors found while tessellating
  NeperInput neper;
};

// Reads and checks a tessellation config of a D-dimensional cell (3: domain.depth set,
// the 2D-only keys refused by name). Throws ConfigError naming the key.
template <int D>
TessellateJob<D> read_tessellate_job(const Config& config);
template <>
TessellateJob<2> read_tessellate_job<2>(const Config& config);
template <>
TessellateJob<3> read_tessellate_job<3>(const Config& config);

// Tessellates with randomness from the job's seed alone. A binder fraction (2D) or a
// contiguity target (2D) out of reach is refused naming its key (ConfigError); the 3D
// stage's own check failing is a GeometryError saying so.
Tessellation run_tessellate_job(const TessellateJob<2>& job);
Tessellation3 run_tessellate_job(const TessellateJob<3>& job);

// What the tessellation's phases tell the user before it is meshed (phase_checks.hpp): a
// phase left without grains refused (ConfigError naming its fraction key, through the
// job's origin), a fraction missed by more than 0.01 a warning.
void check_phases(const Tessellation& t, const TessellateJob<2>& job, Warnings& warnings);
void check_phases(const Tessellation3& t, const TessellateJob<3>& job, Warnings& warnings);

}  // namespace grainmesh
