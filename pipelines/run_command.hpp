// `grainmesh run [CONFIG] -o OUT`: tessellate, mesh and export in one process, from one
// config (or the embedded default, data/default.ini). Writes OUT/tessellation.json,
// tessellation.png, mesh.vtu, mesh.json, mesh.png, case/ (the OpenFOAM case), config.ini
// (the resolved config, which repeats the run exactly) and report.json, last; with
// --solve the case is solved and homogenised too.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "pipelines/config.hpp"
#include "pipelines/run_config.hpp"

namespace grainmesh {

// With `solve`, also runs solidDisplacementFoam on the case and homogenises (report.json
// "effective"); a run that does not converge fails.
// A terminal shows the stage and the meshing's progress on stderr unless `quiet`; the
// summary goes to stdout when `summary`.
void run_run_command(const Config& config, const std::filesystem::path& out, bool solve = false, bool quiet = false,
                     bool summary = true);

}  // namespace grainmesh
