// `grainmesh tessellate CONFIG -o OUT` for a 3D cell (domain.depth set): OUT/
// tessellation.json (version 2), tessellation.vtu (VTK polyhedra), tessellation.png (a
// section) and report.json (last).
#pragma once

#include <cstdint>
#include <filesystem>

#include "pipelines/config.hpp"
#include "pipelines/report.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

struct Tessellate3Job {
  Tessellation3Options options;
  std::uint64_t seed = 1;
  int picture_width = 1200;  // pixels
  double section = 0.5;      // the section's height, as a fraction of the depth
  ConfigOrigin origin;       // names the key at fault in errors found while tessellating
};

// Reads and checks a 3D tessellation config (the keys of tessellate_config_keys(); the
// 2D-only ones refused by name). Throws ConfigError naming the key.
Tessellate3Job read_tessellate_3d_job(const Config& config);

// Tessellates (randomness from job.seed only). A phase with no grain fails naming its
// fraction key; a fraction missed by more than 1 % becomes a warning.
Tessellation3 run_tessellate_3d_job(const Tessellate3Job& job, Warnings& warnings);

// Writes tessellation.json, tessellation.vtu and, when `pictures`, tessellation.png (the
// section at section_height: a laminate's face may lie in the plane asked for), its scale
// bar in `length_unit` (empty: the config's own, unnamed), into `dir`; returns what
// report.json says of the cell (seed, box, statistics, counts, section_z). A section that
// cannot be drawn is a warning, not a failure.
Json write_tessellation_3d_files(const std::filesystem::path& dir, const Tessellation3& t, const Tessellate3Job& job,
                                 bool pictures, const std::string& length_unit, Warnings& warnings);

// The cell's one-line summary and its phases, on stdout.
void print_tessellation_3d_summary(const Tessellation3& t, double seconds);

void run_tessellate_3d_command(const Config& config, const std::filesystem::path& out);

}  // namespace grainmesh
