// What a config asks of the mesh stage, read and checked (the mesh keys,
// mesh_config_keys()) before any work, then resolved against the tessellation it meshes
// (sizes per grain need its grain count, per phase its phases): a plane cell's job and a
// solid one's (their keys differ: grading, boundary and junction sizes in 2D so far).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "grains/grain_mesh_options.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "pipelines/config.hpp"
#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// The mesh keys, read; the size per grain and per phase resolved against a tessellation
// by resolve_mesh_job.
struct MeshJob {
  GrainMeshOptions options;
  int picture_width = 1200;  // pixels
  std::optional<double> per_grain;                          // mesh.triangles_per_grain, when no size is given
  std::string size_key;                                     // mesh.size or mesh.h, when given
  std::vector<std::pair<std::string, double>> phase_sizes;  // phase.NAME.size, by name
  ConfigOrigin origin;                                      // names the key at fault in resolve_mesh_job's errors
};

// Reads and checks the mesh keys (all that can be checked without the tessellation).
// Throws ConfigError naming the key.
MeshJob read_mesh_job(const Config& config);
// The job for tessellation `t`: options.size from mesh.triangles_per_grain and the grains'
// mean area, options.phase_size by the tessellation's phases; refuses (ConfigError naming
// the key) an unknown phase and a size that asks for more than 2 kMaxMeshPoints triangles.
MeshJob resolve_mesh_job(MeshJob job, const Tessellation& t);
// Both at once (the mesh command's and the tests' way).
MeshJob read_mesh_job(const Config& config, const Tessellation& t);

// The mesh keys of a 3D cell, read; the size per grain resolved against a tessellation by
// resolve_mesh_job.
struct Mesh3Job {
  GrainMesh3Options options;
  int picture_width = 1200;  // pixels
  double section = 0.5;      // mesh.png: the section's height, a fraction of the depth
  std::optional<double> per_grain;  // mesh.tets_per_grain, when no size is given
  std::string size_key;             // mesh.size or mesh.h, when given
  ConfigOrigin origin;              // names the key at fault in resolve_mesh_job's errors
};

// Reads and checks the mesh keys for a 3D tessellation: mesh.size (or mesh.h) or
// mesh.tets_per_grain (default 500), mesh.threads; the 2D-only keys refused by name.
Mesh3Job read_mesh_3d_job(const Config& config);
// The job for tessellation `t`: options.size from mesh.tets_per_grain; refuses (ConfigError
// naming the key) a size that asks for more than 2e7 tetrahedra.
Mesh3Job resolve_mesh_job(Mesh3Job job, const Tessellation3& t);

}  // namespace grainmesh
