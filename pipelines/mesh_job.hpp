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

// A cell's mesh job, per dimension D (2: plane, 3: solid): the mesh keys, read; the size
// per grain (and, in 2D, per phase) resolved against a tessellation by resolve_mesh_job.
template <int D>
struct MeshJob;

template <>
struct MeshJob<2> {
  GrainMeshOptions options;
  int picture_width = 1200;  // pixels
  std::optional<double> per_grain;                          // mesh.triangles_per_grain, when no size is given
  std::string size_key;                                     // mesh.size or mesh.h, when given
  std::vector<std::pair<std::string, double>> phase_sizes;  // phase.NAME.size, by name
  ConfigOrigin origin;                                      // names the key at fault in resolve_mesh_job's errors

  const Deadline& deadline() const { return options.distmesh.deadline; }
};

template <>
struct MeshJob<3> {
  GrainMesh3Options options;
  int picture_width = 1200;  // pixels
  double section = 0.5;      // mesh.png: the section's height, a fraction of the depth
  std::optional<double> per_grain;  // mesh.tets_per_grain, when no size is given
  std::string size_key;             // mesh.size or mesh.h, when given
  ConfigOrigin origin;              // names the key at fault in resolve_mesh_job's errors

  const Deadline& deadline() const { return options.deadline; }
};

// Reads and checks the mesh keys (all that can be checked without the tessellation): the
// size (mesh.size or mesh.h) or elements per grain (mesh.triangles_per_grain, default
// 100; mesh.tets_per_grain, default 500), mesh.threads; in 3D the 2D-only keys refused by
// name. Throws ConfigError naming the key.
template <int D>
MeshJob<D> read_mesh_job(const Config& config);
template <>
MeshJob<2> read_mesh_job<2>(const Config& config);
template <>
MeshJob<3> read_mesh_job<3>(const Config& config);

// The job for tessellation `t`: options.size from the elements per grain; in 2D
// options.phase_size by the tessellation's phases. Refuses (ConfigError naming the key) an
// unknown phase and a size that asks for more than 2 kMaxMeshPoints triangles or 2e7
// tetrahedra.
MeshJob<2> resolve_mesh_job(MeshJob<2> job, const Tessellation& t);
MeshJob<3> resolve_mesh_job(MeshJob<3> job, const Tessellation3& t);

// A resolved job's sizes (element edge lengths: the size, per phase, on boundaries and at
// junctions) times `factor`: the same cell meshed coarser (the finite elements' coarse
// level, factor 2).
MeshJob<2> scaled_mesh_job(MeshJob<2> job, double factor);
MeshJob<3> scaled_mesh_job(MeshJob<3> job, double factor);

// Both at once (the mesh command's and the tests' way).
MeshJob<2> read_mesh_job(const Config& config, const Tessellation& t);
MeshJob<3> read_mesh_job(const Config& config, const Tessellation3& t);

}  // namespace grainmesh
