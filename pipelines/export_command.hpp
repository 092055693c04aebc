// `grainmesh export MESH.vtu -o CASE`: a mesh written by `grainmesh mesh` or `grainmesh
// domain` (mesh.vtu and the mesh.json beside it) to an OpenFOAM case for
// solidDisplacementFoam. Also the mesh.json both stages write.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "export/foam.hpp"
#include "pipelines/config.hpp"
#include "pipelines/output_dir.hpp"

namespace grainmesh {

// mesh.json: what mesh.vtu does not say. Phases without known moduli have them unset.
struct MeshDescription {
  Box cell;
  bool periodic = false;
  struct PhaseInfo {
    std::string name;
    std::optional<double> youngs_modulus, poisson_ratio;
  };
  std::vector<PhaseInfo> phases;
};

// Writes `description` as `file` (JSON, format grainmesh-mesh version 1).
void write_mesh_description(const std::filesystem::path& file, const MeshDescription& description);

// The keys an export config (or --set) may use ("*" is a phase name).
const std::vector<std::string>& export_config_keys();

// Reads mesh.vtu and its mesh.json, applies the config (options, phase moduli) and
// checks it. Throws IoError (files), GeometryError (their contents), ConfigError (keys).
ExportMesh read_export_mesh(const std::filesystem::path& mesh_file, const Config& config);
FoamOptions read_foam_options(const Config& config);

// The whole command: the case in a staging directory renamed into place, report.json last.
void run_export_command(const std::filesystem::path& mesh_file, const Config& config, const std::filesystem::path& out);

}  // namespace grainmesh
