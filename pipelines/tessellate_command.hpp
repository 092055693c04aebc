// `grainmesh tessellate CONFIG -o OUT`: a grain microstructure with phase labels, plane
// or solid (domain.depth set), written as OUT/tessellation.json, the viewer's file
// (tessellation.vtp, or .vtu in 3D), tessellation.png (3D: a section) and report.json
// (last).
#pragma once

#include <filesystem>

#include "pipelines/config.hpp"

namespace grainmesh {

void run_tessellate_command(const Config& config, const std::filesystem::path& out);

}  // namespace grainmesh
