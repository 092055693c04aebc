// The finite-element mesh files a run or an export writes beside the OpenFOAM case when
// export.format asks for them: mesh.msh (Gmsh) and mesh.inp (Abaqus).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "export/abaqus_file.hpp"
#include "export/element_mesh.hpp"
#include "pipelines/config.hpp"

namespace grainmesh {

// export.format, a comma-separated list: the OpenFOAM case's encoding (ascii or binary, at
// most one; none when not given) and the mesh files written beside the case (gmsh,
// abaqus). Throws ConfigError naming export.format.
struct ExportFormats {
  std::optional<bool> binary;
  bool gmsh = false;
  bool abaqus = false;
  bool mesh_files() const { return gmsh || abaqus; }
};
ExportFormats read_export_formats(const Config& config);

// Writes the files `formats` asks for of `m` into `dir`; returns their names.
std::vector<std::string> write_element_files(const std::filesystem::path& dir, const ElementMesh& m,
                                             const ExportFormats& formats, const AbaqusOptions& abaqus);

}  // namespace grainmesh
