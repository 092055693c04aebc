// `grainmesh run CONFIG -o OUT` on a 3D config (domain.depth set): tessellate and mesh in
// one process. Writes OUT/tessellation.json, tessellation.vtu, tessellation.png, mesh.vtu,
// mesh.png (sections), config.ini (the resolved config) and report.json, last. OpenFOAM
// cases of 3D cells are not written yet: --solve and the export, load, solve and
// homogenise keys are refused by name.
#pragma once

#include <filesystem>

#include "pipelines/config.hpp"

namespace grainmesh {

// The config's keys are known (check_keys against run_config_keys()) before this.
void run_run_3d_command(const Config& config, const std::filesystem::path& out, bool solve, bool quiet, bool summary);

}  // namespace grainmesh
