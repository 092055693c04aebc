// `grainmesh domain CONFIG -o OUT`: meshes a domain given by distance and size functions
// (the thesis' examples), writing OUT/mesh.vtu, OUT/mesh.json, OUT/mesh.png and
// OUT/report.json (last).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/distmesh.hpp"
#include "pipelines/config.hpp"

namespace grainmesh {

// A domain config turned into a meshing problem.
struct DomainJob {
  DistMeshProblem problem;
  DistMeshOptions options;
  std::uint64_t seed = 1;
  int picture_width = 1200;  // pixels
};

// The keys a domain config may use.
const std::vector<std::string>& domain_config_keys();

// Reads and checks a domain config. Throws ConfigError or GeometryError naming the key.
DomainJob read_domain_job(const Config& config);

// Meshes the job's problem with randomness from the job's seed alone.
DistMeshResult mesh_domain(const DomainJob& job);

// Meshes the config and writes the outputs into `out`, atomically, report.json last.
void run_domain_command(const Config& config, const std::filesystem::path& out);

}  // namespace grainmesh
