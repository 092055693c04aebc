// `grainmesh domain CONFIG -o OUT`: meshes a domain given by distance and size functions
// (the thesis' examples), writing OUT/mesh.vtu, OUT/mesh.json, OUT/mesh.png and
// OUT/report.json (last).
#pragma once

#include <filesystem>

#include "pipelines/config.hpp"
#include "pipelines/domain_job.hpp"

namespace grainmesh {

// Meshes the config and writes the outputs into `out`, atomically, report.json last.
void run_domain_command(const Config& config, const std::filesystem::path& out);

}  // namespace grainmesh
