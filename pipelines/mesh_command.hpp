// `grainmesh mesh TESSELLATION.json -o OUT`: the mesh stage on a plane or a solid
// tessellation (tessellation.json version 1 or 2), written as OUT/mesh.vtu, mesh.png
// (3D: a section), in 2D mesh.json and mesh_detail.png, and report.json (last); and
// `grainmesh check`, the conformity checker on a written 2D mesh.
#pragma once

#include <filesystem>

#include "pipelines/config.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

// Reads and validates tessellation.json. Throws IoError or GeometryError naming the file.
Tessellation read_tessellation_file(const std::filesystem::path& file);

void run_mesh_command(const std::filesystem::path& tessellation, const Config& config,
                      const std::filesystem::path& out);

// `grainmesh check TESSELLATION.json MESH.vtu`: the conformity checker on a written mesh
// (cell arrays grain and phase); prints its figures, or throws GeometryError naming the
// mesh file and the first violation (IoError for unreadable files).
void run_check_command(const std::filesystem::path& tessellation, const std::filesystem::path& mesh_file);

}  // namespace grainmesh
