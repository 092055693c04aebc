// The tessellation stage's outputs, plane and solid cells alike: its files and pictures,
// the fields report.json gives the cell, and its summary lines (used by `grainmesh
// tessellate` and `grainmesh run`).
#pragma once

#include <filesystem>

#include "pipelines/drawing.hpp"
#include "pipelines/report.hpp"
#include "pipelines/tessellate_job.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// Writes tessellation.json and, when drawing.pictures, tessellation.png (2D: the cell; 3D:
// the section at the job's height, which when it cannot be drawn is a warning, not a
// failure) into `dir`; returns report.json's fields on the cell: dimensions, seed, width,
// height (depth), periodic, grains, phases, statistics, the counts (vertices, edges or
// faces, regions) and in 3D section_z.
Json write_tessellation_files(const std::filesystem::path& dir, const Tessellation& t, const TessellateJob<2>& job,
                              const Drawing& drawing, Warnings& warnings);
Json write_tessellation_files(const std::filesystem::path& dir, const Tessellation3& t, const TessellateJob<3>& job,
                              const Drawing& drawing, Warnings& warnings);

// The tessellation for viewers, into `dir`: tessellation.vtp (polygons) or
// tessellation.vtu (polyhedra).
void write_tessellation_viewer(const std::filesystem::path& dir, const Tessellation& t);
void write_tessellation_viewer(const std::filesystem::path& dir, const Tessellation3& t);

// The cell's one-line summary and its phases, on stdout.
void print_tessellation_summary(const Tessellation& t, double seconds);
void print_tessellation_summary(const Tessellation3& t, double seconds);

}  // namespace grainmesh
