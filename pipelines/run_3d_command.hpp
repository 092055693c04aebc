// `grainmesh run CONFIG -o OUT` on a 3D config (domain.depth set): tessellate, mesh and
// write the OpenFOAM cases (the mixed load's case/, or the periodic cell's six
// case_NAME/) in one process, and with --solve solve and homogenise them (answer_3d.hpp).
// Writes OUT/tessellation.json, tessellation.vtu, tessellation.png, mesh.vtu, mesh.png
// (sections), the cases, stress_xx.png and von_mises.png when solved, config.ini (the
// resolved config) and report.json, last.
#pragma once

#include <filesystem>

#include "pipelines/config.hpp"

namespace grainmesh {

// The config's keys are known (check_keys against run_config_keys()) before this.
void run_run_3d_command(const Config& config, const std::filesystem::path& out, bool solve, bool quiet, bool summary);

}  // namespace grainmesh
