// `grainmesh tessellate CONFIG -o OUT` for a 3D cell (domain.depth set): OUT/
// tessellation.json (version 2), tessellation.vtu (VTK polyhedra), tessellation.png (a
// section) and report.json (last).
#pragma once

#include <cstdint>
#include <filesystem>

#include "pipelines/config.hpp"
#include "pipelines/report.hpp"
#include "pipelines/tessellate_job.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

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
