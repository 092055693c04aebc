// `grainmesh export MESH.vtu -o CASE`: a mesh written by `grainmesh mesh` or `grainmesh
// domain` (mesh.vtu and the mesh.json beside it) to an OpenFOAM case for
// solidDisplacementFoam.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "export/export_mesh.hpp"
#include "export/foam_options.hpp"
#include "pipelines/config.hpp"
#include "pipelines/output_dir.hpp"
#include "view/mesh_description.hpp"

namespace grainmesh {

// The keys an export config (or --set) may use ("*" is a phase name).
const std::vector<std::string>& export_config_keys();

// Reads mesh.vtu and its mesh.json, applies the config (options, phase moduli) and
// checks it. Throws IoError (files), GeometryError (their contents), ConfigError (keys).
ExportMesh<2> read_export_mesh(const std::filesystem::path& mesh_file, const Config& config);
FoamOptions read_foam_options(const Config& config);

// The whole command: the case in a staging directory renamed into place, report.json last.
void run_export_command(const std::filesystem::path& mesh_file, const Config& config, const std::filesystem::path& out);

}  // namespace grainmesh
