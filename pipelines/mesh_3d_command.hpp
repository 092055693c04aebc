// `grainmesh mesh TESSELLATION.json -o OUT` for a 3D tessellation (version 2): OUT/
// mesh.vtu (VTK tetrahedra with grain, phase, region and quality), mesh.png (a section)
// and report.json (last) with the mesh's size, quality and seconds per stage.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "grains3d/grain_mesh_3d.hpp"
#include "pipelines/config.hpp"
#include "pipelines/report.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// The mesh keys of a 3D cell, read; the size per grain resolved against a tessellation by
// resolve_mesh_3d_job.
struct Mesh3Job {
  GrainMesh3Options options;
  int picture_width = 1200;  // pixels
  double section = 0.5;      // mesh.png: the section's height, a fraction of the depth
  std::optional<double> per_grain;  // mesh.tets_per_grain, when no size is given
  std::string size_key;             // mesh.size or mesh.h, when given
  ConfigOrigin origin;              // names the key at fault in resolve_mesh_3d_job's errors
};

// Reads and checks the mesh keys for a 3D tessellation: mesh.size (or mesh.h) or
// mesh.tets_per_grain (default 500), mesh.threads; the 2D-only keys refused by name.
Mesh3Job read_mesh_3d_job(const Config& config);
// The job for tessellation `t`: options.size from mesh.tets_per_grain; refuses (ConfigError
// naming the key) a size that asks for more than 2e7 tetrahedra.
Mesh3Job resolve_mesh_3d_job(Mesh3Job job, const Tessellation3& t);

// Meshes the cell and checks the mesh's conformity (check_conformity throws otherwise).
GrainMesh3 run_mesh_3d_job(const Tessellation3& t, const Mesh3Job& job);

// Writes mesh.vtu and, when `pictures`, mesh.png (the section at section_height, its
// scale bar in `length_unit`, empty: unnamed) into `dir`; returns what report.json says of
// the mesh (`mesh` with its quality, counts, seconds per stage, section_z); a sliver left
// in the mesh becomes a warning.
Json write_mesh_3d_files(const std::filesystem::path& dir, const Tessellation3& t, const GrainMesh3& m, const Mesh3Job& job,
                         Warnings& warnings, bool pictures, const std::string& length_unit);

// The mesh's one-line summary, on stdout, from the `mesh` write_mesh_3d_files reported.
void print_mesh_3d_summary(const Json& mesh, double seconds);

void run_mesh_3d_command(const Tessellation3& t, const std::filesystem::path& tessellation, const Config& config,
                         const std::filesystem::path& out);

}  // namespace grainmesh
