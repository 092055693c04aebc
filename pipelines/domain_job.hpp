// A domain config (distance and size functions, the thesis' examples) read and checked
// into a meshing problem, and its mesh.
#pragma once

#include <cstdint>
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

}  // namespace grainmesh
